#pragma once
// Checking lpvlab's error messages in tests: the message of the lpvlab::Error a call throws, and
// a substring assertion that prints both strings when it fails.

#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace lpvlab::test {

inline ::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

// The message of the Error `f` throws; a test failure (and "") if it throws nothing or another type.
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not an lpvlab::Error: " << e.what();
    return "";
  }
  ADD_FAILURE() << "no error thrown";
  return "";
}

}  // namespace lpvlab::test

#pragma once
// The test binary's one GL context (lpvlab allows one per process): an osmesa context made on
// first use and kept until the process ends, so any test can run alone or in any order.

#include <filesystem>
#include <memory>

#include "framework/gl/context.h"

namespace lpvlab::test {

inline GlContext& glTestContext() {
  static const std::unique_ptr<GlContext> context = GlContext::create("osmesa");
  return *context;
}

// tests/gl/shaders: the fixture shaders of these tests.
inline std::filesystem::path testShaderRoot() {
  return std::filesystem::path(LPVLAB_SOURCE_DIR) / "tests" / "gl" / "shaders";
}

}  // namespace lpvlab::test

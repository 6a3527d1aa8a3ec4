#include "framework/core/error.h"

#include <cmath>

namespace lpvlab {

std::string echoed(std::string_view value) {
  constexpr std::size_t kWhole = 80, kHead = 60, kTail = 16;
  if (value.size() <= kWhole) return std::string(value);
  std::string out(value.substr(0, kHead));
  out.append("...");
  out.append(value.substr(value.size() - kTail));
  out.append(" (" + std::to_string(value.size()) + " characters)");
  return out;
}

void throwAt(std::string_view where, std::string_view what) {
  throw Error(echoed(where) + ": " + std::string(what));
}

void requireFinite(double value, std::string_view where, std::string_view what) {
  if (!std::isfinite(value)) throwAt(where, std::string(what) + " is not finite (NaN or Inf)");
}

}  // namespace lpvlab

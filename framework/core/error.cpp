#include "framework/core/error.h"

#include <cmath>

namespace lpvlab {

void throwAt(std::string_view where, std::string_view what) {
  throw Error(std::string(where) + ": " + std::string(what));
}

void requireFinite(double value, std::string_view where, std::string_view what) {
  if (!std::isfinite(value)) throwAt(where, std::string(what) + " is not finite (NaN or Inf)");
}

}  // namespace lpvlab

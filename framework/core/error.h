#pragma once
// One exception type for every user-facing failure. The message always names where the problem
// is (a file, a file and line, a key, a strategy) and what is wrong; the CLI prints it once and
// exits non-zero. Code below the CLI never exits the process, so every failure is testable.

#include <stdexcept>
#include <string>
#include <string_view>

namespace lpvlab {

class Error : public std::runtime_error {
public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// "where: what", e.g. errorAt("scenes/a.gltf", "no triangles") -> "scenes/a.gltf: no triangles".
[[noreturn]] void throwAt(std::string_view where, std::string_view what);

// Throws an Error naming `what` when a value is NaN or infinite.
void requireFinite(double value, std::string_view where, std::string_view what);

}  // namespace lpvlab

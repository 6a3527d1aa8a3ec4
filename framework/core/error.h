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

// "where: what", e.g. errorAt("scenes/a.gltf", "no triangles") -> "scenes/a.gltf: no triangles";
// `where` is echoed().
[[noreturn]] void throwAt(std::string_view where, std::string_view what);

// A value as an error message echoes it: whole up to 80 characters, else its start and end with
// its length ("aaaa...aaaa (2000 characters)"), so that a 1 MB value (a pasted file, a runaway
// script) gives a readable error, not a megabyte on stderr.
std::string echoed(std::string_view value);

// Throws an Error naming `what` when a value is NaN or infinite.
void requireFinite(double value, std::string_view where, std::string_view what);

}  // namespace lpvlab

#pragma once
// Running the built lpvlab executable from a test: where it is (beside the tests/ folder of the
// build), shell quoting for its arguments, and reading back what it wrote.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace lpvlab::test {

inline std::filesystem::path lpvlabExecutable() {
  return std::filesystem::read_symlink("/proc/self/exe").parent_path().parent_path() / "lpvlab";
}

// A single-quoted shell word holding `s` verbatim.
inline std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

inline std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace lpvlab::test

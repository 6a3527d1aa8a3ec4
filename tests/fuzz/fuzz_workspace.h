#pragma once
// Where fuzzed inputs become files: a temporary folder holding copies of experiments/*.toml (so
// the `extends` and `include` of inputs grown from them find their bases), and LPVLAB_SHARED_DIR
// pointed at stand-in scenes: every shared scene the experiments name is a one-triangle file of
// its format, so an input spends its time in lpvlab's parsing, not in loading Sponza.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace lpvlab::fuzz {

class FuzzWorkspace {
 public:
  static FuzzWorkspace& instance();  // made on first use, removed at exit
  const std::filesystem::path& dir() const { return dir_; }
  // Writes the bytes to dir()/name and returns the path.
  std::string write(const std::string& name, const std::uint8_t* data, std::size_t size) const;
  std::string write(const std::string& name, const std::string& text) const;
  ~FuzzWorkspace();

 private:
  FuzzWorkspace();
  std::filesystem::path dir_;
};

}  // namespace lpvlab::fuzz

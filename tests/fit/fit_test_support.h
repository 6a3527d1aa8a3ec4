#pragma once
// Shared helpers of the fit tests: experiment files written into a fresh folder, and a small
// Cornell box (64^2 pixels, 16^3 grid) on which one rendering takes a fraction of a second.

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace lpvlab::test {

// A folder of its own per test, removed with it.
class FitFiles {
public:
  explicit FitFiles(const std::string& name)
      : dir_(std::filesystem::temp_directory_path() /
             ("lpvlab-fit-" + name + "-" + std::to_string(getpid()))) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  ~FitFiles() { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& file, const std::string& text) const {
    const std::string path = (dir_ / file).string();
    std::ofstream(path) << text;
    return path;
  }
  const std::filesystem::path& dir() const { return dir_; }

private:
  std::filesystem::path dir_;
};

// The built-in Cornell box, small; propagation iterations as given.
inline std::string smallCornellBox(int iterations = 16) {
  return "[output]\nwidth = 64\nheight = 64\n"
         "[light_maps]\nrsm_resolution = 64\nshadow_resolution = 256\n"
         "[grid]\nresolution = 16\n"
         "[propagation]\niterations = " + std::to_string(iterations) + "\n";
}

}  // namespace lpvlab::test

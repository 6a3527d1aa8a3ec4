#include "framework/core/install_layout.h"

#include <cstdlib>
#include <system_error>

namespace lpvlab {

namespace fs = std::filesystem;

namespace {

const char* environment(const char* name) {
  const char* value = std::getenv(name);
  return value && *value ? value : nullptr;
}

// <executable>/../share/lpvlab when it is a data folder (an installed prefix, the bundle).
fs::path installedDataDirectory() {
  std::error_code ec;
  const fs::path exe = fs::canonical("/proc/self/exe", ec);
  if (ec) return {};
  const fs::path share = exe.parent_path().parent_path() / "share" / "lpvlab";
  return fs::is_directory(share / "shaders", ec) ? share : fs::path();
}

}  // namespace

fs::path executablePath() {
  if (const char* exe = environment("LPVLAB_EXECUTABLE")) return exe;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path("lpvlab") : exe;
}

fs::path dataDirectory() {
  if (const char* dir = environment("LPVLAB_DATA_DIR")) return dir;
  if (const fs::path installed = installedDataDirectory(); !installed.empty()) return installed;
  return LPVLAB_SOURCE_DIR;
}

bool runsFromSourceTree() {
  std::error_code ec;
  return fs::equivalent(dataDirectory(), fs::path(LPVLAB_SOURCE_DIR), ec) && !ec;
}

fs::path shaderDirectory() {
  if (const char* dir = environment("LPVLAB_SHADER_DIR")) return dir;
  return dataDirectory() / "shaders";
}

}  // namespace lpvlab

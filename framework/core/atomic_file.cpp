#include "framework/core/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include "framework/core/error.h"

namespace lpvlab {

namespace fs = std::filesystem;

namespace {

// Unique per process (pid) and per call (counter), so concurrent writers of the same target,
// in this process or another, never share a temporary.
fs::path temporaryFor(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  const std::string tag = ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return target.parent_path() / (target.stem().string() + tag + target.extension().string());
}

}  // namespace

void writeAtomically(const std::string& path,
                     const std::function<void(const std::string&)>& write) {
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec)
      throw Error(path + ": cannot create directory '" + target.parent_path().string() +
                  "': " + ec.message());
  }
  const fs::path temporary = temporaryFor(target);
  try {
    write(temporary.string());
    fs::rename(temporary, target, ec);
    if (ec) throw Error(path + ": cannot rename the temporary file into place: " + ec.message());
  } catch (...) {
    fs::remove(temporary, ec);  // best effort; the original error is the one worth reporting
    throw;
  }
}

void removeLeftoverTemporaries(const std::string& directory) {
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, error))
    if (entry.path().filename().string().find(".tmp-") != std::string::npos)
      fs::remove(entry.path(), error);
}

void writeTextAtomically(const std::string& path, const std::string& text) {
  writeAtomically(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw Error(path + ": cannot open '" + temporary + "' for writing");
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw Error(path + ": write failed (disk full?)");
  });
}

void requireOutputDirectory(const std::string& path, const std::string& option) {
  const fs::path wanted = fs::absolute(path).lexically_normal();
  for (fs::path p = wanted;; p = p.parent_path()) {
    std::error_code ec;
    const fs::file_status status = fs::status(p, ec);
    if (fs::exists(status)) {
      if (fs::is_directory(status)) return;
      throw Error(option + " " + path + ": " +
                  (p == wanted ? std::string("is a file, not a directory")
                               : p.string() + " is a file, not a directory"));
    }
    if (p == p.parent_path()) return;
  }
}

}  // namespace lpvlab

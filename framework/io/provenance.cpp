#include "framework/io/provenance.h"

#include <sys/utsname.h>
#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <fstream>
#include <optional>

#include <OpenImageIO/imageio.h>
#include <glm/glm.hpp>
#include <toml++/toml.h>

#include "framework/core/install_layout.h"

namespace lpvlab {

namespace {

// Runs a shell command with stderr discarded; nullopt when it can't run or exits non-zero.
std::optional<std::string> capture(const std::string& command) {
  FILE* pipe = ::popen((command + " 2>/dev/null").c_str(), "r");
  if (!pipe) return std::nullopt;
  std::string output;
  char buffer[4096];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
  if (::pclose(pipe) != 0) return std::nullopt;
  return output;
}

// Single-quotes a word for /bin/sh, so any directory name passes through unchanged.
std::string shellQuoted(const std::string& word) {
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string trimmed(std::string s) {
  const auto first = s.find_first_not_of(" \t\r\n\"");
  const auto last = s.find_last_not_of(" \t\r\n\"");
  return first == std::string::npos ? "" : s.substr(first, last - first + 1);
}

// The value after "<key>" and its separator (':' in /proc/cpuinfo, '=' in os-release) on the
// first matching line of a text file; "unknown" when absent.
std::string fieldOf(const std::string& file, const std::string& key, char separator) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    const auto at = line.find(separator);
    if (at != std::string::npos && trimmed(line.substr(0, at)) == key)
      return trimmed(line.substr(at + 1));
  }
  return "unknown";
}

std::string dotted(int major, int minor, int patch) {
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

// GCC's __VERSION__ is a bare number ("12.2.0"); Clang's already names itself.
std::string compilerName() {
#if defined(__GNUC__) && !defined(__clang__)
  return std::string("GCC ") + __VERSION__;
#else
  return __VERSION__;
#endif
}

}  // namespace

std::string gitRevision(const std::string& sourceDir) {
  const std::string git = "git -C " + shellQuoted(sourceDir);
  const auto head = capture(git + " rev-parse HEAD");
  if (!head) return "unknown";
  const auto status = capture(git + " status --porcelain");
  const bool dirty = !status || !trimmed(*status).empty();  // can't tell: don't claim clean
  return trimmed(*head) + (dirty ? "-dirty" : "");
}

std::string lpvlabRevision() {
  if (runsFromSourceTree()) return gitRevision(LPVLAB_SOURCE_DIR);
  std::ifstream file(dataDirectory() / "REVISION");
  std::string line;
  return std::getline(file, line) && !trimmed(line).empty() ? trimmed(line) : "unknown";
}

nlohmann::json libraryVersions() {
  // The OpenImageIO actually loaded at run time, which may differ from the headers' version.
  const int oiio = OIIO::openimageio_version();
  return {
      {"openimageio", dotted(oiio / 10000, oiio / 100 % 100, oiio % 100)},
      {"tomlplusplus", dotted(TOML_LIB_MAJOR, TOML_LIB_MINOR, TOML_LIB_PATCH)},
      {"nlohmann_json", dotted(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR,
                               NLOHMANN_JSON_VERSION_PATCH)},
      {"glm", dotted(GLM_VERSION_MAJOR, GLM_VERSION_MINOR, GLM_VERSION_PATCH) + "." +
                  std::to_string(GLM_VERSION_REVISION)},
      {"compiler", compilerName()},
      {"cxx_standard", __cplusplus},
  };
}

nlohmann::json hostInfo() {
  char hostname[256] = "unknown";
  ::gethostname(hostname, sizeof hostname - 1);
  utsname system{};
  const std::string kernel = ::uname(&system) == 0 ? system.release : "unknown";
  return {
      {"cpu", fieldOf("/proc/cpuinfo", "model name", ':')},
      {"logical_cores", ::sysconf(_SC_NPROCESSORS_ONLN)},
      {"os", fieldOf("/etc/os-release", "PRETTY_NAME", '=')},
      {"kernel", kernel},
      {"hostname", std::string(hostname)},
  };
}

std::string utcTimestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buffer;
}

}  // namespace lpvlab

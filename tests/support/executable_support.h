#pragma once
// Running the built lpvlab executable from a test: where it is (beside the tests/ folder of the
// build), shell quoting for its arguments, running it, and reading back what it wrote.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

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

struct LpvlabResult {
  int exitCode = -1;
  std::string out, err;
};

// Runs `EXE ARGS` in `workDir`, capturing stdout and stderr into files in `logDir`;
// `environment` ("NAME=value ...", shell-quoted) is set for it alone.
inline LpvlabResult runExecutable(const std::filesystem::path& exe, const std::string& args,
                                  const std::filesystem::path& workDir,
                                  const std::filesystem::path& logDir,
                                  const std::string& environment = "") {
  LpvlabResult r;
  if (!std::filesystem::exists(exe)) {
    ADD_FAILURE() << exe << " does not exist: build its target";
    return r;
  }
  const std::filesystem::path out = logDir / "stdout.txt", err = logDir / "stderr.txt";
  const std::string command = "cd " + quoted(workDir.string()) + " && " + environment + " " +
                              quoted(exe.string()) + " " + args + " >" + quoted(out.string()) +
                              " 2>" + quoted(err.string());
  const int status = std::system(command.c_str());
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readFile(out);
  r.err = readFile(err);
  return r;
}

// The same for the built lpvlab.
inline LpvlabResult runLpvlab(const std::string& args, const std::filesystem::path& workDir,
                              const std::filesystem::path& logDir,
                              const std::string& environment = "") {
  return runExecutable(lpvlabExecutable(), args, workDir, logDir, environment);
}

}  // namespace lpvlab::test

#include "framework/cli/child_runs.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <map>

#include "framework/core/error.h"
#include "framework/core/log.h"
#include "framework/core/progress.h"

namespace lpvlab::cli {

namespace {

namespace fs = std::filesystem;

std::string lastLine(const fs::path& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

// Starts `exe run CONFIG --out RUNDIR` with stdout and stderr into RUNDIR/error.log; the child
// dies with this process (so a killed sweep leaves no orphan writing into its directory).
pid_t startRun(const std::string& exe, const std::string& config, const std::string& runDir) {
  const std::string log = (fs::path(runDir) / "error.log").string();
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw Error("fork failed");
  if (pid == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(127);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, 1);
      dup2(fd, 2);
      close(fd);
    }
    const int devnull = open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, 0);
    std::vector<std::string> args = {exe, "run", config, "--out", runDir};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

// Whether the child that ran `run` succeeded; if not, says why (its error.log's last line). A
// success's empty error.log is removed.
bool finished(const ChildRun& run, int status) {
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && fs::exists(run.directory / "manifest.json")) {
    fs::remove(run.directory / "error.log");
    return true;
  }
  std::string why = lastLine(run.directory / "error.log");
  if (why.empty())  // nothing written: it could not start (the executable replaced?) or was killed
    why = WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                              : "exit status " + std::to_string(WEXITSTATUS(status)) +
                                    (WEXITSTATUS(status) == 127 ? " (the executable could not be started)" : "");
  log::warning("configuration " + run.label + " failed: " + why + "\n  (see " +
               (run.directory / "error.log").string() + ")");
  return false;
}

}  // namespace

std::vector<std::size_t> runChildren(const std::string& exe, const std::vector<ChildRun>& runs,
                                     int jobs, const std::string& what) {
  ProgressBar progress(what);
  std::map<pid_t, std::size_t> running;
  std::vector<std::size_t> failed;
  std::size_t next = 0, done = 0;
  auto detail = [&] {
    return std::to_string(done) + "/" + std::to_string(runs.size()) + " configurations" +
           (failed.empty() ? "" : ", " + std::to_string(failed.size()) + " failed");
  };
  while (next < runs.size() || !running.empty()) {
    while (next < runs.size() && int(running.size()) < jobs) {
      const ChildRun& run = runs[next];
      fs::remove_all(run.directory);
      fs::create_directories(run.directory);
      running[startRun(exe, run.config, run.directory.string())] = next++;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw Error(what + ": waitpid failed");
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const std::size_t index = it->second;
    running.erase(it);
    ++done;
    if (!finished(runs[index], status)) failed.push_back(index);
    progress.update(double(done) / double(runs.size()), detail());
  }
  progress.finish(detail());
  return failed;
}

}  // namespace lpvlab::cli

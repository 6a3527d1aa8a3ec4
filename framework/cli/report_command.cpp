// `lpvlab report DIR`: the HTML report of a sweep directory, built by analysis/report.py with
// Debian's Python (/usr/bin/python3 sees the python3-* packages; another python3 on PATH may not).

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/core/error.h"

namespace lpvlab::cli {

int reportCommand(const Options& options) {
  const std::string script = (std::filesystem::path(LPVLAB_SOURCE_DIR) / "analysis" / "report.py").string();
  if (!std::filesystem::exists(script)) throw Error(script + ": the report script is missing");
  std::vector<std::string> args = {"/usr/bin/python3", script, options.out};
  if (!options.metric.empty()) args.insert(args.end(), {"--metric", options.metric});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t child = fork();
  if (child < 0) throw Error("report: cannot start /usr/bin/python3");
  if (child == 0) {
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(child, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
    throw Error("report: /usr/bin/python3 could not be run (install python3 and the analysis "
                "packages with scripts/install-deps.sh)");
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

}  // namespace lpvlab::cli

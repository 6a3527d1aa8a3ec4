// `lpvlab report DIR [DIR...] [--out OUT]`: the HTML report of one or several sweep directories
// (several: one page of them all, e.g. the methods' experiments on each scene), built by the
// analysis package (analysis/, docs/experiments.md) with the first of:
//   LPVLAB_PYTHON               that Python running the data folder's analysis/report.py
//                               (install_layout.h);
//   lpvlab-report on PATH       the analysis package pip-installed: its command runs in the
//                               interpreter it was installed into (a virtual environment);
//   /usr/bin/python3            Debian's Python, which sees the python3-* packages (another
//                               python3 on PATH may not), running analysis/report.py;
//   python3 on PATH             elsewhere (a bundle's host).

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/core/install_layout.h"
#include "framework/io/child_process.h"

namespace lpvlab::cli {

int reportCommand(const Options& options) {
  const std::string script = (dataDirectory() / "analysis" / "report.py").string();
  const char* chosen = std::getenv("LPVLAB_PYTHON");
  const std::string installed = chosen && *chosen ? "" : findProgram("lpvlab-report");
  std::vector<std::string> args;
  std::string python;
  if (!installed.empty()) {
    args = {installed, options.out};
    python = installed;
  } else {
    if (!std::filesystem::exists(script)) throw Error(script + ": the report script is missing");
    python = chosen && *chosen ? chosen
             : std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3"
                                                           : "python3";
    args = {python, script, options.out};
  }
  args.insert(args.end(), options.moreSweeps.begin(), options.moreSweeps.end());
  if (!options.metric.empty()) args.insert(args.end(), {"--metric", options.metric});
  if (!options.reportTime.empty()) args.insert(args.end(), {"--time", options.reportTime});
  if (!options.reportGpu.empty()) args.insert(args.end(), {"--gpu", options.reportGpu});
  if (!options.reportOut.empty()) args.insert(args.end(), {"--out", options.reportOut});
  const int status = runProgram(args);
  if (status == 127)
    throw Error("report: " + python + " could not be run (install python3 and the analysis "
                "packages with scripts/install-deps.sh, or set LPVLAB_PYTHON)");
  return status;
}

}  // namespace lpvlab::cli

// `lpvlab report DIR [DIR...] [--out OUT]`: the HTML report of one or several sweep directories
// (several: one page of them all, e.g. the methods' experiments on each scene), built by
// analysis/report.py with
// Debian's Python (/usr/bin/python3 sees the python3-* packages; another python3 on PATH may not).

#include <filesystem>
#include <vector>

#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/io/child_process.h"

namespace lpvlab::cli {

int reportCommand(const Options& options) {
  const std::string script = (std::filesystem::path(LPVLAB_SOURCE_DIR) / "analysis" / "report.py").string();
  if (!std::filesystem::exists(script)) throw Error(script + ": the report script is missing");
  std::vector<std::string> args = {"/usr/bin/python3", script, options.out};
  args.insert(args.end(), options.moreSweeps.begin(), options.moreSweeps.end());
  if (!options.metric.empty()) args.insert(args.end(), {"--metric", options.metric});
  if (!options.reportOut.empty()) args.insert(args.end(), {"--out", options.reportOut});
  const int status = runProgram(args);
  if (status == 127)
    throw Error("report: /usr/bin/python3 could not be run (install python3 and the analysis "
                "packages with scripts/install-deps.sh)");
  return status;
}

}  // namespace lpvlab::cli

// `lpvlab report DIR [DIR...] [--out OUT]`: the HTML report of one or several sweep directories
// (several: one page of them all, e.g. the methods' experiments on each scene), built by the
// analysis package (analysis/, docs/experiments.md): analysis/report.py, or `lpvlab-report` where
// the package is pip-installed (analysis_program.h says which runs).

#include <vector>

#include "framework/cli/analysis_program.h"
#include "framework/cli/commands.h"

namespace lpvlab::cli {

int reportCommand(const Options& options) {
  std::vector<std::string> args = {options.out};
  args.insert(args.end(), options.moreSweeps.begin(), options.moreSweeps.end());
  if (!options.metric.empty()) args.insert(args.end(), {"--metric", options.metric});
  if (!options.reportTime.empty()) args.insert(args.end(), {"--time", options.reportTime});
  if (!options.reportGpu.empty()) args.insert(args.end(), {"--gpu", options.reportGpu});
  if (!options.reportOut.empty()) args.insert(args.end(), {"--out", options.reportOut});
  return runAnalysisProgram("report", args);
}

}  // namespace lpvlab::cli

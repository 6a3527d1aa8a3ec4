#include "framework/cli/analysis_program.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "framework/core/error.h"
#include "framework/core/install_layout.h"
#include "framework/io/child_process.h"

namespace lpvlab::cli {

int runAnalysisProgram(const std::string& name, const std::vector<std::string>& arguments) {
  std::string scriptName = name;
  std::replace(scriptName.begin(), scriptName.end(), '-', '_');
  const std::string script = (dataDirectory() / "analysis" / (scriptName + ".py")).string();
  const char* chosen = std::getenv("LPVLAB_PYTHON");
  const std::string installed = chosen && *chosen ? "" : findProgram("lpvlab-" + name);
  std::vector<std::string> args;
  std::string python;
  if (!installed.empty()) {
    args = {installed};
    python = installed;
  } else {
    if (!std::filesystem::exists(script)) throw Error(script + ": the analysis script is missing");
    python = chosen && *chosen ? chosen
             : std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3"
                                                           : "python3";
    args = {python, script};
  }
  args.insert(args.end(), arguments.begin(), arguments.end());
  const int status = runProgram(args);
  if (status == 127)
    throw Error(name + ": " + python + " could not be run (install python3 and the analysis "
                "packages with scripts/install-deps.sh, or set LPVLAB_PYTHON)");
  return status;
}

}  // namespace lpvlab::cli

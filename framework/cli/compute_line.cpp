// The one line the run and bench commands print about where the strategies' kernels run.

#include "framework/cli/commands.h"

namespace lpvlab::cli {

std::string computeLine(const nlohmann::json& compute) {
  const nlohmann::json strategies = compute.value("strategies", nlohmann::json::object());
  std::string onCpu = compute.value("direct", std::string()) == "cpu" ? "direct" : "";
  for (const auto& [table, where] : strategies.items())
    if (where == "cpu") onCpu += (onCpu.empty() ? "" : ", ") + table;
  return "compute: " + compute.value("backend", std::string("?")) +
         (onCpu.empty() ? "; every strategy on GL" : "; on the CPU: " + onCpu);
}

}  // namespace lpvlab::cli

// The lines the run and bench commands print about where the strategies' kernels run and how
// each stage was timed.

#include "framework/cli/commands.h"
#include "framework/pipeline/pipeline.h"

namespace lpvlab::cli {

std::string computeLine(const nlohmann::json& compute) {
  const nlohmann::json strategies = compute.value("strategies", nlohmann::json::object());
  std::string onCpu = compute.value("direct", std::string()) == "cpu" ? "direct" : "";
  for (const auto& [table, where] : strategies.items())
    if (where == "cpu") onCpu += (onCpu.empty() ? "" : ", ") + table;
  std::string line = "compute: " + compute.value("backend", std::string("?")) +
                     (onCpu.empty() ? "; every strategy on GL" : "; on the CPU: " + onCpu);
  // Where the raster passes ran ([compute] raster) and how direct light is shadowed.
  std::string rayCast;
  const nlohmann::json raster = compute.value("raster", nlohmann::json::object());
  const nlohmann::json passes = raster.value("passes", nlohmann::json::object());  // kept: items() refers into it
  for (const auto& [pass, where] : passes.items())
    if (where == "embree") rayCast += (rayCast.empty() ? "" : ", ") + pass;
  if (!rayCast.empty()) line += "; raster passes by ray casting (Embree): " + rayCast;
  if (compute.value("shadows", std::string()) == "rays") line += "; shadows by rays";
  return line;
}

std::string clockLabel(const std::string& clock) {
  if (clock == "gl_timer_query") return "GL timer query";
  if (clock == "cpu_wall_clock") return "CPU wall clock";
  return clock == "mixed" ? "sum over both clocks" : clock;
}

std::string clocksLine(const std::map<std::string, std::string>& clock, const std::string& renderer,
                       const std::string& cpu) {
  std::string gl, host;
  for (const auto& [stage, name] : clock) {
    if (stage == kMethodTime || stage == kSharedTime || stage == kTotalTime) continue;  // sums
    std::string& list = name == "cpu_wall_clock" ? host : gl;
    list += (list.empty() ? "" : ", ") + stage;
  }
  std::string line = "times:";
  if (!gl.empty()) line += " GL timer queries on " + renderer + " (" + gl + ")";
  if (!host.empty()) line += std::string(gl.empty() ? "" : ";") + " CPU wall clock on " + cpu + " (" + host + ")";
  return line;
}

}  // namespace lpvlab::cli

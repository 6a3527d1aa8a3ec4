// IndirectMethod's defaults (indirect_method.h).
#include "framework/pipeline/indirect_method.h"

#include "framework/core/error.h"

namespace lpvlab {

nlohmann::json workCountJson(const WorkCount& w) {
  return {{"unit", w.unit},
          {"units", w.units},
          {"multiply_adds_per_unit", w.multiplyAddsPerUnit},
          {"bytes_per_unit", w.bytesPerUnit},
          {"multiply_adds", w.units * w.multiplyAddsPerUnit},
          {"bytes", w.units * w.bytesPerUnit}};
}

std::set<std::string> IndirectMethod::cpuStages() const {
  if (!runsOnCpu()) return {};
  const std::vector<std::string> stages = stageNames();
  return {stages.begin(), stages.end()};
}

nlohmann::json IndirectMethod::workReport(bool) const {
  // A method counts what its last frame did, on whichever side it runs.
  nlohmann::json report = nlohmann::json::object();
  for (const auto& [stage, counts] : work()) {
    report[stage] = nlohmann::json::array();
    for (const WorkCount& w : counts) report[stage].push_back(workCountJson(w));
  }
  return report;
}

nlohmann::json IndirectMethod::memoryReport() const { return {{"indirect_method", memoryBytes()}}; }

nlohmann::json IndirectMethod::computeReport() const {
  return {{"indirect_method", {{"name", name()}, {"runs_on", runsOnCpu() ? "cpu" : "gl"}}}};
}

nlohmann::json IndirectMethod::describe(const std::map<std::string, double>&) const {
  return {{"indirect_method", {{"name", name()}, {"statistics", statistics()}}}};
}

GridDump IndirectMethod::dumpGrid() const {
  throw Error("indirect method \"" + name() + "\" keeps no light grid to dump");
}

std::string IndirectMethod::explainRefusal() const {
  return "indirect method \"" + name() + "\" keeps no light grid whose stages could be replaced "
         "one at a time";
}

Image IndirectMethod::renderFromGrids(const GridFill&) {
  throw Error(explainRefusal());
}

std::string IndirectMethod::derivativeRefusal(const std::string& key) const {
  if (key.rfind('.') == std::string::npos) return "'" + key + "' is not <table>.<name>";
  return "indirect method \"" + name() + "\" has no kernels on dual numbers";
}

IndirectMethod::FrameDerivatives IndirectMethod::renderDerivatives(
    const std::vector<std::string>&, const std::function<void()>&) {
  // Pipeline::renderDerivatives asks derivativeRefusal first: only a method that overrides it
  // to accept a key gets here, and it must override this too.
  throw Error("indirect method \"" + name() + "\" has no kernels on dual numbers");
}

}  // namespace lpvlab

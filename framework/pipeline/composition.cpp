#include "framework/pipeline/composition.h"

#include "framework/core/error.h"

namespace lpvlab {

namespace {

// A stage with a main table and [[<stage>.also]] tables: "injection", "injection.also[0]", ...
template <class S>
void listStage(const std::string& stage, const std::vector<std::unique_ptr<S>>& strategies,
               std::vector<std::pair<std::string, Strategy*>>& out) {
  for (std::size_t i = 0; i < strategies.size(); ++i)
    out.emplace_back(i == 0 ? stage : stage + ".also[" + std::to_string(i - 1) + "]",
                     strategies[i].get());
}

}  // namespace

std::vector<std::pair<std::string, Strategy*>> Strategies::all() const {
  std::vector<std::pair<std::string, Strategy*>> out;
  listStage("injection", injection, out);
  out.emplace_back("occlusion", occlusion.get());
  out.emplace_back("propagation", propagation.get());
  listStage("rendering", rendering, out);
  return out;
}

Requirements resolveRequirements(const Strategies& strategies, int shOrder, glm::vec3 skyRadiance,
                                 int cascadeLevels, ComputeBackend backend) {
  if (strategies.injection.empty() || !strategies.occlusion || !strategies.propagation ||
      strategies.rendering.empty())
    throw Error("pipeline: every stage needs a strategy");
  Requirements requirements;
  requirements.shOrder = shOrder;
  requirements.cascadeLevels = cascadeLevels;
  requirements.backend = backend;
  for (const auto& [table, strategy] : strategies.all()) strategy->declare(requirements);
  for (const auto& [table, strategy] : strategies.all()) {
    const std::string who = "[" + table + "] type = \"" + strategy->name() + "\"";
    if (requirements.shOrder > strategy->maxShOrder())
      throw Error(who + " handles SH order up to " + std::to_string(strategy->maxShOrder()) +
                  ", but the light grid has order " + std::to_string(requirements.shOrder) +
                  " ([grid] sh_order): lower the order or choose strategies that support it");
    if (const std::string why = strategy->refusal(requirements); !why.empty())
      throw Error(who + " cannot run in this composition: " + why);
    if (backend == ComputeBackend::Cpu)
      if (const std::string why = strategy->cpuRefusal(requirements); !why.empty())
        throw Error(who + " cannot run on the CPU backend ([compute] backend = \"cpu\"): " + why +
                    "; use backend = \"auto\" (the CPU where a kernel exists) or \"gl\"");
  }
  if (glm::any(glm::greaterThan(skyRadiance, glm::vec3(0.0f))) && !requirements.skyInjected)
    throw Error("[sky] radiance is set, but no injection strategy injects sky light: add one "
                "that does, as [injection] or under [[injection.also]] ('lpvlab list' shows the "
                "injection strategies), or set the radiance to 0");
  return requirements;
}

ComputeBackend resolveBackend(const std::string& requested, const std::string& glRenderer) {
  if (requested == "gl") return ComputeBackend::Gl;
  if (requested == "cpu") return ComputeBackend::Cpu;
  if (requested != "auto")
    throw Error("[compute] backend: '" + requested + "' is not one of auto, gl, cpu");
  const bool software = glRenderer.find("llvmpipe") != std::string::npos ||
                        glRenderer.find("softpipe") != std::string::npos;
  return software ? ComputeBackend::CpuWherePossible : ComputeBackend::Gl;
}

std::string backendName(ComputeBackend backend) {
  switch (backend) {
    case ComputeBackend::Gl: return "gl";
    case ComputeBackend::Cpu: return "cpu";
    case ComputeBackend::CpuWherePossible: return "cpu where possible";
  }
  return "?";
}

}  // namespace lpvlab

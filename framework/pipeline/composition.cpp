#include "framework/pipeline/composition.h"

#include <map>

#include "framework/core/error.h"
#include "framework/gl/context.h"
#include "framework/pipeline/raster_inputs.h"
#include "framework/pipeline/strategy_catalogue.h"

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

// "[propagation] type = \"directed\"": how messages name a strategy.
std::string strategyLabel(const std::string& table, const Strategy& strategy) {
  return "[" + table + "] type = \"" + strategy.name() + "\"";
}

}  // namespace

std::map<std::string, ResourceAllocator> resolveResources(const DeclaredUses& declared) {
  std::map<std::string, ResourceAllocator> produced;  // the first producer's allocator
  std::map<std::string, bool> used;
  for (const auto& [by, uses] : declared)
    for (const ResourceUses::Use& use : uses.uses()) {
      if (use.kind == ResourceUses::Kind::Produces) produced.emplace(use.name, use.allocate);
      else used[use.name] = true;
    }
  for (const auto& [by, uses] : declared)
    for (const ResourceUses::Use& use : uses.uses())
      if (use.kind == ResourceUses::Kind::Consumes && !produced.count(use.name)) {
        std::string producers;
        bool injection = false;  // an injection is added beside the others, not instead
        for (const std::string& producer : producersOf(use.name)) {
          producers += (producers.empty() ? "" : " or ") + producer;
          injection = injection || producer.starts_with("[injection]");
        }
        throw Error(by + " consumes '" + use.name + "' (" + use.description + ")" +
                    (use.why.empty() ? "" : " for " + use.why) +
                    ", which no strategy of this composition produces: " +
                    (producers.empty() ? std::string("no registered strategy produces it")
                                       : "add " + producers) +
                    (injection ? " (as [injection] or under [[injection.also]])" : "") +
                    ", or drop what consumes it");
      }
  std::map<std::string, ResourceAllocator> resources;
  for (const auto& [name, allocate] : produced)
    if (used.count(name)) resources.emplace(name, allocate);
  return resources;
}

std::vector<std::pair<std::string, Strategy*>> Strategies::all() const {
  std::vector<std::pair<std::string, Strategy*>> out;
  listStage("injection", injection, out);
  out.emplace_back("occlusion", occlusion.get());
  out.emplace_back("propagation", propagation.get());
  listStage("rendering", rendering, out);
  return out;
}

std::string stageOfTable(const std::string& table) {
  const std::string stage = table.substr(0, table.find('.'));
  return stage == "rendering" ? "indirect" : stage;
}

Requirements resolveRequirements(const Strategies& strategies, int shOrder,
                                 const DeclaredUses& alsoDeclared, int cascadeLevels,
                                 ComputeBackend backend, bool gl) {
  if (strategies.injection.empty() || !strategies.occlusion || !strategies.propagation ||
      strategies.rendering.empty())
    throw Error("pipeline: every stage needs a strategy");
  Requirements requirements;
  requirements.shOrder = shOrder;
  requirements.cascadeLevels = cascadeLevels;
  requirements.backend = gl ? backend : ComputeBackend::Cpu;
  requirements.gl = gl;
  // Every strategy's uses of resources, and the others' (e.g. a sky that some strategy must
  // inject).
  DeclaredUses declared;
  for (const auto& [table, strategy] : strategies.all()) {
    ResourceUses uses;
    strategy->declare(uses);
    declared.emplace_back(strategyLabel(table, *strategy), std::move(uses));
  }
  declared.insert(declared.end(), alsoDeclared.begin(), alsoDeclared.end());
  // The raster passes make the raster inputs (raster_inputs.h) for whoever consumes them.
  declared.emplace_back("the raster passes", raster::producedByRasterPasses());
  requirements.resources = resolveResources(declared);
  // They are the frame's, not resources allocated per light-grid level.
  std::erase_if(requirements.resources,
                [](const auto& resource) { return raster::isRasterInput(resource.first); });
  for (const auto& [table, strategy] : strategies.all()) {
    const std::string who = strategyLabel(table, *strategy);
    if (requirements.shOrder > strategy->maxShOrder())
      throw Error(who + " handles SH order up to " + std::to_string(strategy->maxShOrder()) +
                  ", but the light grid has order " + std::to_string(requirements.shOrder) +
                  " ([grid] sh_order): lower the order or choose strategies that support it");
    if (const std::string why = strategy->refusal(requirements); !why.empty())
      throw Error(who + " cannot run in this composition: " + why);
    if (!gl) {
      const std::string drawn = strategy->drawsWithGl();
      const std::string why = drawn.empty() ? strategy->cpuRefusal(requirements) : "it draws " + drawn + " with GL";
      if (!why.empty())
        throw Error(who + " needs GL, and this run has none (gl.backend = \"none\", or \"auto\" "
                    "found no GL context): " + why + "; run with GL or choose another strategy");
    }
    if (requirements.backend == ComputeBackend::Cpu && gl)
      if (const std::string why = strategy->cpuRefusal(requirements); !why.empty())
        throw Error(who + " cannot run on the CPU backend ([compute] backend = \"cpu\"): " + why +
                    "; use backend = \"auto\" (the CPU where a kernel exists) or \"gl\"");
  }
  return requirements;
}

ComputeBackend resolveBackend(const std::string& requested, const std::string& glRenderer) {
  if (glRenderer == kNoGlRenderer) {  // gl.backend = "none": everything on the CPU, or refused
    if (requested == "gl")
      throw Error("key 'compute.backend': \"gl\" needs GL, and this run has none (gl.backend = "
                  "\"none\"); use \"cpu\" or \"auto\"");
    return ComputeBackend::Cpu;
  }
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

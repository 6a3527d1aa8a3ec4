#include "framework/pipeline/strategy_catalogue.h"

#include <toml++/toml.h>

#include "framework/core/parameters.h"
#include "framework/pipeline/indirect_method.h"
#include "framework/pipeline/strategy.h"

namespace lpvlab {

namespace {

template <class Interface>
void addStage(const std::string& stage, std::vector<CatalogueEntry>& out) {
  for (const auto& [name, entry] : Registry<Interface>::instance().entries()) {
    const toml::table defaults;
    Params params(defaults, "the strategy catalogue", stage);
    CatalogueEntry item{stage, name, entry.description, {}, {}};
    const auto strategy = entry.factory(params);
    strategy->declare(item.uses);
    Requirements alone;  // order 1, one level, no resources from other strategies
    alone.backend = ComputeBackend::Cpu;
    item.cpuRefusal = strategy->cpuRefusal(alone);
    out.push_back(std::move(item));
  }
}

}  // namespace

std::vector<CatalogueEntry> strategyCatalogue() {
  std::vector<CatalogueEntry> entries;
  addStage<InjectionStrategy>("injection", entries);
  addStage<OcclusionStrategy>("occlusion", entries);
  addStage<PropagationStrategy>("propagation", entries);
  addStage<RenderingStrategy>("rendering", entries);
  return entries;
}

std::vector<MethodCatalogueEntry> methodCatalogue() {
  std::vector<MethodCatalogueEntry> entries;
  for (const auto& [name, entry] : Registry<IndirectMethod>::instance().entries()) {
    const toml::table defaults;
    Params params(defaults, "the method catalogue", "indirect");
    entry.factory(params);
    std::string parameters;
    const nlohmann::json resolved = params.resolved();
    for (const auto& [key, value] : resolved.items())
      parameters += (parameters.empty() ? "" : ", ") + key + " = " + value.dump();
    entries.push_back({name, entry.description, parameters});
  }
  return entries;
}

std::vector<std::string> producersOf(const std::string& resource) {
  std::vector<std::string> producers;
  for (const CatalogueEntry& entry : strategyCatalogue())
    for (const ResourceUses::Use& use : entry.uses.uses())
      if (use.kind == ResourceUses::Kind::Produces && use.name == resource)
        producers.push_back("[" + entry.stage + "] type = \"" + entry.name + "\"");
  return producers;
}

}  // namespace lpvlab

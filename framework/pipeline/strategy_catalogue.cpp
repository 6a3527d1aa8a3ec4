#include "framework/pipeline/strategy_catalogue.h"

#include <iomanip>
#include <sstream>

#include <toml++/toml.h>

#include "framework/core/parameters.h"
#include "framework/pipeline/indirect_method.h"
#include "framework/pipeline/strategy.h"

namespace lpvlab {

namespace {

// A default as a person writes it: floats read as doubles print 0.02, not 0.019999999552965164
// (7 significant digits, a float's), strings quoted as in TOML.
std::string shown(const nlohmann::json& value) {
  if (value.is_number_float()) {
    std::ostringstream out;
    out << std::setprecision(7) << value.get<double>();
    return out.str();
  }
  if (value.is_array()) {
    std::string out = "[";
    for (const nlohmann::json& v : value) out += (out.size() > 1 ? ", " : "") + shown(v);
    return out + "]";
  }
  return value.dump();
}

// "key = value, ..." of every parameter a strategy or method read with its defaults.
std::string parameterLine(const Params& params) {
  std::string line;
  const nlohmann::json resolved = params.resolved();  // items() refers into it
  for (const auto& [key, value] : resolved.items())
    line += (line.empty() ? "" : ", ") + key + " = " + shown(value);
  return line;
}

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
    item.drawsWithGl = strategy->drawsWithGl();
    item.parameters = parameterLine(params);
    item.defaults = params.resolved();
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
    Params experiment(defaults, "the method catalogue");
    Params params = experiment.table("indirect");  // LPV reads its stages' tables beside it
    const auto method = entry.factory(params);
    entries.push_back({name, entry.description, parameterLine(params), params.resolved(),
                       method->stageNames(), method->consumes(), method->summaryKeys()});
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

#include <iostream>
#include <string>
#include <utility>

#include "framework/cli/commands.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "framework/pipeline/strategy_catalogue.h"

namespace lpvlab::cli {

namespace {

// "produces geometry_volume, surface_albedo; reads if produced ...".
std::string resourceLine(const ResourceUses& uses) {
  std::string line;
  for (const auto& [kind, verb] : {std::pair{ResourceUses::Kind::Produces, "produces"},
                                   std::pair{ResourceUses::Kind::Consumes, "consumes"},
                                   std::pair{ResourceUses::Kind::Reads, "reads if produced"}}) {
    std::string names;
    for (const ResourceUses::Use& use : uses.uses())
      if (use.kind == kind) names += (names.empty() ? "" : ", ") + use.name;
    if (!names.empty()) line += (line.empty() ? "" : "; ") + std::string(verb) + " " + names;
  }
  return line;
}

nlohmann::json resourcesJson(const ResourceUses& uses) {
  nlohmann::json out = {{"produces", nlohmann::json::array()},
                        {"consumes", nlohmann::json::array()},
                        {"reads", nlohmann::json::array()}};
  for (const ResourceUses::Use& use : uses.uses())
    out[use.kind == ResourceUses::Kind::Produces   ? "produces"
        : use.kind == ResourceUses::Kind::Consumes ? "consumes"
                                                   : "reads"]
        .push_back(use.name);
  return out;
}

// `lpvlab list --json`: the same, for programs (the analysis, scripts): the pipeline's own stages
// in the order a frame runs them (the method's follow), every strategy and method with its
// parameters' defaults, resources and CPU kernel; each method's own stages, the raster inputs it
// consumes (with its defaults) and its summary keys.
int listJson() {
  nlohmann::json out = {{"pipeline_stages", Pipeline::stageNames()},
                        {"strategies", nlohmann::json::array()},
                        {"methods", nlohmann::json::array()}};
  for (const CatalogueEntry& entry : strategyCatalogue())
    out["strategies"].push_back({{"stage", entry.stage},
                                 {"name", entry.name},
                                 {"description", entry.description},
                                 {"resources", resourcesJson(entry.uses)},
                                 {"cpu_kernel", entry.cpuRefusal.empty()},
                                 {"cpu_refusal", entry.cpuRefusal},
                                 {"without_gl", entry.cpuRefusal.empty() && entry.drawsWithGl.empty()},
                                 {"parameters", entry.defaults}});
  for (const MethodCatalogueEntry& method : methodCatalogue())
    out["methods"].push_back({{"name", method.name},
                              {"description", method.description},
                              {"stages", method.stages},
                              {"consumes", method.consumes},
                              {"summary_keys", method.summaryKeys},
                              {"parameters", method.defaults}});
  std::cout << out.dump(2) << "\n";
  return 0;
}

}  // namespace

// The strategies of each stage in pipeline order, with the resources each produces and consumes
// (named_resources.h) and whether it has a CPU kernel ([compute] backend), with its default
// parameters; their parameters are documented in the header of variants/<stage>/<name>.cpp and in
// docs/variants.md. Then the indirect methods beside LPV with their parameters' defaults
// (variants/methods/, docs/methods.md).
int listCommand(bool json) {
  if (json) return listJson();
  std::string stage;
  for (const CatalogueEntry& entry : strategyCatalogue()) {
    if (entry.stage != stage) std::cout << "[" << (stage = entry.stage) << "] type =\n";
    std::cout << "  " << entry.name << ": " << entry.description << "\n";
    if (const std::string resources = resourceLine(entry.uses); !resources.empty())
      std::cout << "      (" << resources << ")\n";
    if (!entry.parameters.empty()) std::cout << "      (" << entry.parameters << ")\n";
    std::cout << "      (CPU backend: "
              << (entry.cpuRefusal.empty() ? "yes" : "no, " + entry.cpuRefusal) << ")\n";
    if (!entry.drawsWithGl.empty())
      std::cout << "      (needs GL, whatever the backend: it draws " << entry.drawsWithGl << ")\n";
  }
  // The indirect-light methods (docs/methods.md); LPV's stages are the strategies above.
  std::cout << "[indirect] method =\n";
  for (const MethodCatalogueEntry& method : methodCatalogue()) {
    std::cout << "  " << method.name << (method.name == kDefaultIndirectMethod ? " (the default)" : "")
              << ": " << method.description << "\n";
    if (!method.parameters.empty()) std::cout << "      (" << method.parameters << ")\n";
  }
  return 0;
}

}  // namespace lpvlab::cli

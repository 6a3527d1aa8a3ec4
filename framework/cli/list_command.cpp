#include <iostream>
#include <string>
#include <utility>

#include "framework/cli/commands.h"
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

}  // namespace

// The strategies of each stage in pipeline order, with the resources each produces and consumes
// (named_resources.h) and whether it has a CPU kernel ([compute] backend), with its default
// parameters; their parameters are documented in the header of variants/<stage>/<name>.cpp and in
// docs/variants.md. Then the indirect methods beside LPV with their parameters' defaults
// (variants/methods/, docs/methods.md).
int listCommand() {
  std::string stage;
  for (const CatalogueEntry& entry : strategyCatalogue()) {
    if (entry.stage != stage) std::cout << "[" << (stage = entry.stage) << "] type =\n";
    std::cout << "  " << entry.name << ": " << entry.description << "\n";
    if (const std::string resources = resourceLine(entry.uses); !resources.empty())
      std::cout << "      (" << resources << ")\n";
    if (!entry.parameters.empty()) std::cout << "      (" << entry.parameters << ")\n";
    std::cout << "      (CPU backend: "
              << (entry.cpuRefusal.empty() ? "yes" : "no, " + entry.cpuRefusal) << ")\n";
  }
  // The other indirect-light methods, which replace the stages above (docs/methods.md).
  std::cout << "[indirect] method =\n"
            << "  lpv: the stages above (the default)\n";
  for (const MethodCatalogueEntry& method : methodCatalogue())
    std::cout << "  " << method.name << ": " << method.description << "\n"
              << "      (" << method.parameters << ")\n";
  return 0;
}

}  // namespace lpvlab::cli

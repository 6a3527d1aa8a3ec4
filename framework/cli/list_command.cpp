#include <iostream>

#include "framework/cli/commands.h"
#include "framework/pipeline/strategy.h"

namespace lpvlab::cli {

namespace {

template <class Interface>
void printStage(const char* stage) {
  std::cout << "[" << stage << "] type =\n";
  for (const auto& [name, entry] : Registry<Interface>::instance().entries())
    std::cout << "  " << name << ": " << entry.description << "\n";
}

}  // namespace

// The strategies of each stage in pipeline order; their parameters are documented in the header
// of variants/<stage>/<name>.cpp and in docs/variants.md.
int listCommand() {
  printStage<InjectionStrategy>("injection");  // also [[injection.also]]
  printStage<OcclusionStrategy>("occlusion");
  printStage<PropagationStrategy>("propagation");
  printStage<RenderingStrategy>("rendering");
  return 0;
}

}  // namespace lpvlab::cli

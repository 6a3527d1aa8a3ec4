#include <iostream>

#include "framework/cli/commands.h"
#include "framework/pipeline/strategy.h"

namespace lpvlab::cli {

namespace {

template <class Interface>
void printStage(const char* stage) {
  std::cout << "[" << stage << "] type = \n";
  for (const auto& [name, entry] : Registry<Interface>::instance().entries())
    std::cout << "  " << name << ": " << entry.description << "\n";
}

}  // namespace

int listCommand() {
  printStage<InjectionStrategy>("injection");
  printStage<PropagationStrategy>("propagation");
  printStage<RenderingStrategy>("rendering");
  return 0;
}

}  // namespace lpvlab::cli

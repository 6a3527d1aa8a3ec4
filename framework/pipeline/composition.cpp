#include "framework/pipeline/composition.h"

#include "framework/core/error.h"

namespace lpvlab {

std::vector<std::pair<std::string, Strategy*>> Strategies::all() const {
  std::vector<std::pair<std::string, Strategy*>> out;
  for (std::size_t i = 0; i < injection.size(); ++i)
    out.emplace_back(i == 0 ? "injection" : "injection.also[" + std::to_string(i - 1) + "]",
                     injection[i].get());
  out.emplace_back("occlusion", occlusion.get());
  out.emplace_back("propagation", propagation.get());
  out.emplace_back("rendering", rendering.get());
  return out;
}

Requirements resolveRequirements(const Strategies& strategies, int shOrder, glm::vec3 skyRadiance) {
  if (strategies.injection.empty() || !strategies.occlusion || !strategies.propagation ||
      !strategies.rendering)
    throw Error("pipeline: every stage needs a strategy");
  Requirements requirements;
  requirements.shOrder = shOrder;
  for (const auto& [table, strategy] : strategies.all()) strategy->declare(requirements);
  for (const auto& [table, strategy] : strategies.all()) {
    const std::string who = "[" + table + "] type = \"" + strategy->name() + "\"";
    if (requirements.shOrder > strategy->maxShOrder())
      throw Error(who + " handles SH order up to " + std::to_string(strategy->maxShOrder()) +
                  ", but the light grid has order " + std::to_string(requirements.shOrder) +
                  " ([grid] sh_order): lower the order or choose strategies that support it");
    if (const std::string why = strategy->refusal(requirements); !why.empty())
      throw Error(who + " cannot run in this composition: " + why);
  }
  if (glm::any(glm::greaterThan(skyRadiance, glm::vec3(0.0f))) && !requirements.skyInjected)
    throw Error("[sky] radiance is set, but no injection strategy injects sky light: add one "
                "that does, as [injection] or under [[injection.also]] ('lpvlab list' shows the "
                "injection strategies), or set the radiance to 0");
  return requirements;
}

}  // namespace lpvlab

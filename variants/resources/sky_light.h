#pragma once
// The constant sky's light in the light grid ([sky] radiance): a resource without data
// (named_resources.h) that an injection strategy produces by adding the sky's light to the grid, and
// that the experiment consumes when its sky is brighter than 0, so that a sky nobody injects is
// refused by name instead of silently missing.

#include <cstddef>

#include <glm/glm.hpp>

#include "framework/pipeline/composition.h"
#include "framework/pipeline/named_resources.h"

namespace lpvlab {

struct SkyLight {
  explicit SkyLight(const ResourceSetup&) {}
  void clear() {}
  std::size_t memoryBytes() const { return 0; }
};

inline constexpr ResourceKey<SkyLight> kSkyLight{
    "sky_light", "the constant sky's light ([sky] radiance) injected into the light grid"};

// The experiment's own use: a sky brighter than 0 consumes the sky's light (resolveRequirements'
// alsoDeclared), so that a composition with no strategy that injects it is refused by name.
inline DeclaredUses skyLightUses(glm::vec3 skyRadiance) {
  if (!glm::any(glm::greaterThan(skyRadiance, glm::vec3(0.0f)))) return {};
  ResourceUses sky;
  sky.consumes(kSkyLight);
  DeclaredUses declared;
  declared.emplace_back("[sky] radiance", std::move(sky));
  return declared;
}

}  // namespace lpvlab

#include "framework/pipeline/raster_inputs.h"

namespace lpvlab::raster {

bool isRasterInput(std::string_view name) {
  for (const auto& key : {kGBuffer, kReflectiveShadowMaps, kShadowMaps, kEmission})
    if (key.name == name) return true;
  return false;
}

ResourceUses producedByRasterPasses() {
  ResourceUses passes;
  for (const auto& key : {kGBuffer, kReflectiveShadowMaps, kShadowMaps, kEmission})
    passes.produces(key);
  return passes;
}

}  // namespace lpvlab::raster

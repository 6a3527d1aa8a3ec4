#include "framework/pipeline/raster_inputs.h"

namespace lpvlab::raster {

namespace {

constexpr ResourceKey<RasterInput> kEvery[] = {kGBuffer, kReflectiveShadowMaps, kShadowMaps,
                                               kEmission};

}  // namespace

bool isRasterInput(std::string_view name) {
  for (const auto& key : kEvery)
    if (key.name == name) return true;
  return false;
}

ResourceUses producedByRasterPasses() {
  ResourceUses passes;
  for (const auto& key : kEvery) passes.produces(key);
  return passes;
}

}  // namespace lpvlab::raster

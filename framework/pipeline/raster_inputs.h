#pragma once
// What the pipeline's raster passes make before a method runs: the raster side of the resource
// contract. The pipeline renders an input only when the run needs it, so a method or a composition
// that does not read the RSMs has no "rsm" stage and no RSM cost.
//   - a method names what it reads in IndirectMethod::consumes() (by these keys' names);
//   - LPV's strategies declare it as any resource (Strategy::declare:
//     uses.consumes(raster::kReflectiveShadowMaps)), and LPV consumes what its strategies do.
// The keys hold no data: the maps and the G-buffer are the frame's (Frame::lightMaps, gbuffer).

#include <cstddef>

#include "framework/pipeline/named_resources.h"

namespace lpvlab::raster {

// A raster pass's output as a resource: nothing to allocate or clear per light-grid level.
struct RasterInput {
  explicit RasterInput(const ResourceSetup&) {}
  void clear() {}
  std::size_t memoryBytes() const { return 0; }
};

// The camera's G-buffer (positions, normals, albedo): always rendered (the run's AOVs).
inline constexpr ResourceKey<RasterInput> kGBuffer{"gbuffer", "the camera's G-buffer"};
// Reflective shadow maps of every light view (flux, normals, positions).
inline constexpr ResourceKey<RasterInput> kReflectiveShadowMaps{
    "rsm", "the reflective shadow maps of every light view"};
// Shadow maps of every light view: rendered for direct light, and for a method that reads them.
inline constexpr ResourceKey<RasterInput> kShadowMaps{"shadow_maps",
                                                      "the shadow maps of every light view"};
// Emissive surfaces as lights: a scene lit by them alone runs only with a method that consumes
// this (the pipeline otherwise needs a point, spot or directional light).
inline constexpr ResourceKey<RasterInput> kEmission{"emission", "emissive surfaces as lights"};

// Whether `name` is a raster input's key name.
bool isRasterInput(std::string_view name);
// The raster passes' declaration: they produce every raster input (composition.h's
// resolveRequirements adds it to the strategies').
ResourceUses producedByRasterPasses();

}  // namespace lpvlab::raster

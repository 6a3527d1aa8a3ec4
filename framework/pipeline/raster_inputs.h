#pragma once
// What the pipeline's raster passes make before a method runs, by the names methods consume
// (IndirectMethod::consumes): the pipeline renders an input only when the run needs it, so a
// method that does not read the RSMs has no "rsm" stage and no RSM cost. These are the raster
// side of the resource contract; the light grid's resources between LPV's strategies are
// named_resources.h's.

#include <string_view>

namespace lpvlab::raster {

// The camera's G-buffer (positions, normals, albedo): always rendered (the run's AOVs).
inline constexpr std::string_view kGBuffer = "gbuffer";
// Reflective shadow maps of every light view (flux, normals, positions).
inline constexpr std::string_view kReflectiveShadowMaps = "rsm";
// Shadow maps of every light view: rendered for direct light, and for a method that reads them.
inline constexpr std::string_view kShadowMaps = "shadow_maps";
// Emissive surfaces as lights: a scene lit by them alone runs only with a method that consumes
// this (the pipeline otherwise needs a point, spot or directional light).
inline constexpr std::string_view kEmission = "emission";

}  // namespace lpvlab::raster

#pragma once
// The first shot from the scene's punctual lights (point, spot, directional): the irradiance each
// patch side receives straight from them, averaged over the patch, with visibility by Embree
// shadow rays from `samples` points spread over it (stratified, the same points for every light).
// E = I falloff cos / r^2 for point and spot lights, E_perp cos for directional ones, as the path
// tracer's next-event estimation computes it (framework/reference/integrator.cpp). A side facing
// away from a light gets nothing from it.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "framework/radiosity/patch_ray_scene.h"
#include "framework/reference/light_sampler.h"

namespace lpvlab {

struct LightIrradiance {
  std::vector<glm::dvec3> perSide;  // W/m^2
  std::size_t shadowRays = 0;
};

LightIrradiance lightIrradiance(const PatchMesh& mesh, const PatchRayScene& scene,
                                const std::vector<PunctualLight>& lights, int samples);

}  // namespace lpvlab

#pragma once
// What a punctual light sends to a point: the next-event estimation of the path tracer
// (integrator.cpp) and radiosity's first shot (framework/radiosity/light_irradiance.cpp) both
// read it here, so they light a surface alike.

#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "framework/math/shared.h"
#include "framework/reference/light_sampler.h"

namespace lpvlab {

struct PunctualArrival {
  glm::vec3 toLight;   // unit, from the point to the light
  float distance;      // m; infinity for a directional light
  glm::vec3 arriving;  // irradiance on a surface facing the light, W/m^2: I falloff / r^2 (point,
                       // spot) or E_perp (directional)
};

// False when x is at the light's position (no direction).
inline bool punctualArrival(const PunctualLight& light, const glm::vec3& x, PunctualArrival& out) {
  if (light.type == LightType::Directional) {
    out = {-light.direction, std::numeric_limits<float>::infinity(), light.radiant};
    return true;
  }
  const glm::vec3 offset = light.position - x;
  const float distance2 = glm::dot(offset, offset);
  if (!(distance2 > 0.0f)) return false;
  out.distance = std::sqrt(distance2);
  out.toLight = offset / out.distance;
  const float falloff = light.type == LightType::Spot
                            ? float(shared::spotFalloff(glm::dot(light.direction, -out.toLight),
                                                        light.cosInner, light.cosOuter))
                            : 1.0f;
  out.arriving = light.radiant * (falloff / distance2);
  return true;
}

}  // namespace lpvlab

#pragma once
// Virtual point lights (seed 001, 2.1-2.3): points of the scene's surfaces that reflect light
// they received, each a Lambertian emitter. Units, stated once for every many-light method:
//
//   flux     the flux the VPL reflects, W per channel: the flux its light path brought to the
//            point times the point's albedo (what a reflective shadow map's texel holds)
//   emitted  radiant intensity I(theta) = flux / pi * cos(theta) (W/sr), theta from `normal`
//
// A receiver x with normal n_x and albedo rho_x, at distance d, then reflects towards the camera
//   L = rho_x / pi * I(theta) * cos(theta_x) / d^2 * V = flux / pi * G * f_r,
// with G = cos(theta) cos(theta_x) / d^2 * V and f_r = rho_x / pi: the terms of seed 001's
// equation (11), whose clamp (12) bounds G f_r by c (vpl_gather.h).

#include <vector>

#include <glm/glm.hpp>

namespace lpvlab {

struct Vpl {
  glm::vec3 position;  // m
  glm::vec3 normal;    // unit, on the side the light arrived from
  glm::vec3 flux;      // W per channel, reflected
  int bounce = 1;      // 1 where light first lands, 2 after one diffuse bounce, ...
};

}  // namespace lpvlab

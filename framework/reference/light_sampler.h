#pragma once
// The scene's lights as next-event estimation reads them.
//
// Punctual lights (point, spot, directional) are delta lights: only next-event estimation can
// find them, and every vertex samples all of them (one shadow ray each where the light reaches
// the point): scenes have few, and a per-light shadow ray has no selection noise.
//
// Emissive triangles are area lights. One is picked per vertex with probability proportional to
// its emitted power (luminance(emission) * area; the common factor pi of a Lambertian emitter
// cancels), then a uniformly distributed point on it. emitterPdf gives the same density for a
// point found by a BRDF-sampled ray, for multiple importance sampling.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "framework/reference/material_sampling.h"
#include "framework/scene/scene.h"

namespace lpvlab {

struct PunctualLight {
  LightType type;
  glm::vec3 position;         // Point, Spot
  glm::vec3 direction;        // Spot, Directional: unit, the way the light travels
  glm::vec3 radiant;          // colour * intensity: W/sr (Point, Spot) or W/m^2 (Directional)
  double cosInner, cosOuter;  // Spot cone, as shared::spotFalloff takes them
};

// A point on an emissive triangle, seen from the shading point.
struct EmitterSample {
  glm::vec3 direction;  // unit, from the shading point to the light point
  float distance;       // m
  glm::vec3 radiance;   // emitted towards the shading point, W/(m^2 sr)
  float pdf;            // solid-angle density of the direction, 1/sr
};

class LightSampler {
public:
  // Throws an Error naming a light with non-finite or negative values, a zero direction, or a
  // spot cone outside 0 <= inner <= outer <= pi/2.
  LightSampler(const Scene& scene, const std::vector<SurfaceMaterial>& materials);

  const std::vector<PunctualLight>& punctual() const { return punctual_; }
  bool hasEmitters() const { return !cumulativePower_.empty(); }

  // Picks an emissive triangle and a point on it from three uniform numbers. False when the
  // point cannot light `from` (seen edge-on, or cut out by an alpha mask).
  bool sampleEmitter(const glm::vec3& from, float pickTriangle, float s, float t,
                     EmitterSample& sample) const;

  // Index of mesh `meshIndex`'s first triangle among the emitters (its others follow in order),
  // -1 when its material doesn't emit.
  int firstEmitterOfMesh(int meshIndex) const { return firstEmitterOfMesh_[meshIndex]; }
  // Solid-angle density with which sampleEmitter picks a point on emitter `emitter` at
  // `distance`, where the direction meets the emitter's plane at |cos| `cosAtEmitter`.
  float emitterPdf(int emitter, float distance, float cosAtEmitter) const {
    return emitters_[emitter].pdfArea * distance * distance / cosAtEmitter;
  }

private:
  struct EmissiveTriangle {
    glm::vec3 p0, edge1, edge2;  // point = p0 + a edge1 + b edge2
    glm::vec2 uv0, uvEdge1, uvEdge2;
    glm::vec3 unitNormal;
    const SurfaceMaterial* material;
    float pdfArea;  // probability of picking it / its area, 1/m^2
  };

  std::vector<PunctualLight> punctual_;
  std::vector<EmissiveTriangle> emitters_;
  std::vector<double> cumulativePower_;  // running sums over emitters_, normalised to end at 1
  std::vector<int> firstEmitterOfMesh_;
};

}  // namespace lpvlab

#include "framework/reference/light_sampler.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

PunctualLight prepareLight(const Light& light) {
  const std::string where = "path tracer: light '" + light.name + "'";
  for (int i = 0; i < 3; ++i) {
    requireFinite(light.position[i], where, "position");
    requireFinite(light.direction[i], where, "direction");
    requireFinite(light.color[i], where, "colour");
  }
  requireFinite(light.intensity, where, "intensity");
  if (light.intensity < 0.0f || glm::any(glm::lessThan(light.color, glm::vec3(0.0f))))
    throwAt(where, "negative colour or intensity");
  const bool spot = light.type == LightType::Spot;
  if (light.type != LightType::Point && !(glm::length(light.direction) > 0.0f))
    throwAt(where, "direction has zero length");
  if (spot && !(light.innerConeAngle >= 0.0f && light.innerConeAngle <= light.outerConeAngle &&
                light.outerConeAngle <= 0.5f * float(M_PI)))
    throwAt(where, "cone angles must satisfy 0 <= inner <= outer <= pi/2");
  return {.type = light.type,
          .position = light.position,
          .direction =
              light.type == LightType::Point ? glm::vec3(0.0f) : glm::normalize(light.direction),
          .radiant = light.color * light.intensity,
          .cosInner = spot ? std::cos(double(light.innerConeAngle)) : -1.0,
          .cosOuter = spot ? std::cos(double(light.outerConeAngle)) : -1.0};
}

}  // namespace

LightSampler::LightSampler(const Scene& scene, const std::vector<SurfaceMaterial>& materials) {
  for (const Light& light : scene.lights) punctual_.push_back(prepareLight(light));

  std::vector<double> power;
  for (const Mesh& mesh : scene.meshes) {
    const SurfaceMaterial& material = materials[mesh.material];
    if (!material.emissive || mesh.indices.empty()) {
      firstEmitterOfMesh_.push_back(-1);
      continue;
    }
    firstEmitterOfMesh_.push_back(int(emitters_.size()));
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
      const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
      EmissiveTriangle triangle{.p0 = mesh.positions[a],
                                .edge1 = mesh.positions[b] - mesh.positions[a],
                                .edge2 = mesh.positions[c] - mesh.positions[a],
                                .uv0 = mesh.uvs[a],
                                .uvEdge1 = mesh.uvs[b] - mesh.uvs[a],
                                .uvEdge2 = mesh.uvs[c] - mesh.uvs[a],
                                .unitNormal = glm::vec3(0.0f),
                                .material = &material,
                                .pdfArea = 0.0f};
      const glm::vec3 crossEdges = glm::cross(triangle.edge1, triangle.edge2);
      const double area = 0.5 * glm::length(crossEdges);
      if (area > 0.0) triangle.unitNormal = glm::normalize(crossEdges);
      emitters_.push_back(triangle);
      power.push_back(area * luminance(material.emission));
    }
  }

  double total = 0.0;
  for (double p : power) total += p;
  if (!(total > 0.0)) return;  // no emitter with area: nothing to sample, hits count fully
  double running = 0.0;
  for (std::size_t i = 0; i < emitters_.size(); ++i) {
    running += power[i];
    cumulativePower_.push_back(running / total);
    const double area = 0.5 * glm::length(glm::cross(emitters_[i].edge1, emitters_[i].edge2));
    emitters_[i].pdfArea = area > 0.0 ? float(power[i] / total / area) : 0.0f;
  }
  cumulativePower_.back() = 1.0;  // the last sum may round below 1; a pick must never fall past it
}

bool LightSampler::sampleEmitter(const glm::vec3& from, float pickTriangle, float s, float t,
                                 EmitterSample& sample) const {
  // The first triangle whose running power exceeds the pick: zero-power triangles are skipped.
  const auto found =
      std::upper_bound(cumulativePower_.begin(), cumulativePower_.end(), double(pickTriangle));
  const EmissiveTriangle& triangle = emitters_[found - cumulativePower_.begin()];
  // Uniform on the triangle: fold the unit square's upper half onto the lower one.
  if (s + t > 1.0f) s = 1.0f - s, t = 1.0f - t;
  if (triangle.material->alphaCutoff >= 0.0f &&
      cutOut(*triangle.material, triangle.uv0 + s * triangle.uvEdge1 + t * triangle.uvEdge2))
    return false;
  const glm::vec3 toLight = triangle.p0 + s * triangle.edge1 + t * triangle.edge2 - from;
  const float distance = glm::length(toLight);
  if (!(distance > 0.0f)) return false;
  const glm::vec3 direction = toLight / distance;
  const float cosAtEmitter = std::abs(glm::dot(triangle.unitNormal, direction));
  if (!(cosAtEmitter > 0.0f)) return false;
  sample = {direction, distance, triangle.material->emission,
            triangle.pdfArea * distance * distance / cosAtEmitter};
  return true;
}

}  // namespace lpvlab

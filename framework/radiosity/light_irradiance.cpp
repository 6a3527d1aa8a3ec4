#include "framework/radiosity/light_irradiance.h"

#include <atomic>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "framework/reference/punctual_arrival.h"

namespace lpvlab {

LightIrradiance lightIrradiance(const PatchMesh& mesh, const PatchRayScene& scene,
                                const std::vector<PunctualLight>& lights, int samples) {
  LightIrradiance out;
  out.perSide.assign(mesh.sides(), glm::dvec3(0.0));
  if (lights.empty()) return out;
  const EmbreeScene& embree = scene.embree();
  const float epsilon = embree.epsilon();
  // Sample points: centres of the cells of an m x m grid folded onto the triangle (m^2 >= samples
  // would overshoot; the first `samples` cells of a Halton-free fixed order are used).
  const int grid = std::max(1, int(std::ceil(std::sqrt(double(samples)))));
  std::vector<glm::vec2> points;
  for (int k = 0; k < samples; ++k) {
    const float s = (float(k % grid) + 0.5f) / grid, t = (float(k / grid) + 0.5f) / grid;
    const float root = std::sqrt(s);
    points.emplace_back(root * (1.0f - t), root * t);
  }
  std::atomic<std::size_t> rays{0};
  tbb::parallel_for(std::size_t(0), mesh.sides(), [&](std::size_t side) {
    const Patch& patch = mesh.patches[side / 2];
    const glm::vec3 n = sideNormal(mesh, side);
    glm::dvec3 sum(0.0);
    std::size_t traced = 0;
    ShadowPacket packet;
    glm::vec3 weights[kPacketWidth];
    int lane = 0;
    auto flush = [&] {
      embree.occluded(packet);
      for (int l = 0; l < lane; ++l)
        if (!packet.occluded(l)) sum += glm::dvec3(weights[l]);
      traced += std::size_t(lane);
      packet.clear();
      lane = 0;
    };
    for (const glm::vec2& b : points) {
      const glm::vec3 x = pointOn(patch, b.x, b.y) + epsilon * n;
      for (const PunctualLight& light : lights) {
        PunctualArrival a;
        if (!punctualArrival(light, x, a)) continue;
        const float cosine = glm::dot(n, a.toLight);
        if (!(cosine > 0.0f) || !glm::any(glm::greaterThan(a.arriving, glm::vec3(0.0f)))) continue;
        packet.set(lane, x, a.toLight, 0.0f, a.distance);
        weights[lane++] = a.arriving * cosine;
        if (lane == kPacketWidth) flush();
      }
    }
    if (lane > 0) flush();
    out.perSide[side] = sum / double(points.size());
    rays += traced;
  });
  out.shadowRays = rays;
  return out;
}

}  // namespace lpvlab

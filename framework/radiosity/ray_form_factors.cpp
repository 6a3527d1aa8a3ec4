#include "framework/radiosity/ray_form_factors.h"

#include <cmath>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "framework/reference/hemisphere_sampling.h"
#include "framework/reference/random.h"

namespace lpvlab {

RayFormFactors::RayFormFactors(const PatchMesh& mesh, const PatchRayScene& scene, int rays, std::uint64_t seed)
    : mesh_(mesh), scene_(scene), rays_(rays), seed_(seed) {}

std::vector<FormFactor> RayFormFactors::row(std::uint32_t side, RowAccumulator& accumulator) const {
  const Patch& patch = mesh_.patches[side / 2];
  const glm::vec3 n = sideNormal(mesh_, side);
  const EmbreeScene& embree = scene_.embree();
  const glm::vec3 lift = (2.0f * embree.epsilon()) * n;  // off the patch, to the side's half-space
  SampleRandom random(seed_, side, 0);
  // Origins stratified over the triangle: ray k in cell k of a square grid over the unit square,
  // folded onto the triangle (Turk's square-to-triangle map keeps strata compact).
  const int strata = std::max(1, int(std::sqrt(double(rays_))));
  RayPacket packet;
  int lane = 0;
  auto flush = [&] {
    embree.intersect(packet, false);
    for (int l = 0; l < lane; ++l)
      if (packet.hit(l)) {
        const RayHit hit = packet.hitAt(l);
        const std::size_t target = scene_.patchOf(hit);
        const bool front = glm::dot(glm::vec3(packet.query.ray.dir_x[l], packet.query.ray.dir_y[l],
                                              packet.query.ray.dir_z[l]),
                                    mesh_.patches[target].normal) < 0.0f;
        accumulator.add(std::uint32_t(2 * target + (front ? 0 : 1)), 1.0);
      }
    packet.clear();
    lane = 0;
  };
  for (int k = 0; k < rays_; ++k) {
    const int cell = k % (strata * strata);
    const float s = (float(cell % strata) + random.uniform()) / strata;
    const float t = (float(cell / strata) + random.uniform()) / strata;
    const float root = std::sqrt(s);
    const glm::vec3 origin = pointOn(patch, root * (1.0f - t), root * t) + lift;
    const glm::vec3 direction = cosineHemisphere(n, random.uniform(), random.uniform());
    packet.set(lane++, origin, direction, 0.0f, std::numeric_limits<float>::infinity());
    if (lane == kPacketWidth) flush();
  }
  if (lane > 0) flush();
  return accumulator.take(1.0 / rays_);
}

void RayFormFactors::computeRows(const std::vector<std::uint32_t>& sides, FormFactorRows& rows) {
  tbb::enumerable_thread_specific<RowAccumulator> accumulators([&] { return RowAccumulator(mesh_.sides()); });
  std::vector<std::vector<FormFactor>> made(sides.size());
  tbb::parallel_for(std::size_t(0), sides.size(), [&](std::size_t k) { made[k] = row(sides[k], accumulators.local()); });
  for (std::size_t k = 0; k < sides.size(); ++k) rows.set(sides[k], std::move(made[k]));
  traced_ += sides.size() * std::size_t(rays_);
}

nlohmann::json RayFormFactors::statistics() const {
  return {{"estimator", "rays"}, {"rays_per_side", rays_}, {"rays", traced_}};
}

}  // namespace lpvlab

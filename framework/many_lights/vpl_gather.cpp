#include "framework/many_lights/vpl_gather.h"

#include <algorithm>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/many_lights/vpl_depth_maps.h"
#include "framework/reference/embree_scene.h"

namespace lpvlab {

namespace {

// One pixel's pairs waiting for their shadow rays.
struct PendingPairs {
  ShadowPacket packet;
  glm::vec3 gfr[kPacketWidth];
  const Vpl* vpl[kPacketWidth];
  int count = 0;
};

// What gathering one pixel needs: the VPLs, how their visibility is found, and the offsets.
struct PixelGatherer {
  std::span<const Vpl> vpls;
  const GatherSettings& settings;
  const GatherVisibilitySource& source;
  bool rays;          // visibility by shadow rays through source.scene
  float minDistance;  // the geometry term's distance clamp
  float epsilon;      // ray offsets from the surfaces

  // The radiance that the VPLs send to the surface point p (normal n, albedo rho) through its
  // Lambertian BRDF, clamped per pair (settings.clamp); counts into `row`.
  glm::dvec3 gather(const glm::vec3& p, const glm::vec3& n, const glm::vec3& rho,
                    PendingPairs& pending, GatherCounts& row) const {
    glm::dvec3 sum(0.0), removed(0.0);
    double largest = 0.0;
    const auto flush = [&] {
      if (pending.count == 0) return;
      source.scene->occluded(pending.packet);
      row.shadowRays += pending.count;
      for (int lane = 0; lane < pending.count; ++lane) {
        if (pending.packet.occluded(lane)) continue;
        const glm::vec3& gfr = pending.gfr[lane];
        largest = std::max(largest, double(std::max({gfr.r, gfr.g, gfr.b})));
        addClamped(pending.vpl[lane]->flux, gfr, settings.clamp, sum, removed);
      }
      pending.packet.clear();
      pending.count = 0;
    };
    const glm::vec3 origin = p + epsilon * n;
    for (std::size_t index = 0; index < vpls.size(); ++index) {
      const Vpl& vpl = vpls[index];
      glm::vec3 toVpl;
      float distance = 0.0f;
      const glm::vec3 gfr = settings.lobe.lambertianPoints()
                                ? vplGeometryTerm(p, n, rho, vpl, minDistance, toVpl, distance)
                                : vplTransfer(p, n, rho, vpl, settings.lobe, minDistance, toVpl, distance);
      if (!(gfr.r > 0.0f || gfr.g > 0.0f || gfr.b > 0.0f)) continue;
      row.pairs += 1.0;
      if (!rays) {
        if (settings.visibility == GatherVisibility::DepthMaps && !source.maps->visible(index, vpl, p, n))
          continue;
        largest = std::max(largest, double(std::max({gfr.r, gfr.g, gfr.b})));
        addClamped(vpl.flux, gfr, settings.clamp, sum, removed);
        continue;
      }
      // From just above the pixel's surface to just above the VPL's.
      const glm::vec3 end = vpl.position + epsilon * vpl.normal;
      const glm::vec3 span = end - origin;
      const float length = glm::length(span);
      if (!(length > 0.0f)) continue;
      pending.packet.set(pending.count, origin, span / length, 0.0f, length * (1.0f - 1e-4f));
      pending.gfr[pending.count] = gfr;
      pending.vpl[pending.count] = &vpl;
      if (++pending.count == kPacketWidth) flush();
    }
    flush();
    row.radiance += sum.r + sum.g + sum.b;
    row.clampedAway += removed.r + removed.g + removed.b;
    row.largestGfr = std::max(row.largestGfr, largest);
    return sum;
  }
};

void checkInputs(const HostImage& position, const HostImage& normal, const HostImage& albedo,
                 std::span<const Vpl> vpls, const GatherSettings& settings,
                 const GatherVisibilitySource& source, const HostImage& indirect) {
  for (const HostImage* image : {&normal, &albedo, &indirect})
    if (image->width != position.width || image->height != position.height)
      throw Error("VPL gathering: the G-buffer and the output differ in size");
  if (settings.visibility == GatherVisibility::Rays && !source.scene)
    throw Error("VPL gathering: exact visibility needs the scene's rays");
  if (settings.visibility == GatherVisibility::DepthMaps &&
      (!source.maps || source.maps->depths.size() <
                           vpls.size() * std::size_t(source.maps->settings.size) * source.maps->settings.size))
    throw Error("VPL gathering: shadow-map visibility needs a map per VPL");
}

}  // namespace

void gatherVpls(const HostImage& position, const HostImage& normal, const HostImage& albedo,
                std::span<const Vpl> vpls, const GatherSettings& settings,
                const GatherVisibilitySource& source, HostImage& indirect, GatherCounts* counts) {
  checkInputs(position, normal, albedo, vpls, settings, source, indirect);
  const EmbreeScene* scene = source.scene;
  const PixelGatherer gatherer{
      vpls, settings, source, settings.visibility == GatherVisibility::Rays,
      scene ? std::max(settings.minDistance, 4.0f * scene->epsilon()) : settings.minDistance,
      scene ? scene->epsilon() : 0.0f};
  const int width = position.width, height = position.height;
  std::vector<GatherCounts> rows(static_cast<std::size_t>(height));

  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& range) {
    PendingPairs pending;
    for (int y = range.begin(); y != range.end(); ++y)
      for (int x = 0; x < width; ++x) {
        const std::size_t i = std::size_t(y) * width + x;
        if (!(position.texels[i].w > 0.0f)) continue;
        const glm::dvec3 sum = gatherer.gather(glm::vec3(position.texels[i]), glm::vec3(normal.texels[i]),
                                               glm::vec3(albedo.texels[i]), pending, rows[std::size_t(y)]);
        indirect.texels[i] += glm::vec4(glm::vec3(sum), 0.0f);
      }
  });
  if (!counts) return;
  *counts = {};
  for (const GatherCounts& row : rows) {
    counts->pairs += row.pairs;
    counts->shadowRays += row.shadowRays;
    counts->radiance += row.radiance;
    counts->clampedAway += row.clampedAway;
    counts->largestGfr = std::max(counts->largestGfr, row.largestGfr);
  }
}

}  // namespace lpvlab

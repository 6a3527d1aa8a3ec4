#include "variants/occlusion/geometry_volume_cpu.h"

#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/buckets.h"
#include "framework/core/error.h"
#include "framework/math/shared.h"
#include "variants/resources/geometry_volume.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/occlusion/gv_surfel_sources.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

namespace {

// One surfel as the shared functions describe it.
struct Surfel {
  glm::dvec3 normal{0.0};
  double area = 0.0;
  glm::dvec3 albedo{0.0};
  bool albedoKnown = false;
};

// Adds `count` surfels to the target: positionOf(i) is surfel i's position (w = 0: not covered),
// normalOf(i) its normal, surfelAt(i) the rest of it, computed again as each cell sums its own.
template <class PositionOf, class NormalOf, class SurfelAt>
void addSurfels(std::size_t count, PositionOf positionOf, NormalOf normalOf, SurfelAt surfelAt,
                const GvTarget& target) {
  const int cells = target.gv.cellCount();
  const glm::dvec3 origin(target.gv.origin);
  const double cellSize = target.gv.cellSize;
  std::vector<int> cellOf(count, -1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      const glm::vec4 p = positionOf(i);
      if (p.w == 0.0f) continue;
      const glm::ivec3 cell = shared::surfaceCell(shared::gridFromWorld(glm::dvec3(p), origin, cellSize),
                                                  normalOf(i));
      if (shared::cellInside(cell, target.gv.resolution))
        cellOf[i] = shared::cellIndex(cell, target.gv.resolution);
    }
  });
  const Buckets byCell = bucketByKey(cellOf, cells);
  tbb::parallel_for(tbb::blocked_range<int>(0, cells), [&](const tbb::blocked_range<int>& r) {
    for (int cell = r.begin(); cell < r.end(); ++cell) {
      const std::size_t from = byCell.first[std::size_t(cell)], to = byCell.first[std::size_t(cell) + 1];
      if (from == to) continue;
      glm::dvec4 blocking(0.0), albedo(0.0);
      for (std::size_t j = from; j < to; ++j) {
        const Surfel s = surfelAt(byCell.order[j]);
        const double weight = shared::gvSurfelWeight(s.area, cellSize);
        blocking += shared::gvSurfelBlocking(s.normal, weight, double(target.blockingScale));
        if (s.albedoKnown) albedo += glm::dvec4(weight * s.albedo, weight);
      }
      for (int k = 0; k < 4; ++k) target.blocking[std::size_t(k) * cells + cell] += float(blocking[k]);
      if (target.albedo)
        for (int c = 0; c < 4; ++c) target.albedo[std::size_t(cell) * 4 + c] += float(albedo[c]);
    }
  });
}

}  // namespace

void addCameraSurfelsCpu(const GBufferImages& g, const glm::vec3& cameraPosition, float texelEdge,
                         const GvTarget& target) {
  const std::size_t pixels = g.position->texels.size();
  if (g.normal->texels.size() != pixels || (target.albedo && g.albedo->texels.size() != pixels))
    throw Error("geometry volume (CPU): the G-buffer's images differ in size");
  addSurfels(
      pixels, [&](std::size_t i) { return g.position->texels[i]; },
      [&](std::size_t i) { return glm::dvec3(g.normal->texels[i]); },
      [&](std::size_t i) {
        const glm::vec4 normalDepth = g.normal->texels[i];
        Surfel s;
        s.normal = glm::dvec3(normalDepth);
        s.area = shared::gvCameraSurfelArea(glm::dvec3(g.position->texels[i]), s.normal,
                                            double(normalDepth.w), glm::dvec3(cameraPosition),
                                            double(texelEdge));
        s.albedoKnown = target.albedo != nullptr;
        if (s.albedoKnown) s.albedo = glm::dvec3(g.albedo->texels[i]);
        return s;
      },
      target);
}

void addRsmSurfelsCpu(const RsmImages& rsm, const LightViews& records, const GvTarget& target) {
  const std::size_t texels = rsm.position->texels.size();
  if (rsm.normal->texels.size() != texels || rsm.flux->texels.size() != texels)
    throw Error("geometry volume (CPU): the RSM's images differ in size");
  const int resolution = rsm.position->width;
  if (rsm.position->height != resolution || std::size_t(rsm.position->layers) > records.views.size())
    throw Error("geometry volume (CPU): the RSM is not square or has a layer without its view");
  // Named members, not a structured binding: clang 14 cannot capture bindings in lambdas.
  const auto lightViews = sharedLightViews<shared::GpuLight, shared::GpuView>(records);
  const auto& lights = lightViews.lights;
  const auto& views = lightViews.views;
  const std::size_t perLayer = std::size_t(resolution) * resolution;
  addSurfels(
      texels, [&](std::size_t i) { return rsm.position->texels[i]; },
      [&](std::size_t i) { return glm::dvec3(rsm.normal->texels[i]); },
      [&](std::size_t i) {
        const shared::GpuView& view = views[i / perLayer];
        const shared::GpuLight& light = lights[std::size_t(view.params.z)];
        const glm::dvec3 p(rsm.position->texels[i]);
        Surfel s;
        s.normal = glm::dvec3(rsm.normal->texels[i]);
        s.area = shared::gvRsmSurfelArea(view, light, p, s.normal, resolution);
        if (target.albedo) {
          const std::size_t inLayer = i % perLayer;
          const glm::dvec2 texelCentre(double(inLayer % std::size_t(resolution)) + 0.5,
                                       double(inLayer / std::size_t(resolution)) + 0.5);
          const shared::GvSurfelAlbedo albedo = shared::gvRsmSurfelAlbedo(
              view, light, p, s.normal, texelCentre, glm::dvec3(rsm.flux->texels[i]), resolution);
          s.albedo = albedo.albedo;
          s.albedoKnown = albedo.known;
        }
        return s;
      },
      target);
}

void mergeGeometryVolumesCpu(float* first, const float* other, int cells, float* firstAlbedo,
                             const float* otherAlbedo) {
  for (std::size_t i = 0; i < std::size_t(cells); ++i)
    if (shared::gvMergeTakesOther(first[i], other[i])) {
      for (std::size_t k = 0; k < 4; ++k) first[k * cells + i] = other[k * cells + i];
      if (firstAlbedo && otherAlbedo)
        for (std::size_t k = 0; k < 4; ++k) firstAlbedo[4 * i + k] = otherAlbedo[4 * i + k];
    }
}

}  // namespace lpvlab

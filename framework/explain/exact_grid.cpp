#include "framework/explain/exact_grid.h"

#include <algorithm>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/math/shared.h"
#include "framework/reference/embree_scene.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/common/grid.glsl"
#include "shaders/common/sh.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

namespace {

constexpr int kMaxCoefficients = 16;

// One cell's sums, in double precision (a cell may gather thousands of VPLs).
struct CellSum {
  double c[3][kMaxCoefficients] = {};

  void add(const glm::dvec3& intensity, const glm::dvec3& w, int coefficients) {
    for (int k = 0; k < coefficients; ++k) {
      const double y = shared::shBasisAt(k, w);
      c[0][k] += intensity.r * y;
      c[1][k] += intensity.g * y;
      c[2][k] += intensity.b * y;
    }
  }
};

// A VPL's contribution to a cell centre before visibility: the intensity it stores (W/sr) and the
// direction it travels; zero intensity where the VPL faces away.
struct Arrival {
  glm::dvec3 intensity{0.0};
  glm::dvec3 direction{0.0};
  double distance = 0.0;
};

Arrival arrival(const Vpl& vpl, const glm::dvec3& centre, double cellSize) {
  const glm::dvec3 d = centre - glm::dvec3(vpl.position);
  const double d2 = glm::dot(d, d);
  Arrival a;
  if (!(d2 > 0.0)) return a;  // a VPL exactly at the centre: no direction to send its light
  a.distance = std::sqrt(d2);
  a.direction = d / a.distance;
  const double cosine = glm::dot(glm::dvec3(vpl.normal), a.direction);
  if (cosine <= 0.0) return a;
  const double s2 = cellSize * cellSize;
  a.intensity = glm::dvec3(vpl.flux) * (cosine / M_PI * s2 / std::max(d2, s2));
  return a;
}

// The cell's visibility points: the centres of its 2 x 2 x 2 sub-cells, offsets in cells.
constexpr int kVisibilityPoints = 8;
constexpr int kVplsPerPacket = kPacketWidth / kVisibilityPoints;

// The cell's sum over `vpls`, with shadow rays in packets where `scene` is given: each VPL's
// light weighted by the fraction of the cell's visibility points that see it.
void sumCell(std::span<const Vpl> vpls, const glm::dvec3& centre, double cellSize,
             int coefficients, const EmbreeScene* scene, CellSum& sum) {
  if (!scene) {
    for (const Vpl& vpl : vpls) {
      const Arrival a = arrival(vpl, centre, cellSize);
      if (a.intensity != glm::dvec3(0.0)) sum.add(a.intensity, a.direction, coefficients);
    }
    return;
  }
  const float epsilon = scene->epsilon();
  ShadowPacket packet;
  Arrival pending[kVplsPerPacket];
  int count = 0;
  const auto flush = [&] {
    scene->occluded(packet);
    for (int v = 0; v < count; ++v) {
      int seen = 0;
      for (int p = 0; p < kVisibilityPoints; ++p) seen += packet.occluded(v * kVisibilityPoints + p) ? 0 : 1;
      // An exact 1 when every point sees the VPL: then the grid is the one without visibility.
      if (seen > 0) sum.add(pending[v].intensity * (double(seen) / kVisibilityPoints), pending[v].direction, coefficients);
    }
    packet.clear();
    count = 0;
  };
  for (const Vpl& vpl : vpls) {
    const Arrival a = arrival(vpl, centre, cellSize);
    if (a.intensity == glm::dvec3(0.0)) continue;
    // From just above the VPL's surface to each point (a point closer than the offsets sees it).
    const glm::vec3 origin = vpl.position + epsilon * vpl.normal;
    for (int p = 0; p < kVisibilityPoints; ++p) {
      const glm::dvec3 offset((p & 1) ? 0.25 : -0.25, (p & 2) ? 0.25 : -0.25, (p & 4) ? 0.25 : -0.25);
      const glm::vec3 span = glm::vec3(centre + offset * cellSize) - origin;
      const float length = glm::length(span);
      const int lane = count * kVisibilityPoints + p;
      if (length > 2.0f * epsilon)
        packet.set(lane, origin, span / length, 0.0f, length);
      else
        packet.set(lane, origin, glm::vec3(0, 0, 1), 0.0f, 0.0f);  // nothing can block an empty ray
    }
    pending[count] = a;
    if (++count == kVplsPerPacket) flush();
  }
  if (count > 0) flush();
}

}  // namespace

std::vector<float> exactLightGrid(std::span<const Vpl> vpls, const GridGeometry& grid,
                                  int coefficients, const EmbreeScene* visibility,
                                  const std::function<void(double)>& progress) {
  if (coefficients != 4 && coefficients != 9 && coefficients != 16)
    throw Error("explain: " + std::to_string(coefficients) +
                " SH coefficients per channel is not 4, 9 or 16");
  const int cells = grid.cellCount();
  std::vector<float> out(std::size_t(3) * coefficients * cells, 0.0f);
  const glm::ivec3 r = grid.resolution;
  // Slices of z one after another (each in parallel), so progress can be told between them.
  for (int z = 0; z < r.z; ++z) {
    tbb::parallel_for(tbb::blocked_range<int>(0, r.x * r.y), [&](const tbb::blocked_range<int>& range) {
      for (int i = range.begin(); i != range.end(); ++i) {
        const glm::ivec3 cell(i % r.x, i / r.x, z);
        const glm::dvec3 centre =
            glm::dvec3(grid.origin) + (glm::dvec3(cell) + 0.5) * double(grid.cellSize);
        CellSum sum;
        sumCell(vpls, centre, grid.cellSize, coefficients, visibility, sum);
        const int index = shared::cellIndex(cell, r);
        for (int channel = 0; channel < 3; ++channel)
          for (int k = 0; k < coefficients; ++k)
            out[std::size_t(shared::coefficientIndex(channel, k, coefficients, index, cells))] =
                float(sum.c[channel][k]);
      }
    });
    if (progress) progress(double(z + 1) / r.z);
  }
  return out;
}

}  // namespace lpvlab

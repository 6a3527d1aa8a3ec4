#include "variants/propagation/directed_cpu.h"

#include <algorithm>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/math/dual.h"
#include "framework/math/shared.h"
#include "variants/resources/geometry_volume.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/directed_faces.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

namespace {

constexpr int kUnreached = -1;

// The six face neighbours' offsets.
const glm::ivec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

// The dilation of directed_dilate.comp (directedDilated over the six neighbours' unit normals),
// step by step: each cell's normal as the gather sees it, and the iteration from which it has
// one (kUnreached: never). Only the cells next to those that gained a normal in the step before
// can gain one, so each step looks at those alone.
struct DilatedNormals {
  std::vector<glm::vec4> stored;  // as the GL kernels store them (float)
  std::vector<int> since;
};

DilatedNormals dilateNormals(const glm::ivec3& res, const std::vector<float>& injected,
                             int iterations, bool dilation) {
  const std::size_t cells = std::size_t(res.x) * res.y * res.z;
  DilatedNormals d;
  d.stored.resize(cells);
  d.since.assign(cells, kUnreached);
  std::vector<glm::dvec3> unit(cells, glm::dvec3(0.0));
  std::vector<glm::ivec3> gained;
  for (int z = 0; z < res.z; ++z)
    for (int y = 0; y < res.y; ++y)
      for (int x = 0; x < res.x; ++x) {
        const glm::ivec3 cell(x, y, z);
        const std::size_t i = std::size_t(shared::cellIndex(cell, res));
        d.stored[i] = glm::vec4(injected[4 * i], injected[4 * i + 1], injected[4 * i + 2],
                                injected[4 * i + 3]);
        if (!shared::directedHasNormal(glm::dvec4(d.stored[i]))) continue;
        d.since[i] = 0;
        unit[i] = shared::directedUnitNormal(glm::dvec4(d.stored[i]));
        gained.push_back(cell);
      }
  if (!dilation) return d;
  std::vector<char> candidate(cells, 0);
  for (int iteration = 0; iteration < iterations && !gained.empty(); ++iteration) {
    // The cells without a normal next to the last step's gains, each once.
    std::vector<glm::ivec3> candidates;
    for (const glm::ivec3& g : gained)
      for (const glm::ivec3& axis : kAxes) {
        const glm::ivec3 c = g + axis;
        if (!shared::cellInside(c, res)) continue;
        const std::size_t i = std::size_t(shared::cellIndex(c, res));
        if (d.since[i] != kUnreached || candidate[i]) continue;
        candidate[i] = 1;
        candidates.push_back(c);
      }
    // Each from its neighbours as they were before this step (no candidate has a normal yet).
    std::vector<std::pair<std::size_t, glm::vec4>> results;
    for (const glm::ivec3& c : candidates) {
      glm::dvec3 sum(0.0);
      for (const glm::ivec3& axis : kAxes)
        if (shared::cellInside(c + axis, res))
          sum += unit[std::size_t(shared::cellIndex(c + axis, res))];
      const std::size_t i = std::size_t(shared::cellIndex(c, res));
      candidate[i] = 0;
      results.emplace_back(i, glm::vec4(shared::directedDilated(glm::dvec4(d.stored[i]), sum)));
    }
    gained.clear();
    for (const auto& [i, value] : results) {
      if (!shared::directedHasNormal(glm::dvec4(value))) continue;  // opposite normals cancelled
      d.stored[i] = value;
      d.since[i] = iteration;
      unit[i] = shared::directedUnitNormal(glm::dvec4(value));
      const int x = int(i % std::size_t(res.x)), rest = int(i / std::size_t(res.x));
      gained.emplace_back(x, rest % res.y, rest / res.y);
    }
  }
  return d;
}

// An Error unless `injected` holds a vec4 per cell of a `cells`-cell grid.
void checkNormalGrid(const std::vector<float>& injected, std::size_t cells) {
  if (injected.size() != 4 * cells)
    throw Error("directed propagation (CPU): the normal grid holds " +
                std::to_string(injected.size()) + " floats, not 4 per cell of the " +
                std::to_string(cells) + "-cell grid");
}

// The reprojecting cells of makeDirectedCells from the dilated normals.
template <class Real>
ReprojectedCells<Real> reprojectedFrom(const StandardFaceTable<Real>& table, const glm::ivec3& res,
                                       const DilatedNormals& normals, double farSolidAngle,
                                       double sideSolidAngle) {
  ReprojectedCells<Real> r;
  r.resolution = res;
  r.coefficients = table.coefficients;
  r.width = standardCpuRowWidth(res.x);
  const int rows = res.y * res.z;
  const std::size_t plane = std::size_t(rows) * r.width;
  const int lobes = std::min(table.coefficients, ReprojectedCells<Real>::kMaxLobeCoefficients);
  r.since.assign(plane, ReprojectedCells<Real>::kNever);
  r.faceWeight.assign(6 * plane, Real(0));
  r.lobe.assign(std::size_t(lobes) * plane, Real(0));
  // Per cell with a normal: G(n) (directed_gather.comp finds it per cell and iteration; it is
  // the same every time), the six faces' reprojection weights and the lobe about n.
  tbb::parallel_for(tbb::blocked_range<int>(0, rows), [&](const tbb::blocked_range<int>& range) {
    for (int row = range.begin(); row < range.end(); ++row)
      for (int x = 0; x < res.x; ++x) {
        const std::size_t cell = std::size_t(row) * res.x + x;  // grid.glsl's cellIndex
        if (normals.since[cell] == kUnreached) continue;
        const glm::dvec4 stored(normals.stored[cell]);
        const glm::dvec3 n = shared::directedUnitNormal(stored);
        const double gain =
            shared::directedGainOf(stored, farSolidAngle, sideSolidAngle, table.coefficients);
        const std::size_t at = std::size_t(row) * r.width + x;
        r.since[at] = Real(normals.since[cell]);
        for (int normal = 0; normal < 6; ++normal)
          r.faceWeight[normal * plane + at] = Real(shared::directedReprojection(
              glm::dvec3(table.offset[normal]), n, gain, table.coefficients));
        for (int k = 0; k < lobes; ++k) r.lobe[k * plane + at] = Real(shared::shCosineLobeAt(k, n));
      }
  });
  return r;
}

// The released cells of makeReleasedCells from the dilated normals.
ReleasedCells releasedFrom(const glm::ivec3& res, const DilatedNormals& normals,
                           double cosRegionAngle) {
  const std::size_t cells = std::size_t(res.x) * res.y * res.z;
  ReleasedCells r;
  r.keepFrom.assign(cells, 0);
  r.keepUntil.assign(cells, 0);  // empty: released in every iteration
  tbb::parallel_for(tbb::blocked_range<int>(0, res.y * res.z), [&](const tbb::blocked_range<int>& range) {
    for (int row = range.begin(); row < range.end(); ++row)
      for (int x = 0; x < res.x; ++x) {
        const glm::ivec3 cell(x, row % res.y, row / res.y);
        const std::size_t i = std::size_t(row) * res.x + x;  // grid.glsl's cellIndex
        if (normals.since[i] == kUnreached) continue;
        const glm::dvec4 own(normals.stored[i]);
        int until = ReleasedCells::kAlways;
        for (const glm::ivec3& axis : kAxes) {
          if (!shared::cellInside(cell + axis, res)) continue;
          const std::size_t j = std::size_t(shared::cellIndex(cell + axis, res));
          if (normals.since[j] == kUnreached) continue;
          if (shared::directedNeighbourReleases(own, glm::dvec4(normals.stored[j]), cosRegionAngle))
            until = std::min(until, normals.since[j]);
        }
        r.keepFrom[i] = normals.since[i];
        r.keepUntil[i] = std::max(until, normals.since[i]);
      }
  });
  return r;
}

// The normal grid checked and dilated as the GL kernels dilate it.
DilatedNormals checkedDilation(const glm::ivec3& res, const std::vector<float>& injectedNormals,
                               int iterations, bool dilation) {
  checkNormalGrid(injectedNormals, std::size_t(res.x) * res.y * res.z);
  return dilateNormals(res, injectedNormals, iterations, dilation);
}

}  // namespace

template <class Real>
ReprojectedCells<Real> makeDirectedCells(const StandardFaceTable<Real>& table,
                                         const glm::ivec3& res,
                                         const std::vector<float>& injectedNormals, int iterations,
                                         bool dilation, double farSolidAngle,
                                         double sideSolidAngle) {
  return reprojectedFrom(table, res, checkedDilation(res, injectedNormals, iterations, dilation),
                         farSolidAngle, sideSolidAngle);
}

ReleasedCells makeReleasedCells(const glm::ivec3& res, const std::vector<float>& injectedNormals,
                                int iterations, bool dilation, double cosRegionAngle) {
  return releasedFrom(res, checkedDilation(res, injectedNormals, iterations, dilation),
                      cosRegionAngle);
}

template <class Real>
DirectedCells<Real> makeDirectedAndReleasedCells(const StandardFaceTable<Real>& table,
                                                 const glm::ivec3& res,
                                                 const std::vector<float>& injectedNormals,
                                                 int iterations, bool dilation,
                                                 double farSolidAngle, double sideSolidAngle,
                                                 std::optional<double> cosRegionAngle) {
  const DilatedNormals normals = checkedDilation(res, injectedNormals, iterations, dilation);
  DirectedCells<Real> cells{reprojectedFrom(table, res, normals, farSolidAngle, sideSolidAngle), {}};
  if (cosRegionAngle) cells.released = releasedFrom(res, normals, *cosRegionAngle);
  return cells;
}

template DirectedCells<float> makeDirectedAndReleasedCells<float>(
    const StandardFaceTable<float>&, const glm::ivec3&, const std::vector<float>&, int, bool,
    double, double, std::optional<double>);
template DirectedCells<Dual> makeDirectedAndReleasedCells<Dual>(
    const StandardFaceTable<Dual>&, const glm::ivec3&, const std::vector<float>&, int, bool,
    double, double, std::optional<double>);
template ReprojectedCells<float> makeDirectedCells<float>(const StandardFaceTable<float>&,
                                                          const glm::ivec3&,
                                                          const std::vector<float>&, int, bool,
                                                          double, double);
template ReprojectedCells<double> makeDirectedCells<double>(const StandardFaceTable<double>&,
                                                            const glm::ivec3&,
                                                            const std::vector<float>&, int, bool,
                                                            double, double);
template ReprojectedCells<Dual> makeDirectedCells<Dual>(const StandardFaceTable<Dual>&,
                                                        const glm::ivec3&,
                                                        const std::vector<float>&, int, bool,
                                                        double, double);

}  // namespace lpvlab

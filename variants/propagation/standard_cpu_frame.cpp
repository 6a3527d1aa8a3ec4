#include "variants/propagation/standard_cpu_frame.h"

#include <algorithm>
#include <array>
#include <type_traits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/pipeline/dual_frame.h"
#include "framework/pipeline/frame.h"
#include "variants/resources/geometry_volume.h"

namespace lpvlab {

StandardCpuFrame::StandardCpuFrame(int shOrder, double farSolidAngle, double sideSolidAngle,
                                   std::size_t floatsPerGrid)
    : table_(makeStandardFaceTable<float>(shOrder, farSolidAngle, sideSolidAngle)),
      next_(floatsPerGrid, 0.0f) {}

std::size_t StandardCpuFrame::OcclusionCache::bytes() const {
  return (faces.transmittance.size() + faces.bounceLobes.size() + gv.size() + albedo.size()) *
             sizeof(float) +
         faces.bounces.size() * sizeof(StandardOcclusion<float>::Bounce);
}

const StandardOcclusion<float>& StandardCpuFrame::occlusionOf(Frame& frame,
                                                              const GeometryVolume& gv,
                                                              bool bounces) {
  const std::size_t gvCells = std::size_t(gv.geometry.cellCount());
  downloadFloats(gv.blocking, gvCells * GeometryVolume::kCoefficients, gv_);
  if (bounces)
    downloadFloats(frame.get(kSurfaceAlbedo).albedo, gvCells * 4, albedo_);
  else
    albedo_.clear();
  OcclusionCache& cache = occlusion_[&gv];
  const glm::ivec3& resolution = frame.lightGrid.geometry.resolution;
  if (cache.faces.resolution != resolution || gv_ != cache.gv || albedo_ != cache.albedo) {
    cache.faces =
        makeStandardOcclusion(table_, resolution, gv_.data(), bounces ? albedo_.data() : nullptr);
    cache.gv = gv_;
    cache.albedo = albedo_;
  }
  return cache.faces;
}

void StandardCpuFrame::propagate(Frame& frame, const Iterations& iterations) {
  const GeometryVolume* gv = frame.find(kGeometryVolume);
  iterate(frame.lightGrid, gv, gv ? &occlusionOf(frame, *gv, iterations.bounces) : nullptr,
          iterations);
}

void StandardCpuFrame::propagate(LightGrid& grid, const Iterations& iterations) {
  iterate(grid, nullptr, nullptr, iterations);
}

namespace {

// Moves the attached light of every cell that does not keep it in `iteration` into the free
// grid (directed_release.comp's rule, ReleasedCells): grids in grid.glsl's layout.
template <class Real>
void releaseCells(const ReleasedCells& released, int iteration, std::vector<Real>& attached,
                  std::vector<Real>& free) {
  const std::size_t cells = released.keepFrom.size(), planes = attached.size() / cells;
  constexpr std::size_t kChunk = 1024;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells, kChunk), [&](const auto& range) {
    for (std::size_t begin = range.begin(); begin < range.end(); begin += kChunk) {
      const std::size_t end = std::min(range.end(), begin + kChunk);
      std::array<unsigned char, kChunk> keeps;  // once per cell, then plane by plane
      for (std::size_t cell = begin; cell < end; ++cell)
        keeps[cell - begin] = released.keeps(cell, iteration);
      for (std::size_t plane = 0; plane < planes; ++plane) {  // every channel and coefficient
        Real* a = attached.data() + plane * cells;
        Real* f = free.data() + plane * cells;
        for (std::size_t cell = begin; cell < end; ++cell)
          if (!keeps[cell - begin]) {
            f[cell] += a[cell];
            a[cell] = Real(0);
          }
      }
    }
  });
}

// One step of `source` into `target`: gathering with `reprojected` (null: the standard transfer),
// or scattering.
template <class Real>
void stepGrid(const StandardFaceTable<Real>& table, const glm::ivec3& resolution,
              const Real* source, Real* target, Real* accumulated, bool scatter,
              const StandardOcclusion<Real>* faces, StepAccumulation accumulation,
              const ReprojectedCells<Real>* reprojected, int iteration) {
  if (reprojected)
    standardGatherCpu<Real>(table, resolution, source, target, accumulated, "auto", 0, faces,
                            accumulation, reprojected, iteration);
  else if constexpr (std::is_same_v<Real, Dual>)
    // Dual frames always gather: scattering gives the same light and has no Dual version (an
    // unoptimised build must not even name it; only -O2 removed the call to it).
    standardGatherCpu<Real>(table, resolution, source, target, accumulated, "auto", 0, faces,
                            accumulation);
  else
    standardIterationCpu<Real>(scatter, table, resolution, source, target, accumulated, "auto",
                               0, faces, accumulation);
}

// `count` steps from `current` (left holding the last step's light; `next` its partner),
// accumulating into `accumulated`, iterations paired (pairedAccumulation); the GV's faces
// (`occlusion`) from its first occluded iteration on. Float frames and dual ones alike. With
// `released`, `current` starts as the attached light and `free`/`freeNext` hold the free light
// (ReleasedCells); both add to `accumulated` (a release moves light between the grids within a
// cell, so a deferred step's source is still the whole previous step), and `current` ends as
// their sum.
template <class Real>
void iterateGrid(const StandardFaceTable<Real>& table, const glm::ivec3& resolution,
                 std::vector<Real>& current, std::vector<Real>& next,
                 std::vector<Real>& accumulated, int count, bool scatter,
                 const StandardOcclusion<Real>* occlusion, int firstOccludedIteration,
                 const ReprojectedCells<Real>* reprojected, const ReleasedCells* released,
                 std::vector<Real>& free, std::vector<Real>& freeNext) {
  next.resize(current.size());
  if (released) {
    free.assign(current.size(), Real(0));
    freeNext.resize(current.size());
  }
  for (int i = 0; i < count; ++i) {
    const StandardOcclusion<Real>* faces = i >= firstOccludedIteration ? occlusion : nullptr;
    const StepAccumulation accumulation = pairedAccumulation(i, count);
    if (released) {
      releaseCells(*released, i, current, free);
      stepGrid<Real>(table, resolution, free.data(), freeNext.data(), accumulated.data(), scatter,
                     faces, accumulation, nullptr, i);
      free.swap(freeNext);
    }
    stepGrid<Real>(table, resolution, current.data(), next.data(), accumulated.data(), scatter,
                   faces, accumulation, reprojected, i);
    current.swap(next);  // the grid now holds the new light
  }
  if (released)
    for (std::size_t k = 0; k < current.size(); ++k) current[k] += free[k];
}

}  // namespace

void StandardCpuFrame::iterate(LightGrid& grid, const GeometryVolume* gv,
                               const StandardOcclusion<float>* occlusion,
                               const Iterations& iterations) {
  iterateGrid<float>(table_, grid.geometry.resolution, grid.current.host(), next_,
                     grid.accumulated.host(), iterations.count, iterations.scatter,
                     gv ? occlusion : nullptr, gv ? gv->firstOccludedIteration : 0,
                     iterations.reprojected, iterations.released, free_, freeNext_);
}

void StandardCpuFrame::propagateDual(DualFrame& dual, int shOrder, Dual farSolidAngle,
                                     Dual sideSolidAngle, const DualIterations& iterations) {
  Frame& frame = dual.frame;
  const glm::ivec3 resolution = frame.lightGrid.geometry.resolution;
  const StandardFaceTable<Dual> table =
      makeStandardFaceTable<Dual, Dual>(shOrder, farSolidAngle, sideSolidAngle);
  // The GV's faces on Dual: from its derivatives when the occlusion stage made them, else from
  // the frame's GV as constants.
  const GeometryVolume* gv = frame.find(kGeometryVolume);
  StandardOcclusion<Dual> occlusion;
  if (gv) {
    std::vector<float> values;
    downloadFloats(gv->blocking, std::size_t(gv->geometry.cellCount()) * GeometryVolume::kCoefficients,
                   values);
    const std::vector<Dual> blocking = dual.gvBlocking.empty() ? constantDuals(values) : dual.gvBlocking;
    std::vector<Dual> albedo;
    if (iterations.bounces) {
      downloadFloats(frame.get(kSurfaceAlbedo).albedo, std::size_t(gv->geometry.cellCount()) * 4,
                     values);
      albedo = constantDuals(values);
    }
    occlusion = makeStandardOcclusion<Dual, Dual>(table, resolution, blocking.data(),
                                                  iterations.bounces ? albedo.data() : nullptr);
  }
  std::vector<Dual> current = dual.injected, next, free, freeNext;
  dual.accumulated = dual.injected;  // the accumulated light starts as the injected light
  iterateGrid<Dual>(table, resolution, current, next, dual.accumulated, iterations.count, false,
                    gv ? &occlusion : nullptr, gv ? gv->firstOccludedIteration : 0,
                    iterations.reprojected, iterations.released, free, freeNext);
}

std::size_t StandardCpuFrame::memoryBytes() const {
  std::size_t bytes =
      (next_.size() + free_.size() + freeNext_.size() + gv_.size() + albedo_.size()) * sizeof(float);
  for (const auto& [gv, cache] : occlusion_) bytes += cache.bytes();
  return bytes;
}

}  // namespace lpvlab

#include "variants/propagation/standard_cpu_frame.h"

#include <type_traits>

#include "framework/pipeline/dual_frame.h"
#include "framework/pipeline/frame.h"

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

// `count` steps from `current` (left holding the last step's light; `next` its partner),
// accumulating into `accumulated`, iterations paired (pairedAccumulation); the GV's faces
// (`occlusion`) from its first occluded iteration on. Float frames and dual ones alike.
template <class Real>
void iterateGrid(const StandardFaceTable<Real>& table, const glm::ivec3& resolution,
                 std::vector<Real>& current, std::vector<Real>& next,
                 std::vector<Real>& accumulated, int count, bool scatter,
                 const StandardOcclusion<Real>* occlusion, int firstOccludedIteration,
                 const ReprojectedCells<Real>* reprojected) {
  next.resize(current.size());
  for (int i = 0; i < count; ++i) {
    const StandardOcclusion<Real>* faces = i >= firstOccludedIteration ? occlusion : nullptr;
    const StepAccumulation accumulation = pairedAccumulation(i, count);
    if (reprojected)
      standardGatherCpu<Real>(table, resolution, current.data(), next.data(), accumulated.data(),
                              "auto", 0, faces, accumulation, reprojected, i);
    else if constexpr (std::is_same_v<Real, Dual>)
      // Dual frames always gather: scattering gives the same light and has no Dual version (an
      // unoptimised build must not even name it; only -O2 removed the call to it).
      standardGatherCpu<Real>(table, resolution, current.data(), next.data(), accumulated.data(),
                              "auto", 0, faces, accumulation);
    else
      standardIterationCpu<Real>(scatter, table, resolution, current.data(), next.data(),
                                 accumulated.data(), "auto", 0, faces, accumulation);
    current.swap(next);  // the grid now holds the new light
  }
}

}  // namespace

void StandardCpuFrame::iterate(LightGrid& grid, const GeometryVolume* gv,
                               const StandardOcclusion<float>* occlusion,
                               const Iterations& iterations) {
  iterateGrid<float>(table_, grid.geometry.resolution, grid.current.host(), next_,
                     grid.accumulated.host(), iterations.count, iterations.scatter,
                     gv ? occlusion : nullptr, gv ? gv->firstOccludedIteration : 0,
                     iterations.reprojected);
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
  std::vector<Dual> current = dual.injected, next;
  dual.accumulated = dual.injected;  // the accumulated light starts as the injected light
  iterateGrid<Dual>(table, resolution, current, next, dual.accumulated, iterations.count, false,
                    gv ? &occlusion : nullptr, gv ? gv->firstOccludedIteration : 0,
                    iterations.reprojected);
}

std::size_t StandardCpuFrame::memoryBytes() const {
  std::size_t bytes = (next_.size() + gv_.size() + albedo_.size()) * sizeof(float);
  for (const auto& [gv, cache] : occlusion_) bytes += cache.bytes();
  return bytes;
}

}  // namespace lpvlab

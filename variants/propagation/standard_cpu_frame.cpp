#include "variants/propagation/standard_cpu_frame.h"

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

void StandardCpuFrame::iterate(LightGrid& grid, const GeometryVolume* gv,
                               const StandardOcclusion<float>* occlusion,
                               const Iterations& iterations) {
  std::vector<float>& current = grid.current.host();
  std::vector<float>& accumulated = grid.accumulated.host();
  next_.resize(current.size());
  for (int i = 0; i < iterations.count; ++i) {
    const StandardOcclusion<float>* faces =
        gv && i >= gv->firstOccludedIteration ? occlusion : nullptr;
    const StepAccumulation accumulation = pairedAccumulation(i, iterations.count);
    if (iterations.reprojected)
      standardGatherCpu<float>(table_, grid.geometry.resolution, current.data(), next_.data(),
                               accumulated.data(), "auto", 0, faces, accumulation,
                               iterations.reprojected, i);
    else
      standardIterationCpu<float>(iterations.scatter, table_, grid.geometry.resolution,
                                  current.data(), next_.data(), accumulated.data(), "auto", 0,
                                  faces, accumulation);
    current.swap(next_);  // the grid's host side now holds the new light
  }
}

std::size_t StandardCpuFrame::memoryBytes() const {
  std::size_t bytes = (next_.size() + gv_.size() + albedo_.size()) * sizeof(float);
  for (const auto& [gv, cache] : occlusion_) bytes += cache.bytes();
  return bytes;
}

}  // namespace lpvlab

#include "framework/reference/path_tracer.h"

#include <algorithm>
#include <atomic>
#include <string>
#include <thread>

#include "framework/core/available_cores.h"
#include "framework/core/error.h"
#include "framework/reference/camera_rays.h"
#include "framework/reference/embree_scene.h"
#include "framework/reference/integrator.h"
#include "framework/reference/light_sampler.h"
#include "framework/reference/material_sampling.h"
#include "framework/reference/random.h"

namespace lpvlab {

namespace {

void checkImageSize(int width, int height) {
  if (width < 1 || height < 1)
    throw Error("path tracer: image size " + std::to_string(width) + "x" + std::to_string(height) +
                " must be at least 1x1");
}

// Adds one path's values to pixel p's sums. Each sample is added on its own, in sample order, so
// rendering n + m samples equals rendering n then m bit for bit.
void accumulate(Accumulator& acc, std::size_t p, const PathSample& sample) {
  const glm::vec3 radiance[Accumulator::kRadianceAovs] = {
      sample.direct, sample.indirect, sample.indirect1, sample.direct + sample.indirect};
  double* sum = acc.sum.data() + p * Accumulator::kRadianceValues;
  double* sumSquares = acc.sumSquares.data() + p * Accumulator::kRadianceValues;
  for (int aov = 0; aov < Accumulator::kRadianceAovs; ++aov)
    for (int c = 0; c < 3; ++c) {
      const double value = radiance[aov][c];
      sum[aov * 3 + c] += value;
      sumSquares[aov * 3 + c] += value * value;
    }
  double* firstHit = acc.firstHit.data() + p * Accumulator::kFirstHitValues;
  for (int c = 0; c < 3; ++c) {
    firstHit[c] += sample.albedo[c];
    firstHit[3 + c] += sample.normal[c];
  }
  firstHit[6] += sample.depth;
}

}  // namespace

// Members in construction order: each refers to the ones above it.
struct PathTracer::Impl {
  Scene scene;
  std::vector<SurfaceMaterial> materials;
  EmbreeScene embree;
  LightSampler lights;
  CameraRays camera;
  Integrator integrator;
  int width, height;
  std::uint64_t seed;
  SampleSequence sampler;

  Impl(const Scene& source, const Camera& view, int width, int height,
       const TracerSettings& settings)
      : scene(source),
        materials(prepareMaterials(scene)),
        embree(scene, materials, settings.engine),
        lights(scene, materials),
        camera(view, width, height),
        integrator(embree, lights, &camera, settings),
        width(width),
        height(height),
        seed(settings.seed),
        sampler(settings.sampler) {}
};

PathTracer::PathTracer(const Scene& scene, const Camera& camera, int width, int height,
                       const TracerSettings& settings) {
  checkImageSize(width, height);
  impl_ = std::make_unique<Impl>(scene, camera, width, height, settings);
}

PathTracer::~PathTracer() = default;

const std::string& PathTracer::isa() const { return impl_->embree.isa(); }
int PathTracer::packetWidth() const { return impl_->embree.packetWidth(); }

std::int64_t PathTracer::render(Accumulator& acc, int count, int threads,
                                std::int64_t* rays) const {
  const Impl& impl = *impl_;
  if (acc.width != impl.width || acc.height != impl.height ||
      acc.sum.size() != std::size_t(impl.width) * impl.height * Accumulator::kRadianceValues ||
      acc.sumSquares.size() != acc.sum.size() ||
      acc.firstHit.size() != std::size_t(impl.width) * impl.height * Accumulator::kFirstHitValues)
    throw Error("path tracer: accumulator is " + std::to_string(acc.width) + "x" +
                std::to_string(acc.height) + " (or malformed), the tracer renders " +
                std::to_string(impl.width) + "x" + std::to_string(impl.height));
  if (count < 0) throw Error("path tracer: negative sample count " + std::to_string(count));

  const std::int64_t firstSample = acc.samples;
  std::atomic<int> nextRow{0};
  std::atomic<std::int64_t> totalRays{0};
  // Rows are handed out one at a time. A row is traced in runs of kPacketWidth pixels, one sample
  // index at a time for the whole run, so a path's packet companions depend only on its pixel and
  // sample index; each pixel's samples are added in order by the thread that took its row. So
  // neither the thread count nor how the samples are split over calls changes a sum.
  auto work = [&] {
    // Per lane and bounce, at most one shadow ray per punctual light, one to an area light and one
    // to the sky: reserved here, so tracing never allocates.
    std::vector<ShadowQuery> shadows;
    shadows.reserve(std::size_t(kPacketWidth) * (impl.lights.punctual().size() + 2));
    SampleRandom randoms[kPacketWidth];
    glm::vec2 positions[kPacketWidth];
    PathSample samples[kPacketWidth];
    std::int64_t localRays = 0;
    for (int y = nextRow++; y < impl.height; y = nextRow++)
      for (int x0 = 0; x0 < impl.width; x0 += kPacketWidth) {
        const int lanes = std::min(kPacketWidth, impl.width - x0);
        const std::size_t p0 = std::size_t(y) * impl.width + x0;
        for (std::int64_t s = firstSample; s < firstSample + count; ++s) {
          for (int i = 0; i < lanes; ++i) {
            randoms[i] = SampleRandom(impl.seed, p0 + i, std::uint64_t(s), impl.sampler);
            // Box filter: a uniform position inside the pixel.
            const float px = float(x0 + i) + randoms[i].uniform();
            const float py = float(y) + randoms[i].uniform();
            positions[i] = glm::vec2(px, py);
          }
          impl.integrator.trace(lanes, positions, randoms, samples, shadows);
          for (int i = 0; i < lanes; ++i) {
            accumulate(acc, p0 + i, samples[i]);
            localRays += samples[i].rays;
          }
        }
      }
    totalRays += localRays;
  };
  const int available = threads > 0 ? threads : availableCores();
  const int workers = std::min(available, impl.height);
  std::vector<std::thread> helpers;
  for (int i = 1; i < workers; ++i) helpers.emplace_back(work);
  work();
  for (std::thread& helper : helpers) helper.join();

  acc.samples += count;
  if (rays) *rays = totalRays;
  return std::int64_t(impl.width) * impl.height * count;
}

}  // namespace lpvlab

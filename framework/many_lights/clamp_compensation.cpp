#include "framework/many_lights/clamp_compensation.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/many_lights/ray_scene.h"
#include "framework/reference/hemisphere_sampling.h"
#include "framework/reference/integrator.h"

namespace lpvlab {

glm::vec3 clampCompensationWeight(const glm::vec3& albedo, float cosX, float cosY, float distance,
                                  float clamp, float minDistance) {
  if (!(cosX > 0.0f && cosY > 0.0f)) return glm::vec3(0.0f);
  if (!(distance > minDistance)) return glm::vec3(1.0f);
  const glm::vec3 gfr = albedo * (cosX * cosY / (distance * distance * float(M_PI)));
  glm::vec3 weight;
  for (int c = 0; c < 3; ++c) weight[c] = gfr[c] > clamp ? 1.0f - clamp / gfr[c] : 0.0f;
  return weight;
}

namespace {

// A G-buffer texel as the compensation reads it.
struct Receiver {
  glm::vec3 position, normal, albedo;
};

void checkInputs(const HostImage& position, const HostImage& normal, const HostImage& albedo,
                 const ClampCompensationSettings& settings, const HostImage& indirect) {
  for (const HostImage* image : {&normal, &albedo, &indirect})
    if (image->width != position.width || image->height != position.height)
      throw Error("clamp compensation: the G-buffer and the output differ in size");
  if (!(settings.clamp > 0.0f) || !std::isfinite(settings.clamp))
    throw Error("clamp compensation: the clamp c must be positive and finite (it is " +
                std::to_string(settings.clamp) + "): without a clamp nothing is taken away");
  if (settings.samples < 1) throw Error("clamp compensation: samples must be at least 1");
  if (settings.maxScatterings < 2)
    throw Error("clamp compensation: at least two scatterings (light bounced once, then at the pixel)");
}

// Traces one row's compensation paths, kPacketWidth (pixel, sample) pairs at a time.
class RowCompensator {
public:
  RowCompensator(const Integrator& integrator, const RayScene& scene,
                 const ClampCompensationSettings& settings, float minDistance)
      : integrator_(integrator), epsilon_(scene.embree().epsilon()), settings_(settings),
        minDistance_(minDistance) {
    shadows_.reserve(std::size_t(kPacketWidth) * (scene.lights().size() + 2));
  }

  // Adds what each receiver's paths found to its sum in `sums` (receivers[r]: pixel pixels[r]).
  void run(const std::vector<Receiver>& receivers, const std::vector<std::size_t>& pixels,
           std::vector<glm::dvec3>& sums, ClampCompensationCounts& counts) {
    const int samples = settings_.samples;
    const std::size_t pairs = receivers.size() * std::size_t(samples);
    for (std::size_t first = 0; first < pairs; first += kPacketWidth) {
      const int lanes = int(std::min<std::size_t>(kPacketWidth, pairs - first));
      for (int lane = 0; lane < lanes; ++lane) {
        const std::size_t pair = first + lane, r = pair / samples;
        start(receivers[r], pixels[r], int(pair % samples), lane);
        receiver_[lane] = &receivers[r];
      }
      const FirstHitWeight weight = [&](int lane, const SurfacePoint& y) {
        const Receiver& x = *receiver_[lane];
        const glm::vec3 d = y.position - x.position;
        const float distance = glm::length(d);
        const glm::vec3 toY = distance > 0.0f ? d / distance : starts_[lane].direction;
        const glm::vec3 w = clampCompensationWeight(x.albedo, glm::dot(x.normal, toY),
                                                    -glm::dot(y.shadingNormal, toY), distance,
                                                    settings_.clamp, minDistance_);
        if (w.r > 0.0f || w.g > 0.0f || w.b > 0.0f) counts.weightedPaths += 1.0;
        return w;
      };
      integrator_.trace(lanes, starts_, randoms_, samples_, shadows_, &weight);
      for (int lane = 0; lane < lanes; ++lane) {
        const std::size_t r = (first + lane) / samples;
        sums[r] += glm::dvec3(samples_[lane].indirect);
        counts.rays += samples_[lane].rays;
      }
      counts.paths += lanes;
    }
  }

private:
  // Lane `lane`'s path: a cosine-distributed direction about the receiver's normal, its ray cut at
  // r_c (beyond which W is zero), carrying the receiver's albedo (its BRDF cos / pdf).
  void start(const Receiver& x, std::size_t pixel, int sample, int lane) {
    randoms_[lane] = SampleRandom(settings_.seed, pixel, std::uint64_t(sample));
    const float u1 = randoms_[lane].uniform(), u2 = randoms_[lane].uniform();
    const glm::vec3 direction = cosineHemisphere(x.normal, u1, u2);
    const float largest = std::max({x.albedo.r, x.albedo.g, x.albedo.b});
    const float reach = std::max(std::sqrt(largest / (float(M_PI) * settings_.clamp)), minDistance_);
    starts_[lane] = {.origin = x.position + epsilon_ * x.normal,
                     .direction = direction,
                     .tNear = 0.0f,
                     .tFar = reach + 2.0f * epsilon_,
                     .throughput = x.albedo,
                     .brdfPdf = std::max(glm::dot(x.normal, direction), 0.0f) * float(1.0 / M_PI),
                     .scatterings = 1};
  }

  const Integrator& integrator_;
  float epsilon_;
  const ClampCompensationSettings& settings_;
  float minDistance_;
  PathStart starts_[kPacketWidth];
  SampleRandom randoms_[kPacketWidth];
  PathSample samples_[kPacketWidth];
  const Receiver* receiver_[kPacketWidth] = {};
  std::vector<ShadowQuery> shadows_;
};

}  // namespace

void compensateClamp(const HostImage& position, const HostImage& normal, const HostImage& albedo,
                     const RayScene& scene, const ClampCompensationSettings& settings,
                     HostImage& indirect, ClampCompensationCounts* counts) {
  checkInputs(position, normal, albedo, settings, indirect);
  TracerSettings tracer;
  tracer.maxBounces = settings.maxScatterings;
  tracer.emission = false;  // the walks start at punctual lights only
  const Integrator integrator(scene.embree(), scene.lightSampler(), nullptr, tracer);
  // The gather's own distance limit (vpl_gather.cpp): closer pairs it left out entirely.
  const float minDistance = std::max(settings.minDistance, 4.0f * scene.embree().epsilon());
  const int width = position.width, height = position.height;
  std::vector<ClampCompensationCounts> rows(static_cast<std::size_t>(height));

  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& range) {
    RowCompensator compensator(integrator, scene, settings, minDistance);
    std::vector<Receiver> receivers;
    std::vector<std::size_t> pixels;
    std::vector<glm::dvec3> sums;
    for (int y = range.begin(); y != range.end(); ++y) {
      receivers.clear();
      pixels.clear();
      for (int x = 0; x < width; ++x) {
        const std::size_t i = std::size_t(y) * width + x;
        if (!(position.texels[i].w > 0.0f)) continue;
        receivers.push_back({glm::vec3(position.texels[i]), glm::normalize(glm::vec3(normal.texels[i])),
                             glm::vec3(albedo.texels[i])});
        pixels.push_back(i);
      }
      sums.assign(receivers.size(), glm::dvec3(0.0));
      ClampCompensationCounts& row = rows[std::size_t(y)];
      compensator.run(receivers, pixels, sums, row);
      for (std::size_t r = 0; r < receivers.size(); ++r) {
        const glm::dvec3 mean = sums[r] / double(settings.samples);
        indirect.texels[pixels[r]] += glm::vec4(glm::vec3(mean), 0.0f);
        row.pixels += 1.0;
        const double added = mean.r + mean.g + mean.b;
        row.radiance += added;
        if (added > 0.0) row.compensatedPixels += 1.0;
      }
    }
  });
  if (!counts) return;
  *counts = {};
  for (const ClampCompensationCounts& row : rows) {
    counts->paths += row.paths;
    counts->weightedPaths += row.weightedPaths;
    counts->rays += row.rays;
    counts->pixels += row.pixels;
    counts->compensatedPixels += row.compensatedPixels;
    counts->radiance += row.radiance;
  }
}

}  // namespace lpvlab

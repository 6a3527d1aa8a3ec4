#pragma once
// The reference: a CPU path tracer on Embree 3 that renders the same Scene (geometry, Lambertian
// materials with base colour textures and alpha masks, emissive surfaces, point/spot/directional
// lights, an optional constant sky) from the same Camera as the LPV pipeline, into AOVs with the
// pipeline's names. Monte Carlo estimates come with the variance of their pixel means.
//
// Radiance AOVs (W/(m^2 sr)), all for the first surface seen through the pixel:
//   direct     emission seen directly + light arriving straight from a light (one scattering)
//   indirect   all light with two or more scatterings (all bounces, Russian roulette)
//   indirect1  exactly two scatterings: the light that reaches the first surface after exactly one
//              diffuse bounce elsewhere (what a single LPV pass approximates); indirect1 <= indirect
//   combined   direct + indirect
// A scattering is a change of direction at a surface vertex on the light's way to the camera
// (emission seen directly has none); framework/reference/integrator.h details the estimators.
// Pixel samples whose camera ray hits nothing are 0 in every AOV (the LPV pipeline's
// background), whatever the sky.
// Plus first-hit AOVs: albedo, normal (facing the camera), depth (view depth in m, 0 = no hit),
// averaged over the pixel's samples (anti-aliased), and <name>_variance for each radiance AOV:
// the estimated variance of the pixel's mean (sample variance / sample count).
//
// Determinism: sample s of pixel p draws its random numbers from a stream keyed by (seed, p, s)
// only, travels (for speed) in a ray packet with sample s of the same 16-pixel run of its row,
// and each pixel's samples are summed in order by one thread, so a given seed and sample count
// give bit-identical images whatever the thread count, and rendering n then m samples into an
// accumulator equals rendering n + m at once, on one instruction set. Another instruction set
// rounds some hit points differently (Embree's kernels differ, e.g. in fused multiply-adds), so a
// few paths take other turns: its images agree statistically, not bit for bit. The query width
// (TracerSettings::engine) changes no bit (tested).

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "framework/io/image.h"
#include "framework/reference/embree_device.h"
#include "framework/reference/random.h"
#include "framework/scene/scene.h"

namespace lpvlab {

struct TracerSettings {
  std::uint64_t seed = 1;
  int maxBounces = 64;          // hard cap on scattering events (Russian roulette ends most paths first)
  int rouletteAfter = 3;        // bounces before Russian roulette starts
  // How each path's random numbers are made (random.h). Sobol converges faster; the per-pixel
  // variance of its samples then overstates the mean's error (they are not independent), so the
  // relative-error estimate and budget are conservative with it.
  SampleSequence sampler = SampleSequence::Independent;
  glm::vec3 skyRadiance{0.0f};  // constant radiance from every unblocked direction; 0: no sky
  // false: emissive surfaces light nothing, neither seen nor sampled (the light the many-light
  // methods' walks carry, which start at punctual lights only: clamp_compensation.h). Their
  // surfaces still reflect. The reference always has it true.
  bool emission = true;
  // true ([reference] brdf = "phong"): each material's Phong lobe (Material::specular, shininess,
  // metallic; phong_brdf.h) beside its Lambertian albedo; false: Lambertian only, the lobes ignored.
  bool glossy = false;
  // Embree's instruction set and query width. They change no expectation, only speed and the
  // rounding of hit points (so bit-identical images need the same instruction set).
  RayEngineSettings engine;
};

// Per-pixel running sums: enough to resume, to add samples, and to produce means and variances.
struct Accumulator {
  int width = 0, height = 0;
  std::int64_t samples = 0;     // per pixel
  // Per pixel, per radiance AOV (direct, indirect, indirect1, combined) RGB: sum and sum of squares.
  std::vector<double> sum, sumSquares;
  // Per pixel: albedo (3), normal (3), depth (1) sums.
  std::vector<double> firstHit;

  // Layout: pixel p's values start at p * kRadianceValues in sum and sumSquares (AOV-major, then
  // RGB) and at p * kFirstHitValues in firstHit; pixels are row-major, top row first.
  static constexpr int kRadianceAovs = 4;
  static constexpr int kRadianceValues = 3 * kRadianceAovs;
  static constexpr int kFirstHitValues = 7;
  static constexpr const char* kRadianceNames[kRadianceAovs] = {"direct", "indirect", "indirect1",
                                                                "combined"};

  Accumulator() = default;
  // Zero sums for a width x height image; throws an Error unless both are at least 1.
  Accumulator(int width, int height);
  // Means, and variances of the means, as named AOVs (see the top of this file), in the order
  // direct, indirect, indirect1, combined, albedo, normal, depth, then the four <name>_variance.
  // With fewer than 2 samples a variance is unknown and reported as +infinity.
  std::vector<NamedImage> images() const;
  // Mean over covered pixels (any sample hit a surface) of (standard error / max(mean, epsilon))
  // of `combined`'s luminance (Rec. 709 weights). The channels' covariance isn't kept, so the
  // luminance's standard error is bounded above by the weighted sum of the channels' (exact when
  // they are perfectly correlated). +infinity with fewer than 2 samples; 0 with no covered pixel.
  double meanRelativeError(double epsilon = 1e-3) const;
};

class PathTracer {
public:
  // Builds the Embree scene from its own copy of `scene`. Throws an Error for what it cannot
  // render: no triangles, width or height below 1, a non-finite or degenerate camera, settings
  // out of range, malformed meshes, materials or lights.
  PathTracer(const Scene& scene, const Camera& camera, int width, int height,
             const TracerSettings& settings);
  ~PathTracer();
  PathTracer(const PathTracer&) = delete;
  PathTracer& operator=(const PathTracer&) = delete;

  // Adds samples [acc.samples, acc.samples + count) to every pixel, on `threads` threads
  // (0: all cores), and advances acc.samples. Throws an Error when acc's size isn't the tracer's
  // or count is negative. Returns the number of paths traced (= pixels * count)
  // and writes the number of rays (camera, continuation, shadow) to `rays` if given.
  std::int64_t render(Accumulator& acc, int count, int threads, std::int64_t* rays = nullptr) const;

  // The instruction set Embree runs ("auto" resolved) and its query width (0 resolved).
  const std::string& isa() const;
  int packetWidth() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lpvlab

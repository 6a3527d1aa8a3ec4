// The temporal error's noise correction (framework/metrics/temporal.h) on real path-traced
// references: two references of one static frame with different seeds differ only by their
// Monte Carlo noise, so a method that does not change between the frames has a noise-corrected
// temporal error consistent with zero, while the uncorrected one is far from it.

#include <gtest/gtest.h>

#include "framework/metrics/temporal.h"
#include "framework/reference/path_tracer.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {
namespace {

std::vector<NamedImage> renderBox(const Scene& scene, std::uint64_t seed) {
  TracerSettings settings;
  settings.seed = seed;
  PathTracer tracer(scene, scene.cameras.front(), 64, 64, settings);
  Accumulator acc(64, 64);
  tracer.render(acc, 64, 2);
  return acc.images();
}

TEST(TemporalNoise, TwoReferencesOfOneStaticFrameHaveATemporalErrorConsistentWithZero) {
  const Scene scene = makeCornellBox();
  const std::vector<NamedImage> a = renderBox(scene, 1), b = renderBox(scene, 2);
  const Image& depth = findAov(b, "depth");
  Image mask(64, 64, 1);
  for (std::size_t p = 0; p < mask.pixels.size(); ++p) mask.pixels[p] = depth.pixels[p] > 0.0f;
  // The method's light: any fixed image (here the first reference's own), the same in both
  // frames.
  const Image& method = findAov(a, "indirect");
  for (const char* aov : {"indirect", "direct"}) {
    SCOPED_TRACE(aov);
    const std::string variance = std::string(aov) + "_variance";
    const TemporalError error = temporalError(
        method, method,
        {findAov(b, aov), findAov(a, aov), &findAov(b, variance), &findAov(a, variance)},
        Reprojection::identity(64, 64), &mask);
    EXPECT_LT(std::abs(error.meanSquare), 4.0 * error.meanSquareStandardError)
        << error.toJson().dump();
    EXPECT_GT(error.rawMeanSquare, 5.0 * error.meanSquareStandardError) << error.toJson().dump();
  }
}

}  // namespace
}  // namespace lpvlab

// The light walks of instant radiosity with `sampler = "sobol"` (framework/many_lights/light_paths.h):
// walk i is point i of one Owen-scrambled Sobol sequence. On the built-in Cornell box, the
// first-hit VPLs' total reflected flux (what one-bounce gathering spreads) estimated with 256
// walks, over 16 seeds:
//   - unbiased: the seeds' mean is within 4 standard errors of a 65536-walk independent estimate;
//   - less noisy than independent walks: the spread over the seeds is below 0.7 of theirs (the
//     emitted directions, the walks' first two dimensions, are stratified).

#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "framework/many_lights/light_paths.h"
#include "framework/many_lights/ray_scene.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {
namespace {

double totalFlux(const RayScene& scene, int walks, SampleSequence sampler, std::uint64_t seed) {
  LightPathSettings settings;
  settings.paths = walks;
  settings.firstHitsOnly = true;
  settings.sampler = sampler;
  settings.seed = seed;
  double sum = 0.0;
  for (const Vpl& vpl : traceLightPaths(scene, settings)) sum += double(vpl.flux.r + vpl.flux.g + vpl.flux.b);
  return sum;
}

TEST(LightPathSampler, SobolWalksAreUnbiasedAndLessNoisy) {
  const RayScene scene(makeCornellBox());
  const double expected = totalFlux(scene, 65536, SampleSequence::Independent, 1000);
  ASSERT_GT(expected, 0.0);
  const auto spread = [&](SampleSequence sampler, double& mean) {
    std::vector<double> values;
    for (std::uint64_t seed = 1; seed <= 16; ++seed) values.push_back(totalFlux(scene, 256, sampler, seed));
    mean = 0.0;
    for (double v : values) mean += v / double(values.size());
    double squares = 0.0;
    for (double v : values) squares += (v - mean) * (v - mean);
    return std::sqrt(squares / double(values.size() - 1));
  };
  double sobolMean = 0.0, independentMean = 0.0;
  const double sobol = spread(SampleSequence::Sobol, sobolMean);
  const double independent = spread(SampleSequence::Independent, independentMean);
  std::cout << "first-hit VPL flux, 256 walks over 16 seeds: sobol " << sobolMean << " +- " << sobol
            << ", independent " << independentMean << " +- " << independent << "; 65536 walks "
            << expected << "\n";
  // 4 standard errors of the 16 seeds' mean (sd / sqrt(16)), plus the expectation's own noise.
  EXPECT_LT(std::abs(sobolMean - expected), 4.0 * sobol / std::sqrt(16.0) + 1e-3 * expected);
  EXPECT_LT(std::abs(independentMean - expected), 4.0 * independent / std::sqrt(16.0) + 1e-3 * expected);
  EXPECT_LT(sobol, 0.7 * independent);
}

}  // namespace
}  // namespace lpvlab

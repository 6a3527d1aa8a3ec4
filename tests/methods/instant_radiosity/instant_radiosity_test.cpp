// Instant radiosity (variants/methods/instant_radiosity) against the path tracer: unclamped, with
// exact visibility, it is an unbiased estimate of the reference's indirect light (its one-bounce
// mode of `indirect1`), so its variance falls as 1/walks and the mean of independent runs
// passes a per-pixel z-test at a Sidak-corrected level. On the plates scene (method_test_support.h),
// where G is bounded and the estimate's variance finite. Then the clamp's bookkeeping.

#include <cmath>
#include <iostream>

#include "framework/core/error.h"
#include "framework/reference/statistical_compare.h"
#include "method_test_support.h"

namespace lpvlab {
namespace {

constexpr int kWidth = 48, kHeight = 36;

std::vector<std::string> irOverrides(int paths, int seed, bool oneBounce) {
  return {"output.width=" + std::to_string(kWidth), "output.height=" + std::to_string(kHeight),
          "indirect.method=instant_radiosity", "indirect.light_paths=" + std::to_string(paths),
          "indirect.seed=" + std::to_string(seed), std::string("indirect.one_bounce=") + (oneBounce ? "true" : "false")};
}

// The reference of the plates scene at the test's size, once per binary.
const std::vector<NamedImage>& platesReference() {
  static const std::vector<NamedImage> images = [] {
    TracerSettings settings;
    settings.seed = 7;
    const PathTracer tracer(test::platesScene(), test::platesCamera(), kWidth, kHeight, settings);
    Accumulator acc(kWidth, kHeight);
    tracer.render(acc, 2048, 0);
    return acc.images();
  }();
  return images;
}

// The mean over the kept pixels' channels of the runs' variance about their own mean: the
// estimator's variance, free of the reference's noise.
double meanVariance(const std::vector<Image>& runs, const std::vector<bool>& keep) {
  const test::MeanImage mean = test::meanOf(runs);
  double sum = 0.0;
  int values = 0;
  for (std::size_t p = 0; p < keep.size(); ++p)
    for (int c = 0; c < 3 && keep[p]; ++c)
      sum += mean.varianceOfMean.pixels[p * 3 + c] * double(runs.size()), ++values;
  return sum / values;
}

void convergesToTheReference(bool oneBounce) {
  const std::string aov = oneBounce ? "indirect1" : "indirect";
  const Scene scene = test::platesScene();
  const Camera camera = test::platesCamera();
  const Image& reference = findAov(platesReference(), aov);
  const Image& referenceVariance = findAov(platesReference(), aov + "_variance");

  constexpr int kRuns = 48, kFewPaths = 64, kManyPaths = 256;
  std::vector<Image> few, many;
  std::vector<bool> keep;
  for (int seed = 1; seed <= kRuns; ++seed) {
    few.push_back(test::runMethod(irOverrides(kFewPaths, seed, oneBounce), &scene, &camera).indirect());
    const test::MethodRun run = test::runMethod(irOverrides(kManyPaths, 100 + seed, oneBounce), &scene, &camera);
    if (keep.empty()) keep = test::awayFromEdges(run.aovs);
    many.push_back(run.indirect());
  }
  // Four times the walks: a quarter of the variance, the Monte Carlo rate (the walks are
  // independent, so the variance is exactly sigma^2 / walks; the figure measures it).
  const double fewVariance = meanVariance(few, keep), manyVariance = meanVariance(many, keep);
  const double ratio = fewVariance / manyVariance;
  std::cout << aov << ": mean variance of a run, " << kFewPaths << " walks " << fewVariance << ", "
            << kManyPaths << " walks " << manyVariance << ": ratio " << ratio
            << " (4 at the Monte Carlo rate)\n";
  EXPECT_GT(ratio, 2.5);
  EXPECT_LT(ratio, 6.4);

  // The mean of the runs with many walks against the reference, pixel by pixel.
  const test::MeanImage mean = test::meanOf(many);
  const ComparisonResult z = compareImages(mean.mean, test::onlyWhere(mean.varianceOfMean, keep),
                                           reference, referenceVariance, 0.01, 1e-4);
  std::cout << aov << ": " << z.tests << " values tested, " << z.rejected << " rejected at |z| > "
            << z.threshold << " (max |z| " << z.maxAbsZ << ", mean z " << z.meanZ << ")\n";
  EXPECT_GT(z.tests, 1000);
  EXPECT_EQ(z.rejected, 0);
  // And over the whole image: the runs' image means scatter about the reference's.
  const test::ImageMeans means = test::imageMeans(many, reference, keep);
  std::cout << aov << ": image mean " << means.runs << " +- " << means.standardError
            << ", reference " << means.target << "\n";
  EXPECT_LT(std::abs(means.runs - means.target), 4.0 * means.standardError + 1e-3 * means.target);
}

TEST(InstantRadiosity, ConvergesToThePathTracersIndirectLightAtTheMonteCarloRate) {
  convergesToTheReference(false);
}

TEST(InstantRadiosity, OneBounceModeConvergesToTheOneBounceReference) {
  convergesToTheReference(true);
}

// The clamp in the built-in Cornell box, whose corners make G f_r large: the energy removed is
// exactly what the unclamped image has more, and a c above the largest G f_r removes nothing.
TEST(InstantRadiosity, TheClampRemovesExactlyTheEnergyItReports) {
  const std::vector<std::string> base = {"output.width=64", "output.height=64",
                                         "indirect.method=instant_radiosity",
                                         "indirect.light_paths=64"};
  const auto with = [&](const std::string& extra) {
    std::vector<std::string> overrides = base;
    overrides.push_back(extra);
    return test::runMethod(overrides);
  };
  const test::MethodRun free = with("indirect.clamp=0");
  const double largest = free.statistics["clamp"]["largest_g_fr"].get<double>();
  ASSERT_GT(largest, 0.0);
  EXPECT_EQ(free.statistics["clamp"]["removed_radiance_sum"].get<double>(), 0.0);

  const auto imageSum = [](const Image& image) {
    double sum = 0.0;
    for (float v : image.pixels) sum += v;
    return sum;
  };
  for (const double fraction : {0.01, 0.1, 0.5}) {
    const test::MethodRun clamped = with("indirect.clamp=" + std::to_string(largest * fraction));
    const double removed = clamped.statistics["clamp"]["removed_radiance_sum"].get<double>();
    const double lost = imageSum(free.indirect()) - imageSum(clamped.indirect());
    std::cout << "c = " << fraction << " of the largest G f_r (" << largest << "): removed "
              << removed << ", the image lost " << lost << " ("
              << clamped.statistics["clamp"]["removed_fraction"].get<double>() * 100 << "%)\n";
    EXPECT_GT(removed, 0.0);
    EXPECT_NEAR(lost, removed, 1e-5 * imageSum(free.indirect()));
    for (std::size_t i = 0; i < free.indirect().pixels.size(); ++i)
      ASSERT_LE(clamped.indirect().pixels[i], free.indirect().pixels[i] * (1.0f + 1e-6f));
  }
  // Just above the largest G f_r: nothing removed, the image bit for bit the unclamped one.
  const test::MethodRun above = with("indirect.clamp=" + std::to_string(largest * 1.0001));
  EXPECT_EQ(above.statistics["clamp"]["removed_radiance_sum"].get<double>(), 0.0);
  EXPECT_EQ(above.indirect().pixels, free.indirect().pixels);
}

// The clamp compensation (framework/many_lights/clamp_compensation.h) on the plates scene, with
// c = 0.15 where the largest G f_r is about 2.5: the clamped runs' mean is low, beyond their noise
// (the check can fail), and the compensated runs' mean passes the same per-pixel z-test as the
// unclamped estimator.
TEST(InstantRadiosity, ClampCompensationGivesTheClampedLightBackWithoutBias) {
  const Scene scene = test::platesScene();
  const Camera camera = test::platesCamera();
  const Image& reference = findAov(platesReference(), "indirect1");
  const Image& referenceVariance = findAov(platesReference(), "indirect1_variance");
  constexpr int kRuns = 48, kPaths = 256;
  const auto runs = [&](const std::vector<std::string>& extra, int firstSeed, std::vector<bool>& keep) {
    std::vector<Image> images;
    for (int seed = firstSeed; seed < firstSeed + kRuns; ++seed) {
      std::vector<std::string> overrides = irOverrides(kPaths, seed, true);
      overrides.insert(overrides.end(), extra.begin(), extra.end());
      const test::MethodRun run = test::runMethod(overrides, &scene, &camera);
      if (keep.empty()) keep = test::awayFromEdges(run.aovs);
      images.push_back(run.indirect());
    }
    return images;
  };
  std::vector<bool> keep;
  const std::vector<Image> clamped = runs({"indirect.clamp=0.15"}, 1, keep);
  const std::vector<Image> compensated =
      runs({"indirect.clamp=0.15", "indirect.clamp_compensation=true"}, 1, keep);
  const std::vector<Image> unclamped = runs({}, 1, keep);

  const test::ImageMeans low = test::imageMeans(clamped, reference, keep);
  std::cout << "clamped: image mean " << low.runs << " +- " << low.standardError << ", reference "
            << low.target << "\n";
  EXPECT_LT(low.runs, low.target - 4.0 * low.standardError);

  const test::MeanImage mean = test::meanOf(compensated);
  const ComparisonResult z = compareImages(mean.mean, test::onlyWhere(mean.varianceOfMean, keep),
                                           reference, referenceVariance, 0.01, 1e-4);
  const test::ImageMeans back = test::imageMeans(compensated, reference, keep);
  std::cout << "compensated: " << z.tests << " values tested, " << z.rejected << " rejected (max |z| "
            << z.maxAbsZ << "); image mean " << back.runs << " +- " << back.standardError << "\n";
  EXPECT_GT(z.tests, 1000);
  EXPECT_EQ(z.rejected, 0);
  EXPECT_LT(std::abs(back.runs - back.target), 4.0 * back.standardError + 1e-3 * back.target);

  // The price: the compensation's few paths per pixel add their own noise. Here, where unclamped
  // VPLs have a bounded G and little noise, more than the clamp saves (docs/methods.md has the
  // scenes with corners, where the balance turns).
  const double clampedVariance = meanVariance(clamped, keep);
  const double compensatedVariance = meanVariance(compensated, keep);
  const double unclampedVariance = meanVariance(unclamped, keep);
  std::cout << "mean variance of a run: clamped " << clampedVariance << ", compensated "
            << compensatedVariance << ", unclamped " << unclampedVariance << "\n";
  EXPECT_LT(clampedVariance, unclampedVariance);
  EXPECT_GT(compensatedVariance, clampedVariance);
}

// Compensation without a clamp has nothing to add: an error naming the key, not a silent no-op.
TEST(InstantRadiosity, ClampCompensationWithoutAClampIsAnError) {
  try {
    test::runMethod({"output.width=16", "output.height=16", "indirect.method=instant_radiosity",
                     "indirect.clamp_compensation=true"});
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("clamp_compensation"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lpvlab

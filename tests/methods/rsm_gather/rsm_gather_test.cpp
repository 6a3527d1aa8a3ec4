// RSM gathering (variants/methods/rsm_gather): with every texel it is one-bounce instant
// radiosity without visibility whose VPLs are the RSM's texels; its patterns estimate the sum
// over a disk of texels without bias whatever their density.

#include <iostream>

#include "framework/reference/statistical_compare.h"
#include "method_test_support.h"

namespace lpvlab {
namespace {

constexpr int kWidth = 48, kHeight = 36;

std::vector<std::string> sized(std::vector<std::string> overrides) {
  overrides.push_back("output.width=" + std::to_string(kWidth));
  overrides.push_back("output.height=" + std::to_string(kHeight));
  return overrides;
}

// The RSMs' texels against light paths' first hits: two samplings of the light that first lands
// on the surfaces, the one a regular grid over each cube face, the other random walks.
TEST(RsmGather, EveryTexelEqualsOneBounceInstantRadiosityWithoutVisibility) {
  const Scene scene = test::platesScene();
  const Camera camera = test::platesCamera();
  const test::MethodRun rsm = test::runMethod(
      sized({"indirect.method=rsm_gather", "indirect.pattern=all", "light_maps.rsm_resolution=128"}),
      &scene, &camera);
  std::vector<Image> walks;
  for (int seed = 1; seed <= 48; ++seed)
    walks.push_back(test::runMethod(sized({"indirect.method=instant_radiosity",
                                           "indirect.one_bounce=true", "indirect.visibility=none",
                                           "indirect.light_paths=256",
                                           "indirect.seed=" + std::to_string(seed)}),
                                    &scene, &camera)
                        .indirect());
  const test::MeanImage ir = test::meanOf(walks);
  const std::vector<bool> keep = test::awayFromEdges(rsm.aovs);
  // The RSM's grid is exact up to its quadrature error, well below the walks' noise at 128^2
  // texels a face: compared as exact values, with 0.5 % of room for that error.
  const ComparisonResult z = compareToExact(ir.mean, test::onlyWhere(ir.varianceOfMean, keep),
                                            rsm.indirect(), 0.01, 5e-3);
  std::cout << "RSM (" << rsm.statistics["vpls"] << " texels) against one-bounce IR without "
            << "visibility (48 x 256 walks): " << z.tests << " values, " << z.rejected
            << " rejected at |z| > " << z.threshold << ", max |z| " << z.maxAbsZ << ", mean z "
            << z.meanZ << "\n";
  EXPECT_GT(z.tests, 1000);
  EXPECT_EQ(z.rejected, 0);
  const test::ImageMeans means = test::imageMeans(walks, rsm.indirect(), keep);
  std::cout << "image mean: walks " << means.runs << " +- " << means.standardError << ", texels "
            << means.target << "\n";
  EXPECT_LT(std::abs(means.runs - means.target), 4.0 * means.standardError + 5e-3 * means.target);
}

// The importance pattern (denser near the projection, weighted by 1 / density) and the uniform
// one estimate the same disk's sum: over many patterns their means agree.
TEST(RsmGather, ImportanceAndUniformPatternsAgreeOnAverage) {
  const Scene scene = test::platesScene();
  const Camera camera = test::platesCamera();
  std::vector<Image> importance, uniform;
  for (int seed = 1; seed <= 32; ++seed) {
    const std::string s = "indirect.seed=" + std::to_string(seed);
    const std::vector<std::string> common = {"indirect.method=rsm_gather", "indirect.samples=64",
                                             "indirect.radius=0.3", "light_maps.rsm_resolution=64", s};
    std::vector<std::string> a = common, b = common;
    a.push_back("indirect.pattern=importance");
    b.push_back("indirect.pattern=uniform");
    importance.push_back(test::runMethod(sized(a), &scene, &camera).indirect());
    uniform.push_back(test::runMethod(sized(b), &scene, &camera).indirect());
  }
  const test::MeanImage i = test::meanOf(importance), u = test::meanOf(uniform);
  const ComparisonResult z = compareImages(i.mean, i.varianceOfMean, u.mean, u.varianceOfMean);
  std::cout << "importance vs uniform patterns (32 seeds each): " << z.tests << " values, "
            << z.rejected << " rejected at |z| > " << z.threshold << ", mean z " << z.meanZ << "\n";
  EXPECT_GT(z.tests, 1000);
  EXPECT_EQ(z.rejected, 0);
}

}  // namespace
}  // namespace lpvlab

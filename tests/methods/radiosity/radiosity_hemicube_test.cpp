// Form factors by the hemicube on GL (seed 004, 3.5-3.7) against Howell's closed forms: the error
// falls as the hemicube's resolution grows and the patches shrink (the hemicube samples from each
// patch's centroid, so the area-to-area factor is approached as patches get small).
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "framework/radiosity/hemicube.h"
#include "framework/radiosity/ray_form_factors.h"
#include "gl/gl_test_context.h"
#include "radiosity/radiosity_scenes.h"

namespace lpvlab {
namespace {

FormFactorRows hemicubeRows(const PatchMesh& mesh, int resolution, float sceneSize, bool frontOnly,
                            HemicubePlacement placement = HemicubePlacement::Centroid, std::uint64_t seed = 1) {
  test::glTestContext();
  ShaderCompiler shaders;
  HemicubeFormFactors estimator(shaders, mesh, resolution, sceneSize, placement, seed);
  FormFactorRows rows(mesh.sides());
  std::vector<std::uint32_t> sides;
  for (std::uint32_t s = 0; s < mesh.sides(); ++s)
    if (!frontOnly || s % 2 == 0) sides.push_back(s);
  estimator.computeRows(sides, rows);
  return rows;
}

double hemicubeFormFactor(const Scene& scene, float patchSize, int resolution) {
  const PatchMesh mesh = meshPatches(scene, patchSize, 100000);
  return test::meshFormFactor(mesh, hemicubeRows(mesh, resolution, 2.0f, true), 0, 1);
}

TEST(HemicubeFormFactors, ParallelSquaresConvergeToTheClosedForm) {
  const Scene scene = test::parallelRectangles(1.0f, 1.0f, 1.0f);
  const double exact = test::parallelRectanglesFormFactor(1, 1, 1);
  const double coarse = std::abs(hemicubeFormFactor(scene, 1.5f, 16) - exact);
  const double fine = std::abs(hemicubeFormFactor(scene, 0.2f, 128) - exact);
  std::printf("parallel squares: F = %.5f, hemicube error %.2e (16 px, 1 patch per triangle) -> %.2e "
              "(128 px, 0.2 m patches)\n", exact, coarse, fine);
  EXPECT_LT(fine, coarse);
  EXPECT_LT(fine, 0.005 * exact);  // stated: within 0.5% at 128 px and 0.2 m patches
}

TEST(HemicubeFormFactors, PerpendicularRectanglesConvergeToTheClosedForm) {
  const Scene scene = test::perpendicularRectangles(1.0f, 1.0f, 1.0f);
  const double exact = test::perpendicularRectanglesFormFactor(1, 1, 1);
  const double coarse = std::abs(hemicubeFormFactor(scene, 1.5f, 16) - exact);
  const double fine = std::abs(hemicubeFormFactor(scene, 0.1f, 128) - exact);
  std::printf("perpendicular squares: F = %.5f, hemicube error %.2e -> %.2e\n", exact, coarse, fine);
  EXPECT_LT(fine, coarse);
  // Patches along the common edge see the other rectangle at grazing angles from their centroid:
  // the centroid rule converges there at first order in the patch size. Stated: within 2%.
  EXPECT_LT(fine, 0.02 * exact);
}

// Where the hemicubes stand (hemicube.h). Perpendicular unit squares at 0.5 m patches: a jittered
// hemicube stands at a uniformly random point of its patch, so over independent seeds its factor
// is an unbiased estimate of the area-to-area one (Howell's closed form), up to the 1/128^2 of
// the item buffer; the centroid (one-point) and vertex (three-point) rules are printed beside it.
// Near the common edge the point factor varies fast, so one jittered run is noisier than the
// centroid's rule is biased here: jittering trades the rule's bias for noise.
TEST(HemicubeFormFactors, JitteredHemicubesAreUnbiased) {
  const Scene scene = test::perpendicularRectangles(1.0f, 1.0f, 1.0f);
  const double exact = test::perpendicularRectanglesFormFactor(1, 1, 1);
  const PatchMesh mesh = meshPatches(scene, 0.5f, 100000);
  const auto factor = [&](HemicubePlacement placement, std::uint64_t seed) {
    return test::meshFormFactor(mesh, hemicubeRows(mesh, 128, 2.0f, true, placement, seed), 0, 1);
  };
  const double centroid = factor(HemicubePlacement::Centroid, 1);
  const double vertices = factor(HemicubePlacement::Vertices, 1);
  constexpr int kSeeds = 48;
  double sum = 0.0, squares = 0.0;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const double f = factor(HemicubePlacement::Jittered, std::uint64_t(seed));
    sum += f, squares += f * f;
  }
  const double mean = sum / kSeeds;
  const double spread = std::sqrt((squares / kSeeds - mean * mean) * kSeeds / (kSeeds - 1));
  const double error = spread / std::sqrt(double(kSeeds));
  std::printf("perpendicular squares at 0.5 m patches, 128 px: F = %.5f; centroid %.5f (%+.2f%%), "
              "vertices %.5f (%+.2f%%), jittered: one run +- %.2f%%, the mean of %d %.5f +- %.5f (%+.2f%%)\n",
              exact, centroid, 100 * (centroid / exact - 1), vertices, 100 * (vertices / exact - 1),
              100 * spread / exact, kSeeds, mean, error, 100 * (mean / exact - 1));
  EXPECT_LT(std::abs(mean - exact), 4.0 * error + 1e-4);
  EXPECT_GT(spread, 0.0);  // the seeds do move the hemicubes
}

TEST(HemicubeFormFactors, EveryPlacementsRowsInAClosedBoxSumToOne) {
  const Scene scene = test::closedCube(glm::vec3(0.5f), glm::vec3(0.0f));
  const PatchMesh mesh = meshPatches(scene, 0.5f, 100000);
  for (const HemicubePlacement placement : {HemicubePlacement::Vertices, HemicubePlacement::Jittered}) {
    const FormFactorRows rows = hemicubeRows(mesh, 32, 1.0f, false, placement, 3);
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
      EXPECT_NEAR(rows.rowSum(2 * p), 1.0, 1e-5) << p;
      EXPECT_EQ(rows.row(2 * p + 1).size(), 0u);
      for (const FormFactor& f : rows.row(2 * p)) EXPECT_NE(f.side / 2, p) << "a patch saw itself";
    }
  }
}

TEST(HemicubeFormFactors, RowsInsideAClosedBoxSumToOneAndTheOutsideSeesNothing) {
  const Scene scene = test::closedCube(glm::vec3(0.5f), glm::vec3(0.0f));
  const PatchMesh mesh = meshPatches(scene, 0.5f, 100000);
  const FormFactorRows rows = hemicubeRows(mesh, 32, 1.0f, false);
  for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
    EXPECT_NEAR(rows.rowSum(2 * p), 1.0, 1e-5) << p;  // the maps are normalised; no pixel sees out
    EXPECT_EQ(rows.row(2 * p + 1).size(), 0u);
    for (const FormFactor& f : rows.row(2 * p)) {
      EXPECT_EQ(f.side % 2, 0u) << "an inner side saw an outer one";
      EXPECT_NE(f.side / 2, p) << "a patch saw itself";
    }
  }
}

TEST(HemicubeFormFactors, AgreesWithRayCastingWithinTheRaysStandardErrorAndTheHemicubesBias) {
  // Per row, on the open box: both estimate the same F_ij of a small patch (the hemicube from the
  // centroid, rays from the whole patch); their row sums differ by less than the rays' standard
  // error plus the hemicube's aliasing at 128 px.
  Scene scene = test::closedCube(glm::vec3(0.5f), glm::vec3(0.0f));
  scene.meshes.pop_back();
  const PatchMesh mesh = meshPatches(scene, 0.2f, 100000);
  const FormFactorRows cube = hemicubeRows(mesh, 128, 1.0f, true);
  const PatchRayScene rayScene(scene, mesh);
  FormFactorRows rays(mesh.sides());
  std::vector<std::uint32_t> fronts;
  for (std::uint32_t s = 0; s < mesh.sides(); s += 2) fronts.push_back(s);
  const int n = 4096;
  RayFormFactors(mesh, rayScene, n, 5).computeRows(fronts, rays);
  double worstZ = 0.0;
  for (std::uint32_t s : fronts) {
    const double f = rays.rowSum(s), se = std::sqrt(std::max(f * (1 - f), 1e-12) / n);
    worstZ = std::max(worstZ, std::abs(cube.rowSum(s) - f) / (se + 0.01 * f));
  }
  EXPECT_LT(worstZ, 5.0);
}

}  // namespace
}  // namespace lpvlab

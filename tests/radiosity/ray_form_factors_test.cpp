// Ray-cast form factors (Embree) against Howell's closed forms, within their standard error, and
// rows summing to 1 inside a closed box.
#include <cmath>

#include <gtest/gtest.h>

#include "framework/radiosity/ray_form_factors.h"
#include "radiosity_scenes.h"

namespace lpvlab {
namespace {

// The ray estimate of F from mesh 0 to mesh 1 and its standard error: each front side's F_i is a
// binomial proportion over `rays` rays, and the mesh's F is their area-weighted mean.
struct Estimate {
  double value, standardError;
};

Estimate rayEstimate(const Scene& scene, float patchSize, int rays) {
  const PatchMesh mesh = meshPatches(scene, patchSize, 100000);
  const PatchRayScene rayScene(scene, mesh);
  RayFormFactors estimator(mesh, rayScene, rays, 7);
  FormFactorRows rows(mesh.sides());
  std::vector<std::uint32_t> sides;
  for (std::size_t p = 0; p < mesh.patches.size(); ++p)
    if (mesh.patches[p].mesh == 0) sides.push_back(std::uint32_t(2 * p));
  estimator.computeRows(sides, rows);
  double variance = 0.0, area = 0.0;
  for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
    if (mesh.patches[p].mesh != 0) continue;
    double f = 0.0;
    for (const FormFactor& e : rows.row(2 * p)) f += e.value;
    const double a = mesh.patches[p].area;
    variance += a * a * f * (1.0 - f) / rays;
    area += a;
  }
  return {test::meshFormFactor(mesh, rows, 0, 1), std::sqrt(variance) / area};
}

TEST(RayFormFactors, ParallelRectanglesMatchTheClosedFormWithinTheirStandardError) {
  for (const auto& [a, b, c] : {std::array<float, 3>{1, 1, 1}, {2, 1, 0.5f}, {0.5f, 0.5f, 2}}) {
    const double exact = test::parallelRectanglesFormFactor(a, b, c);
    const Estimate e = rayEstimate(test::parallelRectangles(a, b, c), 0.25f, 4096);
    // |z| < 4: a false alarm once in 15000 runs; the estimate is unbiased, so a wrong geometry
    // term (a missing cosine, the wrong side) lands hundreds of standard errors away.
    EXPECT_LT(std::abs(e.value - exact), 4.0 * e.standardError)
        << a << " x " << b << " at " << c << ": " << e.value << " vs " << exact << " (se " << e.standardError << ")";
    EXPECT_LT(e.standardError, 0.05 * exact);  // the test can see a 20% error
  }
}

TEST(RayFormFactors, PerpendicularRectanglesMatchTheClosedFormWithinTheirStandardError) {
  EXPECT_NEAR(test::perpendicularRectanglesFormFactor(1, 1, 1), 0.20004, 1e-4);  // the catalogue's value
  for (const auto& [l, w, h] : {std::array<float, 3>{1, 1, 1}, {1, 0.5f, 2}, {2, 1, 0.25f}}) {
    const double exact = test::perpendicularRectanglesFormFactor(l, w, h);
    const Estimate e = rayEstimate(test::perpendicularRectangles(l, w, h), 0.2f, 4096);
    EXPECT_LT(std::abs(e.value - exact), 4.0 * e.standardError)
        << l << " x " << w << " / " << h << ": " << e.value << " vs " << exact << " (se " << e.standardError << ")";
  }
}

TEST(RayFormFactors, RowsInsideAClosedBoxSumToOneAndTheOutsideSeesNothing) {
  const Scene scene = test::closedCube(glm::vec3(0.5f), glm::vec3(0.0f));
  const PatchMesh mesh = meshPatches(scene, 0.5f, 100000);
  const PatchRayScene rayScene(scene, mesh);
  RayFormFactors estimator(mesh, rayScene, 256, 3);
  FormFactorRows rows(mesh.sides());
  std::vector<std::uint32_t> all;
  for (std::uint32_t s = 0; s < mesh.sides(); ++s) all.push_back(s);
  estimator.computeRows(all, rows);
  for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
    EXPECT_NEAR(rows.rowSum(2 * p), 1.0, 1e-6);  // every ray from inside hits inside
    EXPECT_EQ(rows.row(2 * p + 1).size(), 0u);    // the outside sees nothing
    for (const FormFactor& f : rows.row(2 * p)) EXPECT_EQ(f.side % 2, 0u) << "an inner side saw an outer one";
  }
  // Same seed, same rows; thread count is irrelevant (each side draws its own stream).
  FormFactorRows again(mesh.sides());
  RayFormFactors(mesh, rayScene, 256, 3).computeRows(all, again);
  for (std::size_t s = 0; s < mesh.sides(); ++s) {
    ASSERT_EQ(rows.row(s).size(), again.row(s).size());
    for (std::size_t k = 0; k < rows.row(s).size(); ++k) EXPECT_EQ(rows.row(s)[k].value, again.row(s)[k].value);
  }
}

}  // namespace
}  // namespace lpvlab

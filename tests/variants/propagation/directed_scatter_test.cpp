// Directed propagation's two methods (shaders/propagation/directed_gather.comp and
// directed_scatter.comp), as standard propagation's two are tested (gather_scatter_test.cpp):
// gather and scatter give the same grid (current and accumulated) within float rounding, on
// random grids with normals, at SH orders 1-3, with and without the release (region normals, or
// sparse random normals read literally), with and without a random GV switched on from the
// second iteration. (The CPU backend, whose kernel gathers, refuses "scatter" by name: a row of
// tests/cli/bad_inputs_test.cpp.)

#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "directed_model.h"
#include "error_support.h"
#include "propagation_rig.h"

namespace lpvlab {
namespace {

using namespace test;

struct Result {
  Grid current, accumulated;
};

struct Case {
  int order = 1;
  bool release = true;
  bool withGv = false;
};

Result run(const std::string& method, const Case& c, const glm::ivec3& res, const Grid& current,
           const Grid& accumulated, const std::vector<float>& normals, const Grid& gv) {
  toml::table table = iterationsTable(3, method);
  if (!c.release) table.insert("release", false);
  PropagationRig rig("directed", res, table, c.order, c.withGv);
  rig.load(current, accumulated);
  rig.loadNormals(normals);
  if (c.withGv) rig.loadGv(gv, 1);
  rig.propagate();
  return {rig.current(), rig.accumulated()};
}

void gatherEqualsScatter(const Case& c) {
  const glm::ivec3 res{7, 6, 5};  // not multiples of the 4^3 work group, nor a cube
  std::mt19937 random(2000 + 10 * c.order + 2 * int(c.release) + int(c.withGv));
  const std::size_t n = std::size_t(3) * (c.order + 1) * (c.order + 1) * res.x * res.y * res.z;
  const Grid current = randomFloats(n, random, -1.0f, 1.0f);
  const Grid accumulated = randomFloats(n, random, -1.0f, 1.0f);
  std::vector<float> normals = regionNormals(res, random, 0.4f);
  if (!c.release) {  // sparse random normals, every one of them reprojecting
    std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
    std::fill(normals.begin(), normals.end(), 0.0f);
    for (std::size_t i = 0; i < normals.size(); i += 4)
      if (uniform(random) > 0.6f) {
        for (int k = 0; k < 3; ++k) normals[i + k] = uniform(random);
        normals[i + 3] = 1.0f;
      }
  }
  const Grid gv = randomGv(res + 1, random);
  const Result gather = run("gather", c, res, current, accumulated, normals, gv);
  const Result scatter = run("scatter", c, res, current, accumulated, normals, gv);
  ASSERT_GT(maxDifference(gather.current, current), 0.1) << "propagation changed nothing";
  const double tolerance = 2e-5 * maxAbs(gather.accumulated);
  EXPECT_LE(maxDifference(gather.current, scatter.current), tolerance);
  EXPECT_LE(maxDifference(gather.accumulated, scatter.accumulated), tolerance);
  // The normals made a difference (so the comparison covered the reprojection).
  PropagationRig standard("standard", res, iterationsTable(3), c.order, c.withGv);
  standard.load(current, accumulated);
  if (c.withGv) standard.loadGv(gv, 1);
  standard.propagate();
  EXPECT_GT(maxDifference(standard.current(), gather.current), 0.05 * maxAbs(gather.current));
}

class DirectedScatter : public ::testing::TestWithParam<std::tuple<int, bool, bool>> {};

TEST_P(DirectedScatter, GivesTheGathersGrid) {
  const auto [order, release, withGv] = GetParam();
  gatherEqualsScatter({.order = order, .release = release, .withGv = withGv});
}

INSTANTIATE_TEST_SUITE_P(OrdersReleaseAndGv, DirectedScatter,
                         ::testing::Combine(::testing::Values(1, 2, 3), ::testing::Bool(),
                                            ::testing::Bool()));

}  // namespace
}  // namespace lpvlab

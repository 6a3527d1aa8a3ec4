// The tiled layout of the gathers on GL ([propagation] gpu_kernel = "tiled": tiled_walk.glsl in
// shaders/propagation/standard_gather_tiled.comp and directed_gather_tiled.comp), on llvmpipe:
//   a. it gives the simple kernel's grid (current and accumulated) at SH orders 1-3, without and
//      with a random GV, with bounces, over several iterations, on grids that cut tiles and
//      z-spans part way (several tiles along x and y, several spans along z) and on the extremes
//      (one cell, one row, one column); for directed propagation too, with region normals in
//      some cells (dilation and release at work);
//   b. it gives the CPU kernel's grid (double precision) at orders 1-3, to the tolerance the
//      simple kernel is held to;
//   c. it is refused with scattering, naming the key; an unknown layout is refused;
//   d. its work model reads fewer source bytes than the simple kernel's (and no fewer than one
//      read of each cell).

#include <random>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "cpu_comparison.h"
#include "error_support.h"
#include "framework/math/solid_angle.h"
#include "directed_model.h"
#include "propagation_rig.h"
#include "variants/propagation/standard_cpu.h"
#include "variants/propagation/tiled_walk.h"

namespace lpvlab {
namespace {

using test::Grid;
using test::maxAbs;
using test::maxDifference;
using test::maxRelativeDifference;

struct TiledCase {
  glm::ivec3 resolution;
  int order = 1;
  bool withGv = false;
  bool bounces = false;
  int iterations = 3;
  std::string strategy = "standard";
};

struct Result {
  Grid current, accumulated;
};

toml::table table(const TiledCase& s, const std::string& layout) {
  toml::table t = test::iterationsTable(s.iterations);
  t.insert("gpu_kernel", layout);
  if (s.bounces) t.insert("bounces", true);
  return t;
}

Result run(const TiledCase& s, const std::string& layout, std::uint32_t seed) {
  test::PropagationRig rig(s.strategy, s.resolution, table(s, layout), s.order, s.withGv);
  std::mt19937 random(seed);
  if (s.strategy == "directed") rig.loadNormals(test::regionNormals(s.resolution, random, 0.3f));
  const Grid current = test::randomFloats(rig.floatsPerGrid(), random, -1.0f, 1.0f);
  const Grid accumulated = test::randomFloats(rig.floatsPerGrid(), random, -1.0f, 1.0f);
  rig.load(current, accumulated);
  if (s.withGv) rig.loadGv(test::randomGv(s.resolution + 1, random), 1);
  if (s.bounces) rig.loadAlbedo(test::randomAlbedo(s.resolution + 1, random));
  rig.propagate();
  return {rig.current(), rig.accumulated()};
}

// The two layouts call the same transfer in the same order: equal up to the compiler's freedom
// (fused multiply-adds), far below the 2e-5 the other kernel comparisons allow.
void sameAsSimple(const TiledCase& s) {
  const std::uint32_t seed = 100 * s.order + 10 * s.withGv + s.bounces;
  const Result simple = run(s, "simple", seed);
  const Result tiled = run(s, "tiled", seed);
  const std::string what = s.strategy + ", order " + std::to_string(s.order) +
                           (s.withGv ? ", GV" : "") + (s.bounces ? ", bounces" : "");
  // Relative to the largest value; a grid of zeros (one cell: no neighbours) must stay zero.
  EXPECT_LE(maxDifference(tiled.current, simple.current), 1e-6 * maxAbs(simple.current)) << what;
  EXPECT_LE(maxDifference(tiled.accumulated, simple.accumulated),
            1e-6 * maxAbs(simple.accumulated)) << what;
}

// 37 x 9 x 19: two tiles and a part along x (32 or 16 wide), three along y (4 high), three
// z-spans of 8 with a part; every edge case of the halo is on some tile.
const glm::ivec3 kCutGrid{37, 9, 19};

TEST(StandardTiled, SameGridAsTheSimpleKernelAtEveryOrder) {
  for (int order = 1; order <= 3; ++order) sameAsSimple({kCutGrid, order});
}

TEST(StandardTiled, SameGridAsTheSimpleKernelWithTheGvAndBounces) {
  sameAsSimple({kCutGrid, 1, true, false});
  sameAsSimple({kCutGrid, 3, true, false});
  for (int order = 1; order <= 3; ++order) sameAsSimple({kCutGrid, order, true, true});
}

TEST(DirectedTiled, SameGridAsTheSimpleKernelAtEveryOrderWithAndWithoutTheGv) {
  sameAsSimple({.resolution = kCutGrid, .order = 1, .withGv = true, .strategy = "directed"});
  sameAsSimple({.resolution = kCutGrid, .order = 2, .strategy = "directed"});
  sameAsSimple({.resolution = kCutGrid, .order = 3, .withGv = true, .strategy = "directed"});
}

TEST(DirectedTiled, SameGridOnTheExtremes) {
  for (const glm::ivec3& res : {glm::ivec3(1, 1, 1), glm::ivec3(40, 1, 1), glm::ivec3(1, 1, 40),
                                glm::ivec3(33, 5, 8)})
    sameAsSimple({.resolution = res, .order = 1, .withGv = true, .iterations = 2,
                  .strategy = "directed"});
}

TEST(StandardTiled, SameGridOnTheExtremes) {
  for (const glm::ivec3& res : {glm::ivec3(1, 1, 1), glm::ivec3(40, 1, 1), glm::ivec3(1, 1, 40),
                                glm::ivec3(1, 9, 1), glm::ivec3(33, 5, 8), glm::ivec3(32, 4, 9)})
    for (int order : {1, 3}) sameAsSimple({res, order, true, false, 2});
}

TEST(StandardTiled, SameGridAsTheCpuKernelAtEveryOrder) {
  const double far = cubeFaceSolidAngles().farFace, side = cubeFaceSolidAngles().sideFace;
  for (int order = 1; order <= 3; ++order) {
    const TiledCase s{kCutGrid, order};
    test::PropagationRig rig("standard", s.resolution, table(s, "tiled"), order);
    std::mt19937 random(7 + order);
    const Grid injected = test::randomFloats(rig.floatsPerGrid(), random);
    rig.load(injected);
    rig.propagate();
    ASSERT_GT(maxDifference(rig.current(), injected), 0.1) << "propagation changed nothing";
    const StandardFaceTable<double> faces = makeStandardFaceTable<double>(order, far, side);
    std::vector<double> current(injected.begin(), injected.end()), next(current.size()),
        accumulated = current;
    for (int i = 0; i < s.iterations; ++i) {
      standardGatherCpu(faces, s.resolution, current.data(), next.data(), accumulated.data());
      std::swap(current, next);
    }
    EXPECT_LT(maxRelativeDifference(current, rig.current()), 2e-5) << "order " << order;
    EXPECT_LT(maxRelativeDifference(accumulated, rig.accumulated()), 2e-5) << "order " << order;
  }
}

TEST(DirectedTiled, UnknownLayoutIsRefusedNamingTheKey) {
  test::glTestContext();
  toml::table t = test::iterationsTable(2);
  t.insert("gpu_kernel", "blocked");
  Params params(t, "test.toml", "propagation");
  const std::string error =
      test::errorOf([&] { Registry<PropagationStrategy>::instance().create(params, "directed"); });
  EXPECT_TRUE(test::contains(error, "gpu_kernel")) << error;
}

TEST(StandardTiled, RefusedWithScatteringAndUnknownLayouts) {
  test::glTestContext();
  for (const auto& [method, layout, key] :
       {std::tuple<std::string, std::string, std::string>{"scatter", "tiled", "gpu_kernel"},
        {"gather", "blocked", "gpu_kernel"}}) {
    toml::table t = test::iterationsTable(2, method);
    t.insert("gpu_kernel", layout);
    Params params(t, "test.toml", "propagation");
    const std::string error =
        test::errorOf([&] { Registry<PropagationStrategy>::instance().create(params, "standard"); });
    EXPECT_TRUE(test::contains(error, key)) << error;
    EXPECT_TRUE(test::contains(error, "test.toml")) << error;
  }
}

TEST(StandardTiled, WorkModelReadsEachCellOnceAndAHalo) {
  for (int order = 1; order <= 3; ++order) {
    const int n = (order + 1) * (order + 1);
    const double reads = tiledWalkSourceReads(n);
    EXPECT_GT(reads, 1.0) << order;
    EXPECT_LT(reads, 2.0) << order;  // tiles of at least 16 x 4 and z-spans of 8
    EXPECT_NEAR(tiledWalkBytesSaved(n), 4.0 * 3 * n * (6.0 - reads), 1e-9);
  }
}

}  // namespace
}  // namespace lpvlab

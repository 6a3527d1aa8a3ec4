// Standard propagation's two methods (shaders/propagation/standard_gather.comp and
// standard_scatter.comp) and its geometry-volume attenuation:
//   a. gather and scatter give the same grid (current and accumulated) within float rounding, on
//      random grids, at SH orders 1, 2 and 3, without and with a random GV, over several
//      iterations with the GV switched on from the second (firstOccludedIteration = 1);
//   b. one GPU step with a GV equals the double-precision C++ of the same shared GLSL
//      (standard_faces.glsl per face; for the GV the general trilinear lookup gvBlockingAt of
//      geometry_volume_lookup.glsl, which the kernels' gvBlockingOnFace must equal on the face),
//      for both methods;
//      with firstOccludedIteration = 1 a single step ignores the GV.

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "error_support.h"
#include "framework/math/solid_angle.h"
#include "propagation_rig.h"

namespace lpvlab {
namespace {

using test::Grid;
using test::maxAbs;
using test::maxDifference;
using test::randomFloats;
using test::randomGv;

struct Result {
  Grid current, accumulated;
};

Result run(const std::string& method, const glm::ivec3& res, int order, int iterations,
           const Grid& current, const Grid& accumulated, const Grid* gv,
           int firstOccluded) {
  test::PropagationRig rig("standard", res, test::iterationsTable(iterations, method), order,
                          gv != nullptr);
  rig.load(current, accumulated);
  if (gv) rig.loadGv(*gv, firstOccluded);
  rig.propagate();
  return {rig.current(), rig.accumulated()};
}

void gatherEqualsScatter(int order, bool withGv) {
  const glm::ivec3 res{7, 6, 5};  // not multiples of the 4^3 work group, nor a cube
  const int iterations = 3;
  std::mt19937 random(1000 + 10 * order + int(withGv));
  const std::size_t n = std::size_t(3) * (order + 1) * (order + 1) * res.x * res.y * res.z;
  const Grid current = randomFloats(n, random, -1.0f, 1.0f);
  const Grid accumulated = randomFloats(n, random, -1.0f, 1.0f);
  const Grid gv = randomGv(res + 1, random);
  const Grid* gvOrNull = withGv ? &gv : nullptr;
  const Result gather = run("gather", res, order, iterations, current, accumulated, gvOrNull, 1);
  const Result scatter = run("scatter", res, order, iterations, current, accumulated, gvOrNull, 1);
  ASSERT_GT(maxDifference(gather.current, current), 0.1) << "propagation changed nothing";
  const double tolerance = 2e-5 * maxAbs(gather.accumulated);
  EXPECT_LE(maxDifference(gather.current, scatter.current), tolerance);
  EXPECT_LE(maxDifference(gather.accumulated, scatter.accumulated), tolerance);
  if (withGv) {  // the GV made a difference (so the comparison covered it)
    const Result open = run("gather", res, order, iterations, current, accumulated, nullptr, 0);
    EXPECT_GT(maxDifference(open.current, gather.current), 0.05 * maxAbs(open.current));
  }
}

TEST(GatherScatter, SameGridOrder1) { gatherEqualsScatter(1, false); }
TEST(GatherScatter, SameGridOrder2) { gatherEqualsScatter(2, false); }
TEST(GatherScatter, SameGridOrder3) { gatherEqualsScatter(3, false); }
TEST(GatherScatter, SameGridOrder1WithGv) { gatherEqualsScatter(1, true); }
TEST(GatherScatter, SameGridOrder2WithGv) { gatherEqualsScatter(2, true); }
TEST(GatherScatter, SameGridOrder3WithGv) { gatherEqualsScatter(3, true); }

// ---- b. against the double-precision C++ ------------------------------------------------------

// One order-1 step by gathering in double precision: per target cell, per neighbour, per face,
// the shared functions the kernels call; the GV (when `occluded`) read through the shared lookup.
Grid referenceStep(const glm::ivec3& res, const Grid& current, const Grid* gv) {
  const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  const int cells = shared::cellCount(res);
  if (gv) shared::gvBlocking.assign(gv->begin(), gv->end());
  Grid next(current.size(), 0.0f);
  for (int z = 0; z < res.z; ++z)
    for (int y = 0; y < res.y; ++y)
      for (int x = 0; x < res.x; ++x) {
        const glm::ivec3 cell{x, y, z};
        for (int channel = 0; channel < 3; ++channel) {
          glm::dvec4 sum(0.0);
          for (int axis = 0; axis < 3; ++axis)
            for (int sign = -1; sign <= 1; sign += 2) {
              glm::ivec3 offset(0);
              offset[axis] = sign;
              const glm::ivec3 from = cell + offset;
              if (!shared::cellInside(from, res)) continue;
              glm::dvec4 c;
              for (int k = 0; k < 4; ++k)
                c[k] = current[shared::coefficientIndex(channel, k, 4, shared::cellIndex(from, res), cells)];
              const glm::dvec3 d(-offset);
              for (int f = 0; f < shared::STANDARD_FACES; ++f) {
                const glm::dvec3 w = shared::standardFaceDirection(d, f);
                double transmittance = 1.0;
                if (gv) {
                  const glm::dvec3 crossing =
                      shared::standardFaceCrossing(glm::dvec3(from) + 0.5, d, f);
                  transmittance = shared::gvTransmittance(
                      shared::gvBlockingAt(crossing, res + glm::ivec3(1)), w);
                }
                sum += shared::propagateThroughOccludedFace(
                    c, w, shared::standardFaceNormal(d, f),
                    shared::standardFaceSolidAngle(f, angles.farFace, angles.sideFace),
                    transmittance);
              }
            }
          for (int k = 0; k < 4; ++k)
            next[shared::coefficientIndex(channel, k, 4, shared::cellIndex(cell, res), cells)] =
                float(sum[k]);
        }
      }
  return next;
}

void stepMatchesReference(const std::string& method) {
  const glm::ivec3 res{6, 5, 4};
  std::mt19937 random(777);
  const std::size_t n = std::size_t(3) * 4 * res.x * res.y * res.z;
  const Grid current = randomFloats(n, random, -1.0f, 1.0f);
  const Grid accumulated = randomFloats(n, random, -1.0f, 1.0f);
  const Grid gv = randomGv(glm::ivec3(7, 6, 5), random);

  const Result gpu = run(method, res, 1, 1, current, accumulated, &gv, 0);
  const Grid expected = referenceStep(res, current, &gv);
  const Grid open = referenceStep(res, current, nullptr);
  const double tolerance = 1e-5 * maxAbs(expected);
  EXPECT_LE(maxDifference(gpu.current, expected), tolerance);
  Grid expectedAccumulated = accumulated;
  for (std::size_t i = 0; i < n; ++i) expectedAccumulated[i] += expected[i];
  EXPECT_LE(maxDifference(gpu.accumulated, expectedAccumulated), 2 * tolerance);
  // The GV mattered: without it the reference differs (so the comparison can fail).
  EXPECT_GT(maxDifference(expected, open), 0.05 * maxAbs(open));

  // From iteration 1 on only: the first step is the open one.
  const Result skipped = run(method, res, 1, 1, current, accumulated, &gv, 1);
  EXPECT_LE(maxDifference(skipped.current, open), 1e-5 * maxAbs(open));
}

TEST(GatherScatter, GatherStepWithGvMatchesTheSharedCpp) { stepMatchesReference("gather"); }
TEST(GatherScatter, ScatterStepWithGvMatchesTheSharedCpp) { stepMatchesReference("scatter"); }

TEST(GatherScatter, UnknownMethodIsAnErrorNamingTheKey) {
  test::glTestContext();
  toml::table table;
  table.insert("method", "diffuse");
  Params params(table, "test.toml", "propagation");
  EXPECT_TRUE(test::contains(
      test::errorOf([&] { Registry<PropagationStrategy>::instance().create(params, "standard"); }),
      "method"));
}

}  // namespace
}  // namespace lpvlab

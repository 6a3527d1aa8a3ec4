// The oracles' VPL subsets (framework/explain/rsm_vpl_subset.h): every texel when the budget
// allows; otherwise one VPL per block carrying the block's flux, whose gather at a receiver is,
// on average over draws, the gather of every texel (a statistical test over independent draws).

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/explain/rsm_vpl_subset.h"
#include "framework/many_lights/vpl_gather.h"

namespace lpvlab {
namespace {

// Two views of side x side texels: a lit floor (y = 0) of varying colour and flux, with holes.
struct Rsm {
  HostImage position, normal, flux;
  RsmImages images() const { return {&position, &normal, &flux}; }
};

Rsm floorRsm(int side) {
  Rsm r;
  for (HostImage* image : {&r.position, &r.normal, &r.flux}) *image = HostImage{side, side, 2, {}};
  for (int view = 0; view < 2; ++view)
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) {
        const bool covered = (x * 7 + y * 3 + view) % 11 != 0;
        const glm::vec3 p(float(x) / side + view, 0.0f, float(y) / side);
        r.position.texels.push_back(glm::vec4(p, covered ? 1.0f : 0.0f));
        r.normal.texels.push_back(glm::vec4(0, 1, 0, 0));
        const float f = covered ? 0.01f * (1.0f + float((x * 13 + y * 5) % 17)) : 0.0f;
        r.flux.texels.push_back(glm::vec4(f, 0.5f * f, 0.25f * f, covered ? 1.0f : 0.0f));
      }
  return r;
}

// What `vpls` give a receiver 0.7 m above the floor's middle, facing down (no visibility).
glm::dvec3 gatheredAt(const std::vector<Vpl>& vpls) {
  glm::dvec3 sum(0.0), removed(0.0);
  for (const Vpl& vpl : vpls) {
    glm::vec3 toVpl;
    float distance = 0.0f;
    const glm::vec3 gfr = vplGeometryTerm(glm::vec3(0.8f, 0.7f, 0.5f), glm::vec3(0, -1, 0), glm::vec3(1.0f),
                                          vpl, 1e-4f, toVpl, distance);
    addClamped(vpl.flux, gfr, 0.0f, sum, removed);
  }
  return sum;
}

TEST(RsmVplSubset, EveryCoveredTexelWhenTheBudgetAllows) {
  const Rsm rsm = floorRsm(16);
  const RsmVplSubset all = rsmVplSubset(rsm.images(), 2, 16, 1 << 20, 1, 0);
  EXPECT_EQ(all.blockSide, 1);
  std::size_t covered = 0;
  for (const glm::vec4& t : rsm.flux.texels) covered += t.w > 0.0f;
  EXPECT_EQ(all.coveredTexels, covered);
  EXPECT_EQ(all.vpls.size(), covered);
  // The same subset for another draw: no noise to estimate.
  const RsmVplSubset again = rsmVplSubset(rsm.images(), 2, 16, 1 << 20, 1, 1);
  ASSERT_EQ(again.vpls.size(), all.vpls.size());
  for (std::size_t i = 0; i < all.vpls.size(); ++i) EXPECT_EQ(again.vpls[i].position, all.vpls[i].position);
}

TEST(RsmVplSubset, EachBlockCarriesItsFluxAndTheGatherIsUnbiased) {
  const int side = 64;
  const Rsm rsm = floorRsm(side);
  const std::vector<Vpl> every = rsmVplSubset(rsm.images(), 2, side, 1 << 20, 1, 0).vpls;
  const glm::dvec3 exact = gatheredAt(every);
  double totalFlux = 0.0;
  for (const Vpl& vpl : every) totalFlux += vpl.flux.r + vpl.flux.g + vpl.flux.b;

  const std::size_t budget = 300;
  const int draws = 400;
  double sum = 0.0, sumSquares = 0.0;
  for (int draw = 0; draw < draws; ++draw) {
    const RsmVplSubset subset = rsmVplSubset(rsm.images(), 2, side, budget, 7, std::uint64_t(draw));
    EXPECT_LE(subset.vpls.size(), budget);
    EXPECT_GT(subset.blockSide, 1);
    double flux = 0.0;
    for (const Vpl& vpl : subset.vpls) flux += vpl.flux.r + vpl.flux.g + vpl.flux.b;
    EXPECT_NEAR(flux, totalFlux, 1e-4 * totalFlux);  // every draw: each block's whole flux
    const double red = gatheredAt(subset.vpls).r;
    sum += red;
    sumSquares += red * red;
  }
  const double mean = sum / draws;
  const double standardError = std::sqrt((sumSquares / draws - mean * mean) / (draws - 1));
  EXPECT_GT(standardError, 0.0);  // the draws differ
  EXPECT_LT(std::abs(mean - exact.r), 4.0 * standardError)
      << "mean " << mean << " exact " << exact.r << " standard error " << standardError;
}

TEST(RsmVplSubset, RefusesImagesOfTheWrongSizeAndANoBudget) {
  const Rsm rsm = floorRsm(8);
  EXPECT_THROW(rsmVplSubset(rsm.images(), 3, 8, 10, 1, 0), Error);
  EXPECT_THROW(rsmVplSubset(rsm.images(), 2, 8, 0, 1, 0), Error);
}

}  // namespace
}  // namespace lpvlab

// The error budget's bookkeeping (framework/explain/error_budget.h): its terms telescope to the
// total error, the brightness factors multiply to the total mean ratio, and the chain follows
// whether the method's grid blocks light.

#include <cmath>

#include <gtest/gtest.h>

#include "framework/explain/error_budget.h"

namespace lpvlab {
namespace {

Image pattern(int seed, float scale) {
  Image image(32, 32, 3);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = scale * (1.0f + 0.5f * std::sin(0.3f * x * (seed + 1) + 0.2f * y + c));
  return image;
}

double number(const nlohmann::json& value) { return value.get<double>(); }

TEST(ErrorBudget, TermsTelescopeToTheTotalAndFactorsMultiply) {
  Image mask(32, 32, 1);
  for (float& m : mask.pixels) m = 1.0f;
  mask.at(3, 4, 0) = 0.0f;
  const Image reference = pattern(0, 1.0f);
  ExplainImages images{pattern(1, 1.6f), pattern(2, 1.2f), pattern(3, 0.9f), pattern(4, 1.3f),
                       pattern(5, 1.05f), {}};
  for (const bool blocks : {false, true}) {
    const nlohmann::json budget = errorBudget(images, nullptr, reference, mask, blocks);
    double removed = 0.0, factor = 1.0;
    for (const nlohmann::json& term : budget["terms"]) {
      removed += number(term["block_nrmse_reduction"]);
      factor *= number(term["brightness_factor"]);
    }
    EXPECT_NEAR(removed, number(budget["total"]["block_nrmse"]), 1e-9);
    EXPECT_NEAR(factor, number(budget["total"]["mean_ratio"]), 1e-9);
    EXPECT_NEAR(number(budget["total"]["mean_ratio"]), 1.6, 0.05);
    EXPECT_EQ(budget["terms"].size(), blocks ? 3u : 4u);
    EXPECT_EQ(budget["chain"][1], blocks ? "grid_visible" : "grid");
    EXPECT_EQ(budget["terms"].back()["stage"], "injection");
    EXPECT_NEAR(number(budget["leakage_factor"]), 1.3 / 1.05, 1e-3);
  }
}

TEST(ErrorBudget, AnExactChainHasNoErrorLeft) {
  Image mask(32, 32, 1);
  for (float& m : mask.pixels) m = 1.0f;
  const Image reference = pattern(0, 1.0f);
  const ExplainImages images{reference, reference, reference, reference, reference, {}};
  const Image direct = pattern(7, 0.5f);
  Image combined = reference;
  for (std::size_t i = 0; i < combined.pixels.size(); ++i) combined.pixels[i] += direct.pixels[i];
  const nlohmann::json budget = errorBudget(images, &direct, combined, mask, false);
  for (const nlohmann::json& term : budget["terms"]) EXPECT_EQ(number(term["block_nrmse_reduction"]), 0.0);
  EXPECT_EQ(number(budget["total"]["block_nrmse"]), 0.0);
  EXPECT_DOUBLE_EQ(number(budget["total"]["mean_ratio"]), 1.0);
}

}  // namespace
}  // namespace lpvlab

namespace lpvlab {
namespace {

// Independent pixels of variance v (of their means): an 8 x 8 block's mean has variance v / 64,
// so a constant reference r has noise sqrt(v / 64) / r; a partly covered block counts its covered
// pixels only (v / n for n of them).
TEST(ErrorBudget, ReferenceNoiseIsTheBlockMeansStandardError) {
  const Image reference(16, 16, 3, 2.0f), variance(16, 16, 3, 0.64f);
  Image mask(16, 16, 1, 1.0f);
  EXPECT_NEAR(referenceNoiseBlockNrmse(reference, variance, mask), std::sqrt(0.64 / 64.0) / 2.0, 1e-9);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) mask.at(x, y, 0) = (x < 4 && y < 4) ? 1.0f : 0.0f;  // 16 of 64
  const double expected = std::sqrt((0.64 / 16.0 + 3.0 * 0.64 / 64.0) / 4.0) / 2.0;
  EXPECT_NEAR(referenceNoiseBlockNrmse(reference, variance, mask), expected, 1e-9);
}

}  // namespace
}  // namespace lpvlab

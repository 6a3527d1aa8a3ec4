// The tuner's choices (framework/tune/successive_halving.h): which candidates each rung keeps
// under either goal, which is chosen, and the Pareto front.

#include <gtest/gtest.h>

#include "framework/tune/successive_halving.h"

namespace lpvlab {
namespace {

const std::vector<RungResult> kResults = {
    {"a", 0.50, 10.0}, {"b", 0.30, 30.0}, {"c", 0.20, 50.0}, {"d", 0.40, 12.0},
    {"e", 0.10, 80.0}, {"f", 0.35, 29.0}, {"g", 0.60, 5.0}};

TEST(SuccessiveHalving, ABudgetKeepsTheMostAccurateWithinIt) {
  const TuneGoal goal{30.0, std::nullopt};
  // Within 30 ms: a, b, d, f, g; by error b (0.30), f (0.35), d, a, g; ceil(7 / 3) = 3 kept.
  EXPECT_EQ(promote(kResults, goal, 3), (std::vector<std::string>{"b", "f", "d"}));
  EXPECT_EQ(choose(kResults, goal)->id, "b");
  // Too tight for any: the fastest go on, none is chosen.
  const TuneGoal tight{1.0, std::nullopt};
  EXPECT_EQ(promote(kResults, tight, 3), (std::vector<std::string>{"g", "a", "d"}));
  EXPECT_FALSE(choose(kResults, tight).has_value());
}

TEST(SuccessiveHalving, AnErrorGoalKeepsTheFastestWithinIt) {
  const TuneGoal goal{std::nullopt, 0.35};
  // Within 0.35: b, c, e, f; by time f (29), b (30), c (50), e (80).
  EXPECT_EQ(promote(kResults, goal, 2), (std::vector<std::string>{"f", "b", "c", "e"}));
  EXPECT_EQ(choose(kResults, goal)->id, "f");
  const TuneGoal none{std::nullopt, 0.01};  // nothing so accurate: the most accurate go on
  EXPECT_EQ(promote(kResults, none, 7), (std::vector<std::string>{"e"}));
}

TEST(SuccessiveHalving, AtLeastOneGoesOn) {
  EXPECT_EQ(promote({{"x", 1.0, 1.0}}, TuneGoal{10.0, std::nullopt}, 100).size(), 1u);
}

TEST(SuccessiveHalving, TheParetoFrontIsWhatNothingBeats) {
  std::vector<std::string> ids;
  for (const RungResult& r : paretoFront(kResults)) ids.push_back(r.id);
  // g (5 ms, 0.60), a (10, 0.50), d (12, 0.40), f (29, 0.35), b (30, 0.30), c (50, 0.20), e (80, 0.10).
  EXPECT_EQ(ids, (std::vector<std::string>{"g", "a", "d", "f", "b", "c", "e"}));
  // A point both slower and worse than another is off it.
  std::vector<RungResult> more = kResults;
  more.push_back({"h", 0.45, 31.0});
  EXPECT_EQ(paretoFront(more).size(), kResults.size());
}

}  // namespace
}  // namespace lpvlab

// The [tune] table (framework/tune/tune_spec.h) and the candidates drawn from it
// (tune_space.h): values as asked, deterministic, the baseline first; every bad input an Error
// naming the file and the key.

#include <filesystem>
#include <fstream>
#include <set>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/tune/tune_space.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

std::string write(const test::TempDir& dir, const std::string& text) {
  const std::string path = dir.file("tune.toml");
  std::ofstream(path) << text;
  return path;
}

std::string errorOf(const std::string& tune) {
  test::TempDir dir;
  try {
    readTuneSpec(write(dir, tune), {}, std::nullopt, std::nullopt);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(TuneSpec, ReadsTheSpaceAndTheGoal) {
  test::TempDir dir;
  const TuneSpec spec = readTuneSpec(write(dir, R"(
[tune]
budget_ms = "baseline"
metric = "combined_vs_combined.rmse"
candidates = 5
rungs = [8, 32]
[tune.space]
"grid.resolution" = [16, 32]
"injection.shift" = { min = 0.0, max = 2.0, step = 0.5 }
[[tune.held_out]]
name = "other"
camera = { position = [0.2, 0.3, -0.5], look_at = [0.2, 0.3, 0.3] }
)"), {}, std::nullopt, std::nullopt);
  EXPECT_TRUE(spec.budgetIsBaseline);
  EXPECT_EQ(spec.pair, "combined_vs_combined");
  EXPECT_EQ(spec.metric, "rmse");
  EXPECT_EQ(spec.rungs, (std::vector<int>{8, 32}));
  ASSERT_EQ(spec.space.size(), 2u);
  EXPECT_EQ(spec.views.size(), 1u);  // the file's own
  EXPECT_EQ(spec.heldOut.size(), 1u);
  // The command line's goal replaces the file's.
  const TuneSpec byError = readTuneSpec(dir.file("tune.toml"), {}, std::nullopt, 0.3);
  EXPECT_FALSE(byError.budgetMs.has_value());
  EXPECT_EQ(*byError.maxError, 0.3);
}

TEST(TuneSpec, BadInputNamesTheKey) {
  const std::string space = "[tune.space]\n\"grid.resolution\" = [16]\n";
  EXPECT_NE(errorOf("[tune]\nbudget_ms = 5.0\nbogus = 1\n" + space).find("tune.bogus"), std::string::npos);
  EXPECT_NE(errorOf("[tune]\n" + space).find("exactly one goal"), std::string::npos);
  EXPECT_NE(errorOf("[tune]\nbudget_ms = 5.0\nerror = 0.1\n" + space).find("exactly one goal"), std::string::npos);
  EXPECT_NE(errorOf("[tune]\nbudget_ms = 5.0\n").find("tune.space"), std::string::npos);
  EXPECT_NE(errorOf("[tune]\nbudget_ms = -5.0\n" + space).find("tune.budget_ms"), std::string::npos);
  EXPECT_NE(errorOf("[tune]\nbudget_ms = 5.0\nrungs = [64, 16]\n" + space).find("tune.rungs"), std::string::npos);
  EXPECT_NE(errorOf("[tune]\nbudget_ms = 5.0\n[tune.space]\n\"a.b\" = { min = 2.0, max = 1.0 }\n").find("a.b"),
            std::string::npos);
  EXPECT_NE(errorOf("[tune]\nbudget_ms = 5.0\n[tune.space]\nresolution = [1]\n").find("<table>.<name>"),
            std::string::npos);
  EXPECT_NE(errorOf("[tune]\nbudget_ms = 5.0\nmetric = \"rmse\"\n" + space).find("tune.metric"), std::string::npos);
  EXPECT_NE(errorOf("[grid]\nresolution = 8\n").find("no [tune] table"), std::string::npos);
  EXPECT_NE(errorOf("[tune]\nbudget_ms = 5.0\ntime = \"gpu\"\n" + space).find("tune.time"), std::string::npos);
  // A GPU names whose estimate the time is: only with time = "gpu-estimate".
  EXPECT_NE(errorOf("[tune]\nbudget_ms = 5.0\ngpu = \"h100_sxm\"\n" + space).find("tune.gpu"), std::string::npos);
  EXPECT_NE(errorOf("[tune]\nbudget_ms = 5.0\ntime = \"gpu-estimate\"\ngpu = 3\n" + space).find("tune.gpu"),
            std::string::npos);
}

// [tune.fit]: lpvlab fit's [fit] table, on the tune's views, checked as the fit checks its own.
TEST(TuneSpec, TheFitTableIsAFitTableOnTheTunedViews) {
  const std::string head = "[tune]\nbudget_ms = 5.0\n[tune.space]\n\"grid.resolution\" = [16]\n";
  const std::string parameters =
      "[tune.fit]\nparameters = [{ key = \"propagation.far_face_solid_angle\", lower = 0.0, upper = 2.0 }]\n";
  test::TempDir dir;
  const TuneSpec spec = readTuneSpec(write(dir, head + parameters +
                                                    "[[tune.views]]\nname = \"a\"\n"
                                                    "[[tune.views]]\nname = \"b\"\n"
                                                    "camera = { position = [0.3, 0.3, -0.5], look_at = [0.3, 0.3, 0.3] }\n"),
                                     {}, std::nullopt, std::nullopt);
  ASSERT_TRUE(spec.fit.has_value());
  const toml::array* views = (*spec.fit)["views"].as_array();
  ASSERT_NE(views, nullptr);
  ASSERT_EQ(views->size(), 2u);
  EXPECT_EQ((*views)[1].as_table()->at("name").value_or(std::string()), "b");
  EXPECT_FALSE(readTuneSpec(write(dir, head), {}, std::nullopt, std::nullopt).fit.has_value());
  // Its own views, a key the composition does not have, and a bad setting: named.
  EXPECT_NE(errorOf(head + parameters + "[[tune.fit.views]]\nname = \"x\"\n").find("tune.fit.views"),
            std::string::npos);
  const std::string unknown =
      errorOf(head + "[tune.fit]\nparameters = [{ key = \"propagation.bogus\", lower = 0.0, upper = 1.0 }]\n");
  EXPECT_NE(unknown.find("tune.fit"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("bogus"), std::string::npos) << unknown;
  EXPECT_NE(errorOf(head + parameters + "max_iterations = -1\n").find("tune.fit"), std::string::npos);
}

TEST(TuneSpace, TheBaselineFirstThenDistinctDeterministicDraws) {
  TuneSpec spec;
  spec.candidates = 20;
  spec.space = {{"grid.resolution", {"8", "16", "32"}},
                {"injection.shift", {}, 0.0, 2.0, 0.25},
                {"propagation.iterations", {}, 4.0, 64.0, 0.0, true, true}};
  const std::vector<TuneCandidate> a = drawCandidates(spec), b = drawCandidates(spec);
  ASSERT_EQ(a.size(), 21u);
  EXPECT_EQ(a.front().id, "baseline");
  EXPECT_TRUE(a.front().overrides.empty());
  std::set<std::string> ids;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].id, b[i].id);
    ids.insert(a[i].id);
  }
  EXPECT_EQ(ids.size(), a.size());
  for (std::size_t i = 1; i < a.size(); ++i) {
    ASSERT_EQ(a[i].overrides.size(), 3u);
    const double shift = std::stod(a[i].overrides[1].substr(a[i].overrides[1].find('=') + 1));
    EXPECT_DOUBLE_EQ(shift / 0.25, std::round(shift / 0.25)) << a[i].overrides[1];  // on its step
    const std::string iterations = a[i].overrides[2].substr(a[i].overrides[2].find('=') + 1);
    EXPECT_EQ(iterations.find('.'), std::string::npos) << "an integer range gave " << iterations;
    EXPECT_GE(std::stoi(iterations), 4);
    EXPECT_LE(std::stoi(iterations), 64);
  }
}

TEST(TuneSpace, ASmallSpaceOfChoicesIsEnumeratedWhole) {
  TuneSpec spec;
  spec.candidates = 100;
  spec.space = {{"grid.resolution", {"8", "16"}}, {"occlusion.type", {"\"none\"", "\"geometry_volume\""}}};
  EXPECT_EQ(drawCandidates(spec).size(), 1u + 4u);
}

TEST(TuneSpace, RangeValuesFollowLogStepAndInteger) {
  TuneDimension d{"a.b", {}, 1.0, 100.0, 0.0, true, false};
  EXPECT_DOUBLE_EQ(std::stod(rangeValue(d, 0.5)), 10.0);
  EXPECT_NE(rangeValue(d, 0.5).find('.'), std::string::npos);  // a float stays a TOML float
  TuneDimension stepped{"a.b", {}, 0.0, 1.0, 0.3};
  EXPECT_DOUBLE_EQ(std::stod(rangeValue(stepped, 0.99)), 0.9);  // 1.0 is off the step grid: clamped
  TuneDimension integer{"a.b", {}, 2.0, 9.0, 0.0, false, true};
  EXPECT_EQ(rangeValue(integer, 0.999), "9");
  EXPECT_EQ(rangeValue(integer, 0.0), "2");
}

}  // namespace
}  // namespace lpvlab

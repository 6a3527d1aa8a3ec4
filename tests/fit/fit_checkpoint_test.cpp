// Resuming a fit (framework/fit/fit_checkpoint.h):
//   - the fit's key changes with what decides the solve's path (a bound, a fitted view, the
//     residual) and not with what does not (max_iterations, held-out views);
//   - progress written and read back is the same, to the last bit of every double; another fit's
//     progress is not resumed; a damaged file is an error naming it;
//   - a fit stopped after 2 iterations and resumed with max_iterations 5 starts where it stopped
//     (its first rendering is at the last iteration's x), keeps the first iterations' log,
//     numbers on from 3, stops at 5, and ends no worse than where it stopped; its termination
//     message counts the whole fit's iterations;
//   - a fit stopped just after a rejected step and resumed takes the uninterrupted fit's steps.

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "error_support.h"
#include "fit/fit_test_support.h"
#include "fit/synthetic_views.h"
#include "framework/fit/fit_checkpoint.h"
#include "gl/gl_test_context.h"

namespace lpvlab {
namespace {

const char* kDamping =
    "parameters = [{ key = \"propagation.damping\", initial = 1.0, lower = 0.5, upper = 1.5 }]\n";

FitSpec specWith(const test::FitFiles& files, const std::string& extra) {
  return test::smallFitSpec(files, 16, std::string(kDamping) + extra);
}

TEST(FitCheckpoint, TheKeyFollowsWhatDecidesTheSolve) {
  test::FitFiles files("checkpoint-key");
  const std::string key = fitKey(specWith(files, ""));
  EXPECT_EQ(fitKey(specWith(files, "")), key);
  EXPECT_EQ(fitKey(specWith(files, "max_iterations = 50\n")), key) << "may be raised to go on";
  EXPECT_EQ(fitKey(test::smallFitSpec(files, 16, std::string(kDamping) +
                                                     "[[fit.held_out]]\nname = \"other\"\n")), key);
  EXPECT_NE(fitKey(specWith(files, "residual = \"log\"\n")), key);
  EXPECT_NE(fitKey(test::smallFitSpec(files, 16,
      "parameters = [{ key = \"propagation.damping\", initial = 1.0, lower = 0.6, upper = 1.5 }]\n")), key);
  EXPECT_NE(fitKey(test::smallFitSpec(files, 8, kDamping)), key) << "the experiment changed";
}

TEST(FitCheckpoint, ProgressRoundTripsAndBelongsToOneFit) {
  test::FitFiles files("checkpoint-file");
  const std::string path = (files.dir() / "fit.progress.json").string();
  FitProgress progress;
  progress.renders = 17;
  progress.seconds = 12.25;
  progress.log.push_back({0, 0.1 / 3.0, 1e-3, 0.0, true, 0.5, {1.0, 0.1}});
  progress.log.push_back({1, 0.02, 2e-4, 0.3333333333333333, false, 1.7, {0.9, 1.0 / 7.0}});
  writeFitProgress(path, "abc", progress);

  const std::optional<FitProgress> read = readFitProgress(path, "abc");
  ASSERT_TRUE(read);
  EXPECT_EQ(read->renders, 17);
  EXPECT_EQ(read->seconds, 12.25);
  ASSERT_EQ(read->log.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(read->log[i].iteration, progress.log[i].iteration);
    EXPECT_EQ(read->log[i].cost, progress.log[i].cost);
    EXPECT_EQ(read->log[i].successful, progress.log[i].successful);
    EXPECT_EQ(read->log[i].x, progress.log[i].x);
  }

  bool otherFit = false;
  EXPECT_FALSE(readFitProgress(path, "another", &otherFit));
  EXPECT_TRUE(otherFit);
  EXPECT_FALSE(readFitProgress((files.dir() / "none.json").string(), "abc", &otherFit));
  EXPECT_FALSE(otherFit);

  std::ofstream(path) << "{\"fit_key\": \"abc\", \"log\": [";
  const std::string error = test::errorOf([&] { readFitProgress(path, "abc"); });
  EXPECT_TRUE(test::contains(error, path)) << error;
  EXPECT_TRUE(test::contains(error, "delete it")) << error;
}

TEST(FitCheckpoint, AResumedFitGoesOnFromWhereItStopped) {
  test::glTestContext();
  test::FitFiles files("checkpoint-resume");
  const FitSpec first = specWith(files, "max_iterations = 2\n");
  const std::vector<FitView> views = test::syntheticViews(first, {0.8});
  FitEvaluator stopped(first, views);
  const FitResult part = runFit(stopped);
  ASSERT_EQ(part.log.back().iteration, 2);
  const FitProgress progress{part.log, part.renders, part.seconds};

  const FitSpec more = specWith(files, "max_iterations = 5\n");
  FitEvaluator resumed(more, views);
  const FitResult whole = runFit(resumed, {}, &progress);
  ASSERT_FALSE(resumed.evaluated().empty());
  EXPECT_EQ(resumed.evaluated().front(), part.log.back().x) << "the first rendering is where it stopped";
  ASSERT_GT(whole.log.size(), part.log.size());
  for (std::size_t i = 0; i < part.log.size(); ++i) {
    EXPECT_EQ(whole.log[i].iteration, part.log[i].iteration);
    EXPECT_EQ(whole.log[i].x, part.log[i].x);
  }
  for (std::size_t i = part.log.size(); i < whole.log.size(); ++i)
    EXPECT_EQ(whole.log[i].iteration, int(i)) << "numbered on";
  EXPECT_LE(whole.log.back().iteration, 5);
  EXPECT_EQ(whole.initialCost, part.initialCost);
  EXPECT_LE(whole.finalCost, part.finalCost * (1.0 + 1e-9));
  EXPECT_GT(whole.renders, part.renders);
  EXPECT_NEAR(whole.values[0], 0.8, 0.02);

  // Resumed with no iteration left, the fit's report counts the iterations of the whole fit, not
  // Ceres's 0 of the resumed solve (issue 35).
  ASSERT_NE(part.termination.find("Number of iterations: 2."), std::string::npos) << part.termination;
  FitEvaluator again(first, views);
  const FitResult finished = runFit(again, {}, &progress);
  EXPECT_NE(finished.termination.find("Number of iterations: 2 ("), std::string::npos)
      << finished.termination;
  EXPECT_EQ(finished.termination.find("Number of iterations: 0"), std::string::npos)
      << finished.termination;
}

// A fit stopped just after a rejected step and resumed takes the steps the uninterrupted fit
// takes, to the last bit: Ceres's state after a rejection (the factor that shrinks the trust
// region further) cannot be given back to it, so the resumed fit restarts after the last accepted
// step (resumePoint) and does the rejected ones again. Before, it restarted at the rejected
// step's radius with a fresh factor and ended elsewhere (the Cornell box's shift: 1.65 against
// 3.0).
TEST(FitCheckpoint, AFitResumedAfterARejectedStepTakesTheUninterruptedSteps) {
  test::glTestContext();
  test::FitFiles files("checkpoint-rejected");
  const auto spec = [&](int iterations) {
    return test::smallFitSpec(
        files, 16,
        "parameters = [{ key = \"propagation.damping\", initial = 1.4, lower = 0.5, upper = 1.5 },"
        " { key = \"injection.shift\", initial = 2.5, lower = 0.0, upper = 3.0, step = 0.25 }]\n"
        "max_iterations = " + std::to_string(iterations) + "\n");
  };
  constexpr int kIterations = 10;
  const FitSpec whole = spec(kIterations);
  const std::vector<FitView> views = test::syntheticViews(whole, {0.85, 1.0});
  FitEvaluator uninterruptedEvaluator(whole, views);
  const FitResult uninterrupted = runFit(uninterruptedEvaluator);
  int rejected = 0;  // the first rejected step that another iteration follows
  for (const FitIteration& it : uninterrupted.log)
    if (it.iteration > 0 && it.iteration < uninterrupted.log.back().iteration && !it.successful) {
      rejected = it.iteration;
      break;
    }
  ASSERT_GT(rejected, 0) << "started far from the truth, this fit has rejected steps near its end";

  const FitSpec early = spec(rejected);  // the evaluator keeps a reference to its spec
  FitEvaluator stoppedEvaluator(early, views);
  const FitResult stopped = runFit(stoppedEvaluator);
  ASSERT_EQ(stopped.log.back().iteration, rejected);
  ASSERT_FALSE(stopped.log.back().successful);
  const FitProgress progress{stopped.log, stopped.renders, stopped.seconds};
  EXPECT_LT(resumePoint(progress).log.back().iteration, rejected);
  EXPECT_TRUE(resumePoint(progress).log.back().successful);

  FitEvaluator resumedEvaluator(whole, views);
  const FitResult resumed = runFit(resumedEvaluator, {}, &progress);
  ASSERT_EQ(resumed.log.size(), uninterrupted.log.size());
  for (std::size_t i = 0; i < resumed.log.size(); ++i) {
    EXPECT_EQ(resumed.log[i].iteration, uninterrupted.log[i].iteration);
    EXPECT_EQ(resumed.log[i].x, uninterrupted.log[i].x) << "iteration " << i;
    EXPECT_EQ(resumed.log[i].cost, uninterrupted.log[i].cost) << "iteration " << i;
    EXPECT_EQ(resumed.log[i].successful, uninterrupted.log[i].successful) << "iteration " << i;
    EXPECT_EQ(resumed.log[i].trustRegionRadius, uninterrupted.log[i].trustRegionRadius)
        << "iteration " << i << ": the trust region shrinks as the uninterrupted fit's does";
  }
  EXPECT_EQ(resumed.values, uninterrupted.values);
  EXPECT_EQ(resumed.finalCost, uninterrupted.finalCost);
}

}  // namespace
}  // namespace lpvlab

// A run's timing report (framework/experiment/timing.h): per stage, and the sums "method" (the
// indirect method's stages), "shared" (the raster passes and direct light) and "total", each by
// its stages' clock; the method's time is what differs between a sweep's configurations (issue
// 43), so it must hold exactly the method's stages.

#include <gtest/gtest.h>

#include "framework/experiment/timing.h"

namespace lpvlab {
namespace {

FrameTimes frame(double gbuffer, double propagation, double indirect, bool named = true) {
  FrameTimes t;
  t.stageMs = {{"gbuffer", gbuffer}, {"propagation", propagation}, {"indirect", indirect}};
  t.wallMs = {{"gbuffer", gbuffer + 1}, {"propagation", propagation + 1}, {"indirect", indirect + 1}};
  t.clock = {{"gbuffer", kGlTimerQuery}, {"propagation", kCpuWallClock}, {"indirect", kCpuWallClock}};
  t.order = {"gbuffer", "propagation", "indirect"};
  if (named) t.methodStages = {"propagation", "indirect"};
  return t;
}

TEST(Timing, TheMethodsTimeSumsItsStagesAndTheSharedTimeTheRest) {
  const TimingReport r = timingReport({frame(10, 2, 1), frame(12, 4, 1), frame(11, 3, 2)}, 1);
  EXPECT_EQ(r.stageSamples.at(kMethodTime), (std::vector<double>{3, 5, 5}));
  EXPECT_EQ(r.stageSamples.at(kSharedTime), (std::vector<double>{10, 12, 11}));
  EXPECT_EQ(r.stageSamples.at(kTotalTime), (std::vector<double>{13, 17, 16}));
  EXPECT_EQ(r.wallSamples.at(kMethodTime), (std::vector<double>{5, 7, 7}));
  EXPECT_DOUBLE_EQ(r.stageMs.at(kMethodTime).median, 5.0);
  // Each sum's clock is its stages' when they agree: the method ran on the CPU, the G-buffer on
  // GL, so only the total mixes them.
  EXPECT_EQ(r.clock.at(kMethodTime), kCpuWallClock);
  EXPECT_EQ(r.clock.at(kSharedTime), kGlTimerQuery);
  EXPECT_EQ(r.clock.at(kTotalTime), "mixed");
  EXPECT_EQ(r.order, (std::vector<std::string>{"gbuffer", "propagation", "indirect", kMethodTime,
                                               kSharedTime, kTotalTime}));
}

TEST(Timing, FramesThatDoNotNameTheMethodsStagesGetTheTotalOnly) {
  // A sequence resumed over frame records written before they named the method's stages: no
  // frame's split is guessed.
  const TimingReport r = timingReport({frame(10, 2, 1), frame(12, 4, 1, false)}, 0);
  EXPECT_FALSE(r.stageSamples.count(kMethodTime));
  EXPECT_FALSE(r.stageSamples.count(kSharedTime));
  EXPECT_EQ(r.stageSamples.at(kTotalTime), (std::vector<double>{13, 17}));
  EXPECT_EQ(r.order.back(), kTotalTime);
}

}  // namespace
}  // namespace lpvlab

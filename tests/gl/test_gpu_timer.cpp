#include <gtest/gtest.h>

#include <chrono>
#include <functional>

#include "framework/core/error.h"
#include "framework/gl/gpu_timer.h"
#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "gl_test_context.h"

namespace lpvlab {
namespace {

// Tests of behaviour, not speed: a timed stage must measure the work inside it, so its GPU time
// must be positive and within a factor of 10 of the wall time around it (llvmpipe runs the work
// on the CPU, so the two are close). Unflushed timestamps on llvmpipe gave 80 ns for a 900 ms
// dispatch; the factor catches that.
class GpuTimerTest : public testing::Test {
protected:
  void SetUp() override { test::glTestContext(); }

  // Times `work` as `stage` (after one untimed run: llvmpipe compiles shaders on first use);
  // returns {GPU ms, wall ms}.
  std::pair<double, double> time(const std::string& stage, const std::function<void()>& work) {
    work();
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    timer_.begin(stage);
    work();
    timer_.end();
    glFinish();
    const std::chrono::duration<double, std::milli> wall = std::chrono::steady_clock::now() - start;
    const std::map<std::string, double> ms = timer_.collectMs();
    EXPECT_EQ(ms.size(), 1u);
    return {ms.at(stage), wall.count()};
  }

  ShaderCompiler compiler_{test::testShaderRoot()};
  GpuTimer timer_;
};

void expectConsistent(double gpuMs, double wallMs) {
  EXPECT_GT(wallMs, 5.0) << "the workload is too small to compare times";
  EXPECT_GT(gpuMs, wallMs / 10.0);
  EXPECT_LT(gpuMs, wallMs * 10.0);
}

TEST_F(GpuTimerTest, ComputeDispatchTimeAgreesWithWallClock) {
  constexpr GLuint kGroups = 1024;
  gl::Buffer out(kGroups * 64 * sizeof(float), "busy.out");
  out.bindStorage(0);
  const Program busy = compiler_.compute("busy.comp", {SpecConstant::i(0, 3000)});
  const auto [gpuMs, wallMs] = time("dispatch", [&] {
    busy.use();
    glDispatchCompute(kGroups, 1, 1);
  });
  RecordProperty("dispatch_gpu_ms", std::to_string(gpuMs));
  RecordProperty("dispatch_wall_ms", std::to_string(wallMs));
  expectConsistent(gpuMs, wallMs);
}

TEST_F(GpuTimerTest, DrawTimeAgreesWithWallClock) {
  gl::Texture target(GL_TEXTURE_2D, GL_RGBA8, 256, 256, 1, "busy.target");
  gl::Framebuffer framebuffer;
  framebuffer.attach(GL_COLOR_ATTACHMENT0, target);
  framebuffer.checkComplete("busy.target");
  GLuint vertexArray = 0;
  glCreateVertexArrays(1, &vertexArray);
  const Program busy =
      compiler_.graphics("fullscreen.vert", "busy.frag", {SpecConstant::i(0, 3000)});
  const auto [gpuMs, wallMs] = time("draw", [&] {
    framebuffer.bind();
    glViewport(0, 0, 256, 256);
    glBindVertexArray(vertexArray);
    busy.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
  });
  glDeleteVertexArrays(1, &vertexArray);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  RecordProperty("draw_gpu_ms", std::to_string(gpuMs));
  RecordProperty("draw_wall_ms", std::to_string(wallMs));
  expectConsistent(gpuMs, wallMs);
}

TEST_F(GpuTimerTest, StagesTimedTwiceAddUpAndQueriesAreReused) {
  for (int frame = 0; frame < 3; ++frame) {
    timer_.begin("a");
    timer_.end();
    timer_.begin("b");
    timer_.end();
    timer_.begin("a");
    timer_.end();
    const std::map<std::string, double> ms = timer_.collectMs();
    EXPECT_EQ(ms.size(), 2u);
    EXPECT_GE(ms.at("a"), 0.0);
    EXPECT_GE(ms.at("b"), 0.0);
  }
  EXPECT_TRUE(timer_.collectMs().empty());
}

TEST_F(GpuTimerTest, MisuseIsAnError) {
  EXPECT_THROW(timer_.end(), Error);
  timer_.begin("outer");
  EXPECT_THROW(timer_.begin("inner"), Error);
  EXPECT_THROW(timer_.collectMs(), Error);
  timer_.end();
  EXPECT_EQ(timer_.collectMs().size(), 1u);
}

}  // namespace
}  // namespace lpvlab

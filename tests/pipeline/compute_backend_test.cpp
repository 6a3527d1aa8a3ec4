// [compute] backend (framework/pipeline/strategy.h, ComputeBackend):
//   a. the default Cornell box, a cascaded SH order 2 composition, the GV with bounces, and
//      directed and tetrahedral propagation with a GV in two cascade levels give the same images
//      with direct light and the strategies on the CPU ("auto" on llvmpipe) and on GL, within
//      float rounding (direct light: but for rare shadow comparisons, backend_comparison.h);
//   b. "auto" resolves to the CPU where a kernel exists only on a software renderer, and keeps
//      a strategy without a CPU kernel for its composition on GL (every shipped strategy has one
//      now, so this test registers one that has not, "test_gl_only");
//   c. a CPU frame is the same bit for bit on one thread and on all;
//   d. "cpu" runs the default composition and refuses, naming the strategy and saying why, a
//      composition with a strategy that has no CPU kernel; an unknown backend is an error naming
//      the key.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "error_support.h"
#include "lpv_support.h"
#include "framework/core/parameters.h"
#include "framework/core/registry.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "backend_comparison.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

// A rendering strategy without a CPU kernel (Strategy::cpuRefusal's default), registered in this
// test binary alone: every shipped strategy has a CPU kernel, and what the backend does with one
// that has not is still to be checked. It adds no light.
class GlOnlyRendering final : public RenderingStrategy {
public:
  explicit GlOnlyRendering(Params&) {}
  void prepare(const StrategySetup&) override {}
  void render(Frame&) override {}
};
LPVLAB_REGISTER(RenderingStrategy, "test_gl_only",
                "a rendering strategy without a CPU kernel, for the compute-backend tests",
                GlOnlyRendering);

struct Rendered {
  std::vector<NamedImage> aovs;
  bool propagationOnCpu = false;
  bool renderingOnCpu = false;  // every rendering strategy
};

Rendered render(std::vector<std::string> overrides) {
  test::glTestContext();
  overrides.insert(overrides.end(),
                   {"output.width=96", "output.height=96", "timing.warmup=0", "timing.repeats=1"});
  Experiment e = loadExperiment("", overrides);
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  bool renderingOnCpu = true;
  const LightPropagationVolumes& lpv = test::lpvOf(pipeline);
  for (const auto& rendering : lpv.strategies().rendering)
    renderingOnCpu = renderingOnCpu && rendering->runsOnCpu(lpv.requirements());
  return {pipeline.readOutputs(),
          lpv.strategies().propagation->runsOnCpu(lpv.requirements()), renderingOnCpu};
}

// Largest |a - b| over an AOV, relative to b's largest value.
double relativeDifference(const Rendered& a, const Rendered& b, const std::string& name) {
  const Image& x = findAov(a.aovs, name);
  const Image& y = findAov(b.aovs, name);
  double largest = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < x.pixels.size(); ++i) {
    largest = std::max(largest, double(std::abs(x.pixels[i] - y.pixels[i])));
    scale = std::max(scale, double(std::abs(y.pixels[i])));
  }
  return scale > 0.0 ? largest / scale : largest;
}

TEST(ComputeBackend, CpuAndGlPropagationGiveTheSameImages) {
  for (const std::vector<std::string>& composition :
       {std::vector<std::string>{},
        {"grid.sh_order=2", "cascades.levels=2"},
        {"occlusion.type=\"geometry_volume\"", "propagation.bounces=true"},
        // Directed and tetrahedral propagation keep their CPU state per cascade level.
        {"propagation.type=\"directed\"", "cascades.levels=2", "occlusion.type=\"geometry_volume\""},
        {"propagation.type=\"tetrahedral\"", "propagation.iterations=12", "cascades.levels=2",
         "occlusion.type=\"geometry_volume\""}}) {
    const Rendered gl = render([&] {
      auto o = composition;
      o.push_back("compute.backend=gl");
      return o;
    }());
    const Rendered cpu = render(composition);  // "auto" on llvmpipe
    ASSERT_FALSE(gl.propagationOnCpu);
    ASSERT_TRUE(cpu.propagationOnCpu) << "this test needs a software GL renderer";
    test::expectSameDirectLight(findAov(cpu.aovs, "direct"), findAov(gl.aovs, "direct"), "direct");
    EXPECT_LT(relativeDifference(cpu, gl, "indirect"), 1e-5) << composition.size();
    EXPECT_GT(relativeDifference(cpu, gl, "indirect"), 0.0)
        << "bit-identical: did both runs take the same backend?";
  }
}

// A whole frame on the CPU backend, with the GV, bounces and cascades, is the same bit for bit on
// one thread and on all: no kernel's sums depend on how the work was shared out.
TEST(ComputeBackend, CpuFramesDoNotDependOnTheThreadCount) {
  const std::vector<std::string> composition = {
      "compute.backend=cpu", "occlusion.type=\"geometry_volume\"", "propagation.bounces=true",
      "cascades.levels=2"};
  const Rendered all = render(composition);
  Rendered one;
  {
    const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = render(composition);
  }
  for (const char* aov : {"direct", "indirect"})
    EXPECT_EQ(findAov(one.aovs, aov).pixels, findAov(all.aovs, aov).pixels) << aov;
}

TEST(ComputeBackend, AutoTakesTheCpuOnlyOnASoftwareRendererAndOnlyWhereAKernelExists) {
  EXPECT_EQ(resolveBackend("auto", "llvmpipe (LLVM 15.0.6, 256 bits)"), ComputeBackend::CpuWherePossible);
  EXPECT_EQ(resolveBackend("auto", "NVIDIA H100 PCIe/PCIe/SSE2"), ComputeBackend::Gl);
  EXPECT_EQ(resolveBackend("cpu", "NVIDIA H100 PCIe/PCIe/SSE2"), ComputeBackend::Cpu);
  EXPECT_EQ(resolveBackend("gl", "llvmpipe"), ComputeBackend::Gl);
  // Every propagation has a CPU kernel (standard with the GV and by scattering, directed,
  // tetrahedral), and every shipped rendering; "auto" keeps one without a CPU kernel on GL.
  EXPECT_TRUE(render({"occlusion.type=\"geometry_volume\"", "propagation.bounces=true"}).propagationOnCpu);
  EXPECT_TRUE(render({"propagation.method=\"scatter\""}).propagationOnCpu);
  EXPECT_TRUE(render({"propagation.type=\"directed\""}).propagationOnCpu);
  EXPECT_TRUE(render({"propagation.type=\"tetrahedral\"", "propagation.iterations=4"}).propagationOnCpu);
  EXPECT_TRUE(render({}).renderingOnCpu);
  EXPECT_TRUE(render({"rendering.type=\"subsurface\""}).renderingOnCpu);
  const Rendered glOnly = render({"rendering.type=\"test_gl_only\""});
  EXPECT_FALSE(glOnly.renderingOnCpu);
  EXPECT_TRUE(glOnly.propagationOnCpu);
}

TEST(ComputeBackend, CpuRefusesStrategiesWithoutACpuKernelByName) {
  // The default composition, and the GV with bounces, have CPU kernels throughout; the test's
  // GL-only rendering strategy has none.
  EXPECT_NO_THROW(loadExperiment("", {"compute.backend=\"cpu\""}));
  EXPECT_NO_THROW(loadExperiment("", {"compute.backend=\"cpu\"", "occlusion.type=\"geometry_volume\"",
                                      "propagation.bounces=true"}));
  const std::string message = test::errorOf([] {
    loadExperiment("", {"compute.backend=\"cpu\"", "rendering.type=\"test_gl_only\""});
  });
  EXPECT_TRUE(
      test::contains(message, "[rendering] type = \"test_gl_only\" cannot run on the CPU backend"))
      << message;
  EXPECT_TRUE(test::contains(message, "no CPU kernel yet")) << message;
  EXPECT_TRUE(test::contains(
      test::errorOf([] { loadExperiment("", {"compute.backend=\"vulkan\""}); }), "compute.backend"));
}

}  // namespace
}  // namespace lpvlab

// RSM injection on the CPU backend (variants/injection/rsm_vpl_cpu.h), which calls the GL
// kernel's shared VPL functions (shaders/injection/vpl.glsl) and sums each cell's VPLs in texel
// order instead of adding them with float atomics:
//   a. on the built-in Cornell box at SH orders 1-3 it fills the grid the GL kernel fills,
//      within float rounding (the flux balance itself is injection_test.cpp's, which runs on the
//      default backend, the CPU here);
//   b. the normal grid it fills drives directed propagation (on the CPU too) to the image of an
//      all-GL run, within float rounding;
//   c. its grid does not depend on the thread count, bit for bit;
//   d. VPLs shifted by whole cells from walls on cell boundaries land in the same cells.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "lpv_support.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

struct Injected {
  std::vector<float> grid;
  std::vector<NamedImage> images;
  std::string injectionRanOn;
};

Injected inject(std::vector<std::string> overrides, bool renderFrame = false) {
  test::glTestContext();
  overrides.insert(overrides.end(), {"output.width=96", "output.height=96",
                                     "light_maps.shadow_resolution=128", "timing.warmup=0",
                                     "timing.repeats=1"});
  // The grid compared is the injected one (measureInjection injects again): no propagation, which
  // was most of the frame's time at SH order 3.
  if (!renderFrame) overrides.push_back("propagation.iterations=0");
#ifdef LPVLAB_SANITIZED
  // Under the sanitizers (-O0) fewer VPLs: the backends must agree at any RSM resolution, and the
  // default's took two minutes there for the three orders.
  overrides.push_back("light_maps.rsm_resolution=64");
#endif
  Experiment e = loadExperiment("", overrides);
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  Injected out;
  out.injectionRanOn = pipeline.computeReport().at("strategies").at("injection").get<std::string>();
  if (renderFrame) {
    pipeline.renderFrame();
    out.images = pipeline.readOutputs();
  } else {
    pipeline.renderFrame();  // the RSMs
    test::lpvOf(pipeline).measureInjection();
    out.grid = test::lpvOf(pipeline).readGrid(false);
  }
  return out;
}

double relativeDifference(const std::vector<float>& a, const std::vector<float>& b) {
  double largest = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, double(std::abs(a[i] - b[i])));
    scale = std::max(scale, double(std::abs(b[i])));
  }
  return scale > 0.0 ? largest / scale : largest;
}

TEST(RsmVplCpu, FillsTheGridTheGlKernelFillsAtEveryOrder) {
  for (int order = 1; order <= 3; ++order) {
    const std::string sh = "grid.sh_order=" + std::to_string(order);
    const Injected gl = inject({sh, "compute.backend=gl"});
    const Injected cpu = inject({sh});  // "auto" on llvmpipe
    ASSERT_EQ(gl.injectionRanOn, "gl");
    ASSERT_EQ(cpu.injectionRanOn, "cpu");
    ASSERT_EQ(cpu.grid.size(), gl.grid.size());
    ASSERT_TRUE(std::any_of(gl.grid.begin(), gl.grid.end(), [](float v) { return v != 0.0f; }))
        << "order " << order << ": nothing injected, the comparison would pass by zeros";
    EXPECT_LT(relativeDifference(cpu.grid, gl.grid), 1e-5) << "order " << order;
  }
}

// The built-in Cornell box's grid is fitted to the box, so its walls lie on cell boundaries, and a
// whole-cell shift moves their VPLs exactly onto another boundary, where float (GL) and double
// (CPU) arithmetic rounded to different cells until VPLs were binned along their normals with
// grid.glsl's surfaceCell (found by the fit, which ran into the bound shift = 3 and stopped elsewhere on the
// CPU: 6% of the indirect light had moved).
TEST(RsmVplCpu, VplsShiftedOntoACellBoundaryLandInTheSameCellOnBothBackends) {
  for (const std::string shift : {"1", "2", "3"}) {
    const Injected gl = inject({"injection.shift=" + shift, "compute.backend=gl"});
    const Injected cpu = inject({"injection.shift=" + shift});
    EXPECT_LT(relativeDifference(cpu.grid, gl.grid), 1e-5) << "shift " << shift;
  }
}

TEST(RsmVplCpu, ItsNormalGridDrivesDirectedPropagationAsGlsOwnDoes) {
  const std::vector<std::string> directed = {"propagation.type=\"directed\""};
  std::vector<std::string> glOnly = directed;
  glOnly.push_back("compute.backend=gl");
  const Injected gl = inject(glOnly, true);
  const Injected cpu = inject(directed, true);
  ASSERT_EQ(cpu.injectionRanOn, "cpu");
  const Image& a = findAov(cpu.images, "indirect");
  const Image& b = findAov(gl.images, "indirect");
  EXPECT_LT(relativeDifference(a.pixels, b.pixels), 1e-4);
}

TEST(RsmVplCpu, TheGridDoesNotDependOnTheThreadCount) {
  const Injected all = inject({"grid.sh_order=2"});
  Injected one;
  {
    const tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = inject({"grid.sh_order=2"});
  }
  ASSERT_EQ(all.grid.size(), one.grid.size());
  EXPECT_EQ(all.grid, one.grid);
}

}  // namespace
}  // namespace lpvlab

// The pipeline allocates only what the composition declares (framework/pipeline/strategy.h
// Requirements), checked through Pipeline::memoryReport() on the built-in Cornell box:
//   - occlusion "none": no geometry volume at all (0 bytes);
//   - occlusion "geometry_volume": exactly (res + 1)^3 cells of 4 floats (order-1 blocking), and
//     with both sources one more such GV for merging, counted under "occlusion";
//   - the RSMs are rendered only when a strategy consumes them (raster_inputs.h): sky injection
//     alone, or a GV of the camera's surfels alone, has no "rsm" stage;
//   - the light grid (current + accumulated) and standard propagation's scratch hold exactly
//     3 * (order + 1)^2 floats per cell at SH orders 1, 2 and 3 (a GL scratch grid, or three host
//     grids when gathering runs on the CPU).

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "variants/resources/geometry_volume.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

// The built-in Cornell box, small, with `extra` overrides.
Experiment smallDefault(const std::vector<std::string>& extra) {
  test::glTestContext();
  std::vector<std::string> overrides = {"output.width=64", "output.height=64",
                                        "light_maps.shadow_resolution=64",
                                        "light_maps.rsm_resolution=32", "grid.resolution=12"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  return loadExperiment("", overrides);
}

struct Report {
  nlohmann::json bytes;
  glm::ivec3 resolution;
};

Report memoryOf(const std::vector<std::string>& extra) {
  Experiment e = smallDefault(extra);
  ShaderCompiler shaders;
  const glm::ivec3 resolution = e.settings.grid.resolution;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  return {pipeline.memoryReport(), resolution};
}

std::size_t cells(const glm::ivec3& r) { return std::size_t(r.x) * r.y * r.z; }
const std::size_t kFloat = sizeof(float);

// The stages one frame runs with `extra`, and what LPV consumes.
struct Rendered {
  std::vector<std::string> stages;
  std::set<std::string> consumed;
  nlohmann::json work;
};

Rendered stagesOf(const std::vector<std::string>& extra) {
  Experiment e = smallDefault(extra);
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  const FrameTimes times = pipeline.renderFrame();
  return {times.order, pipeline.method().consumes(), pipeline.workReport()};
}

bool has(const std::vector<std::string>& stages, const std::string& stage) {
  return std::find(stages.begin(), stages.end(), stage) != stages.end();
}

TEST(ResourceEconomy, TheRsmsAreRenderedOnlyWhenAStrategyConsumesThem) {
  const Rendered standard = stagesOf({});
  EXPECT_TRUE(has(standard.stages, "rsm"));  // rsm_vpl's VPLs
  EXPECT_EQ(standard.consumed, std::set<std::string>{"rsm"});
  EXPECT_TRUE(standard.work.contains("rsm"));

  const Rendered sky = stagesOf({"injection.type=\"sky_columns\"", "sky.radiance=[0.2, 0.3, 0.4]"});
  EXPECT_FALSE(has(sky.stages, "rsm"));
  EXPECT_TRUE(has(sky.stages, "injection"));
  EXPECT_TRUE(sky.consumed.empty());
  EXPECT_FALSE(sky.work.contains("rsm"));

  const std::string gv = "occlusion.type=\"geometry_volume\"";
  const std::string sky1 = "injection.type=\"sky_columns\"", sky2 = "sky.radiance=[0.2, 0.3, 0.4]";
  EXPECT_FALSE(has(stagesOf({sky1, sky2, gv, "occlusion.sources=[\"camera\"]"}).stages, "rsm"));
  EXPECT_TRUE(has(stagesOf({sky1, sky2, gv, "occlusion.sources=[\"light\"]"}).stages, "rsm"));
}

TEST(ResourceEconomy, NoOcclusionAllocatesNoGeometryVolume) {
  const Report r = memoryOf({"occlusion.type=\"none\""});
  EXPECT_EQ(r.bytes.value("geometry_volume", std::size_t(0)), 0u);  // not even allocated
  EXPECT_EQ(r.bytes.at("occlusion").get<std::size_t>(), 0u);
}

TEST(ResourceEconomy, TheGeometryVolumeIsResPlusOneCubedTimesFourFloats) {
  for (const std::string backend : {"gl", "cpu"})
    for (const std::string sources : {"[\"camera\"]", "[\"light\"]", "[\"light\", \"camera\"]"}) {
      const Report r = memoryOf({"occlusion.type=\"geometry_volume\"", "occlusion.sources=" + sources,
                                 "compute.backend=" + backend});
      const std::size_t gv = cells(r.resolution + 1) * 4 * kFloat;
      EXPECT_EQ(r.bytes.at("geometry_volume").get<std::size_t>(), gv) << sources;
      // Merging two sources needs a second GV; one source fills the GV directly (on GL; the CPU
      // fills a host copy, uploaded).
      const bool both = sources.find(',') != std::string::npos;
      const std::size_t own = backend == "gl" ? (both ? gv : 0u) : (both ? 2 * gv : gv);
      EXPECT_EQ(r.bytes.at("occlusion").get<std::size_t>(), own) << sources << " on " << backend;
    }
}

TEST(ResourceEconomy, LightGridAndScratchHoldExactlyTheOrdersCoefficients) {
  for (int order = 1; order <= 3; ++order) {
    for (const std::string backend : {"gl", "cpu"}) {
      const Report r = memoryOf({"grid.sh_order=" + std::to_string(order),
                                 "propagation.method=\"scatter\"", "compute.backend=" + backend});
      const std::size_t perGrid = cells(r.resolution) * 3 * (order + 1) * (order + 1) * kFloat;
      EXPECT_EQ(r.bytes.at("light_grid").get<std::size_t>(), 2 * perGrid) << "order " << order;
      // A ping-pong partner for `current`: on GL a buffer, on the CPU a host array (the grids'
      // own host sides belong to the light grid, allocated when a CPU kernel first uses them).
      const std::size_t grids = 1;
      EXPECT_EQ(r.bytes.at("propagation").get<std::size_t>(), grids * perGrid) << "order " << order;
    }
  }
}

}  // namespace
}  // namespace lpvlab

namespace lpvlab {
namespace {

// A pipeline without direct light (what lpvlab fit renders) skips the shadow maps and the direct
// light, and gives the same indirect light as one with them.
TEST(ResourceEconomy, WithoutDirectLightTheIndirectIsTheSameAndNoShadowMapsAreRendered) {
  test::glTestContext();
  ShaderCompiler shaders;
  Image indirect[2];
  for (const bool direct : {true, false}) {
    Experiment e = loadExperiment("", {"output.width=48", "output.height=48",
                                       "light_maps.rsm_resolution=32", "grid.resolution=12",
                                       "compute.backend=\"cpu\""});
    e.settings.directLight = direct;
    Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
    const FrameTimes times = pipeline.renderFrame();
    EXPECT_EQ(times.wallMs.count("shadow_maps"), direct ? 1u : 0u);
    EXPECT_EQ(times.wallMs.count("direct"), direct ? 1u : 0u);
    double directSum = 0.0;
    for (const NamedImage& aov : pipeline.readOutputs()) {
      if (aov.name == "indirect") indirect[direct] = aov.image;
      if (aov.name == "direct")
        for (float v : aov.image.pixels) directSum += v;
    }
    if (direct) {
      EXPECT_GT(directSum, 0.0);
    } else {
      EXPECT_EQ(directSum, 0.0);
    }
  }
  ASSERT_EQ(indirect[0].pixels.size(), indirect[1].pixels.size());
  double largest = 0.0;
  for (float v : indirect[1].pixels) largest = std::max(largest, double(v));
  ASSERT_GT(largest, 0.0);
  for (std::size_t i = 0; i < indirect[0].pixels.size(); ++i)
    EXPECT_EQ(indirect[0].pixels[i], indirect[1].pixels[i]) << "value " << i;
}

}  // namespace
}  // namespace lpvlab

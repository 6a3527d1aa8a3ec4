// Cascaded light grids ([cascades], framework/pipeline/cascade.h, thesis 5.1):
//   - rendering blends two levels exactly as cascade_blend.glsl's weights say (checked against
//     the double-precision fade), so a surface crossing a level's boundary gets a continuous
//     value; a hard switch (blend_cells = 0) jumps, so the check can fail;
//   - moving the camera by less than a cell leaves every level's light unchanged (to the rounding
//     of float atomics); a move
//     of several cells moves the finer levels;
//   - carrying: each parent cell inside its child holds the sum of its 2x2x2 children's injected
//     light (flux conserved), cells outside keep their own; without carrying they differ;
//   - "depth" placement: on the ablation view from inside the Cornell box every level injects
//     light and three levels render differently from two (with "eye" placement the finest level
//     held only air there); levels sit around the median of the G-buffer's positions, a
//     sub-cell camera move keeps the light, and a frame that sees nothing uses the eye rule;
//   - memory: every level has its own light grid (and GV), the strategies' scratch exists once;
//   - extremes: eight levels of 4^3 cells give finite light.

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lpv_support.h"
#include "framework/experiment/experiment.h"
#include "framework/math/cascade_placement.h"
#include "framework/pipeline/pipeline.h"
#include "variants/resources/geometry_volume.h"
#include "pipeline_test_support.h"
#include "rendering_rig.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/common/cascade_fade.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using glm::dvec3;

// --- Blending, on hand-made levels ------------------------------------------------------------

// Two levels with constant isotropic intensities: the coarse one 8^3 cells of 1 m at the origin,
// the fine one 8^3 cells of 0.5 m starting at (2, 2, 2) (on whole coarse cells).
struct TwoLevels {
  std::vector<test::HandGrid> levels;
  TwoLevels(double fineIntensity, double coarseIntensity) {
    GridGeometry coarse, fine;
    coarse.resolution = fine.resolution = glm::ivec3(8);
    coarse.cellSize = 1.0f;
    fine.cellSize = 0.5f;
    fine.origin = glm::vec3(2.0f);
    levels = {test::HandGrid(fine, 1), test::HandGrid(coarse, 1)};
    levels[0].fill([&](glm::ivec3, int, std::vector<double>& c) { c[0] = fineIntensity; });
    levels[1].fill([&](glm::ivec3, int, std::vector<double>& c) { c[0] = coarseIntensity; });
  }
};

// A floor at y = 4 crossed along x through the fine level's centre, densely.
std::vector<test::SurfacePixel> rowAlongX(int count) {
  std::vector<test::SurfacePixel> row;
  for (int i = 0; i < count; ++i)
    row.push_back({dvec3(0.5 + 7.0 * (i + 0.5) / count, 4.0, 4.0), dvec3(0, 1, 0), dvec3(1.0)});
  return row;
}

std::vector<double> red(const std::vector<dvec3>& values) {
  std::vector<double> out;
  for (const dvec3& v : values) out.push_back(v.x);
  return out;
}

TEST(CascadeRendering, LevelsBlendWithTheFadeWeightsAndTheValueIsContinuous) {
  const TwoLevels grids(2.0, 3.0);
  const std::vector<test::SurfacePixel> row = rowAlongX(280);
  const glm::vec3 camera(4.0f, 6.0f, 4.0f);
  // Each level alone gives a constant radiance (the fields are uniform).
  const double fine = red(test::renderPixels("trilinear", {}, grids.levels[0], row, camera))[140];
  const double coarse = red(test::renderPixels("trilinear", {}, grids.levels[1], row, camera))[140];
  ASSERT_GT(std::abs(fine - coarse), 0.1 * coarse);  // so a jump would show

  const double blendCells = 2.0;
  const std::vector<double> blended =
      red(test::renderPixels("trilinear", {}, grids.levels, row, camera, float(blendCells)));
  double largestStep = 0.0;
  for (std::size_t i = 0; i < row.size(); ++i) {
    const dvec3 g = (row[i].position - dvec3(2.0)) / 0.5;  // the fine level's grid coordinates
    const double w = shared::cascadeFade(g, glm::ivec3(8), blendCells);
    EXPECT_NEAR(blended[i], w * fine + (1.0 - w) * coarse, 1e-5 * coarse) << "pixel " << i;
    if (i > 0) largestStep = std::max(largestStep, std::abs(blended[i] - blended[i - 1]));
  }
  // The fade rises over blendCells fine cells (1 m); the row steps 7/280 m: each step may change
  // the value by at most |fine - coarse| * 0.025 / 1.
  EXPECT_LE(largestStep, std::abs(fine - coarse) * 0.025 * 1.001);

  // A hard switch jumps by the whole difference somewhere along the row.
  const std::vector<double> hard = red(test::renderPixels("trilinear", {}, grids.levels, row, camera, 0.0f));
  double hardStep = 0.0;
  for (std::size_t i = 1; i < row.size(); ++i) hardStep = std::max(hardStep, std::abs(hard[i] - hard[i - 1]));
  EXPECT_NEAR(hardStep, std::abs(fine - coarse), 1e-4 * coarse);
}

TEST(CascadeRendering, WeightsSumToOneSoEqualLevelsGiveOneLevelsValue) {
  // Levels holding the same radiance (intensity scaled by the cell area) render as one level.
  const TwoLevels grids(1.0, 4.0);
  const std::vector<test::SurfacePixel> row = rowAlongX(64);
  const glm::vec3 camera(4.0f, 6.0f, 4.0f);
  const std::vector<double> single = red(test::renderPixels("trilinear", {}, grids.levels[1], row, camera));
  const std::vector<double> both = red(test::renderPixels("trilinear", {}, grids.levels, row, camera, 2.0f));
  for (std::size_t i = 0; i < row.size(); ++i) EXPECT_NEAR(both[i], single[i], 1e-5 * single[i]);
}

// --- The pipeline ---------------------------------------------------------------------------

Experiment cornell(const std::vector<std::string>& extra) {
  std::vector<std::string> overrides = {"output.width=48", "output.height=48",
                                        "light_maps.shadow_resolution=64",
                                        "light_maps.rsm_resolution=32", "grid.resolution=12"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  return loadExperiment("", overrides);
}

// The largest difference between two grids relative to the first's largest value. Injection adds
// VPLs with float atomics, whose order varies between runs: equal light agrees to rounding only.
double relativeDifference(const std::vector<float>& a, const std::vector<float>& b) {
  double largest = 0.0, difference = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, double(std::abs(a[i])));
    difference = std::max(difference, double(std::abs(a[i] - b[i])));
  }
  return largest > 0.0 ? difference / largest : difference;
}

struct LevelsSnapshot {
  std::vector<std::vector<float>> accumulated;  // per level, finest first
  std::vector<GridGeometry> placement;
};

LevelsSnapshot snapshot(const Pipeline& pipeline) {
  LevelsSnapshot run;
  for (std::size_t level = 0; level < test::lpvOf(pipeline).levels().size(); ++level) {
    run.accumulated.push_back(test::lpvOf(pipeline).readGrid(true, int(level)));
    run.placement.push_back(test::lpvOf(pipeline).levels()[level].geometry);
  }
  return run;
}

TEST(CascadePipeline, ACameraMoveOfLessThanACellLeavesTheLightUnchanged) {
  test::glTestContext();
  // A camera inside the box, near the floor's left corner, so the finest level holds walls.
  Experiment e = cornell({"cascades.levels=3", "cascades.placement=\"eye\"", "propagation.iterations=6",
                          "camera.position=[0.12, 0.1, 0.15]", "camera.look_at=[0.05, 0.0, 0.5]",
                          "camera.up=[0.0, 1.0, 0.0]", "camera.fov_deg=60.0"});
  ShaderCompiler shaders;
  const Camera start = e.camera;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  const LevelsSnapshot before = snapshot(pipeline);
  const float finestCell = before.placement[0].cellSize;
  for (const std::vector<float>& level : before.accumulated)  // else the comparisons say nothing
    ASSERT_GT(*std::max_element(level.begin(), level.end()), 0.0f);

  // Find a small move that keeps every level's placement (most sub-cell moves do), then check
  // that the light is the same (up to the rounding of float atomics).
  int checked = 0;
  for (int step = 1; step <= 8 && checked == 0; ++step) {
    Camera moved = start;
    moved.position += glm::vec3(0.03f, -0.02f, 0.04f) * (finestCell * float(step));
    const std::vector<GridGeometry> placed = placeCascadeLevels(
        e.settings.grid, 3, moved.position, moved.forward, e.settings.cascades.viewShift);
    bool samePlacement = true;
    for (int level = 0; level < 3; ++level)
      samePlacement = samePlacement && placed[std::size_t(level)].origin == before.placement[std::size_t(level)].origin;
    if (!samePlacement) continue;
    pipeline.setCamera(moved);
    pipeline.renderFrame();
    const LevelsSnapshot after = snapshot(pipeline);
    for (int level = 0; level < 3; ++level)
      EXPECT_LT(relativeDifference(before.accumulated[std::size_t(level)], after.accumulated[std::size_t(level)]),
                1e-5) << "level " << level;
    ++checked;
  }
  ASSERT_EQ(checked, 1);

  // Several cells' move: the finest level follows, and its light changes.
  Camera far = start;
  far.position += glm::vec3(4.0f * before.placement[1].cellSize, 0.0f, 0.0f);
  pipeline.setCamera(far);
  pipeline.renderFrame();
  const LevelsSnapshot moved = snapshot(pipeline);
  EXPECT_NE(moved.placement[0].origin, before.placement[0].origin);
  EXPECT_GT(relativeDifference(before.accumulated[0], moved.accumulated[0]), 0.01);
  EXPECT_EQ(moved.placement[2].origin, before.placement[2].origin);  // the coarsest stays put
}

TEST(CascadePipeline, WithDepthPlacementASubCellCameraMoveLeavesTheLightUnchanged) {
  test::glTestContext();
  Experiment e = cornell({"cascades.levels=3", "cascades.placement=\"depth\"",
                          "propagation.iterations=6", "camera.position=[0.12, 0.1, 0.15]",
                          "camera.look_at=[0.05, 0.0, 0.5]", "camera.up=[0.0, 1.0, 0.0]",
                          "camera.fov_deg=60.0"});
  ShaderCompiler shaders;
  const Camera start = e.camera;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  const LevelsSnapshot before = snapshot(pipeline);
  for (const std::vector<float>& level : before.accumulated)
    ASSERT_GT(*std::max_element(level.begin(), level.end()), 0.0f);
  // The focus (a median of what is seen) moves by about the camera's move or less, so most
  // sub-cell moves keep every level where it was; where one does, the light is the same. Where
  // a level moved, it moved by whole cells of its parent.
  int kept = 0;
  for (int step = 1; step <= 6; ++step) {
    Camera moved = start;
    moved.position += glm::vec3(0.03f, -0.02f, 0.04f) * (before.placement[0].cellSize * float(step));
    pipeline.setCamera(moved);
    pipeline.renderFrame();
    const LevelsSnapshot after = snapshot(pipeline);
    bool samePlacement = true;
    for (std::size_t level = 0; level < 3; ++level) {
      const glm::vec3 shift = after.placement[level].origin - before.placement[level].origin;
      const float parentCell = before.placement[std::min(level + 1, std::size_t(2))].cellSize;
      for (int axis = 0; axis < 3; ++axis) {
        const double cells = shift[axis] / parentCell;
        EXPECT_NEAR(cells, std::round(cells), 1e-3) << "level " << level;
      }
      samePlacement = samePlacement && shift == glm::vec3(0.0f);
    }
    if (!samePlacement) continue;
    for (std::size_t level = 0; level < 3; ++level)
      EXPECT_LT(relativeDifference(before.accumulated[level], after.accumulated[level]), 1e-5)
          << "level " << level << ", step " << step;
    ++kept;
  }
  EXPECT_GE(kept, 3);
}

// The camera of experiments/ablation_cascades.toml: inside the box near the floor, looking along
// it at the blocks.
const std::vector<std::string> kAblationView = {
    "camera.position=[0.42, 0.12, 0.12]", "camera.look_at=[0.1, 0.1, 0.5]",
    "camera.up=[0.0, 1.0, 0.0]", "camera.fov_deg=65.0"};

// Flux (W, RGB summed) in a grid of `coefficients` per channel (the SH constant term integrated).
double gridFlux(const std::vector<float>& grid, int cells, int coefficients) {
  double flux = 0.0;
  for (int channel = 0; channel < 3; ++channel)
    for (int cell = 0; cell < cells; ++cell)
      flux += shared::shIntegral(glm::dvec4(
          grid[std::size_t(shared::coefficientIndex(channel, 0, coefficients, cell, cells))], 0, 0, 0));
  return flux;
}

struct PlacedRun {
  std::vector<double> injectedFlux;  // per level, finest first (each level's own: no carrying)
  std::vector<GridGeometry> placement;
  Image indirect;
  Image depth;
};

PlacedRun runAblationView(const std::string& placement, int levels) {
  test::glTestContext();
  std::vector<std::string> overrides = kAblationView;
  overrides.insert(overrides.end(), {"cascades.levels=" + std::to_string(levels),
                                     "cascades.placement=\"" + placement + "\"",
                                     "cascades.carry=false", "propagation.iterations=8"});
  Experiment e = cornell(overrides);
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  PlacedRun run;
  for (int level = 0; level < levels; ++level) {
    const GridGeometry& g = test::lpvOf(pipeline).levels()[std::size_t(level)].geometry;
    run.injectedFlux.push_back(gridFlux(test::lpvOf(pipeline).readGrid(false, level), g.cellCount(), 4));
    run.placement.push_back(g);
  }
  for (NamedImage& image : pipeline.readOutputs()) {
    if (image.name == "indirect") run.indirect = std::move(image.image);
    if (image.name == "depth") run.depth = std::move(image.image);
  }
  return run;
}

// The largest difference between two images relative to the first's mean.
double imageDifference(const Image& a, const Image& b) {
  double sum = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    sum += a.pixels[i];
    largest = std::max(largest, double(std::abs(a.pixels[i] - b.pixels[i])));
  }
  return largest / (sum / double(a.pixels.size()));
}

TEST(CascadePipeline, DepthPlacementPutsSurfacesInTheFinestLevelOnTheAblationView) {
  const PlacedRun depth = runAblationView("depth", 3);
  const PlacedRun eye = runAblationView("eye", 3);
  for (int level = 0; level < 3; ++level)
    std::cout << "[ flux ] level " << level << ": depth " << depth.injectedFlux[std::size_t(level)]
              << " W, eye " << eye.injectedFlux[std::size_t(level)] << " W\n";
  // Every level holds VPLs (measured: the finest 0.9 % of the scene's injected flux in 1/64 of
  // its volume; the light falls mostly on the floor and blocks far from this corner).
  for (int level = 0; level < 3; ++level) EXPECT_GT(depth.injectedFlux[std::size_t(level)], 0.0);
  EXPECT_GT(depth.injectedFlux[0], 0.005 * depth.injectedFlux[2]);
  // The eye rule's finest level, around the eye, holds no surface (measured: exactly 0 W).
  EXPECT_LT(eye.injectedFlux[0], 0.1 * depth.injectedFlux[0]);

  // So the third level changes the image with "depth" placement (with "eye" it did not).
  const PlacedRun twoLevels = runAblationView("depth", 2);
  EXPECT_GT(imageDifference(twoLevels.indirect, depth.indirect), 0.05);
  // The coarser finer level (level 1 of 3, the finest of 2) is the same grid in both runs.
  EXPECT_EQ(twoLevels.placement[0].origin, depth.placement[1].origin);
}

TEST(CascadePipeline, DepthPlacementCentresTheFinerLevelsOnWhatTheCameraSees) {
  const PlacedRun run = runAblationView("depth", 3);
  // The median visible depth, from the depth output (0 where nothing was hit): the finest level,
  // centred on the per-axis median of the visible positions, lies along the view around it.
  std::vector<float> depths;
  for (const float d : run.depth.pixels)
    if (d > 0.0f) depths.push_back(d);
  ASSERT_FALSE(depths.empty());
  std::nth_element(depths.begin(), depths.begin() + std::ptrdiff_t(depths.size() / 2), depths.end());
  const double medianDepth = depths[depths.size() / 2];
  const Experiment e = cornell(kAblationView);
  const GridGeometry& finest = run.placement[0];
  const glm::vec3 centre = finest.origin + 0.5f * finest.extent();
  const double centreDepth = glm::dot(centre - e.camera.position, e.camera.forward);
  // Within a quarter of the finest level's extent (the median point is off the view axis).
  EXPECT_NEAR(centreDepth, medianDepth, 0.25 * finest.extent().x);
  EXPECT_GT(centreDepth, 0.0);  // ahead of the camera, not around it
}

TEST(CascadePipeline, WithDepthPlacementAFrameThatSeesNothingFallsBackToTheEyeRule) {
  test::glTestContext();
  // The default camera turned round: it looks away from the open box and sees no surface.
  Experiment e = cornell({"cascades.levels=3", "cascades.placement=\"depth\"",
                          "cascades.view_shift=0.4", "camera.position=[0.28, 0.27, -0.3]",
                          "camera.look_at=[0.28, 0.27, -1.0]", "camera.up=[0.0, 1.0, 0.0]"});
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  for (const NamedImage& image : pipeline.readOutputs()) {
    if (image.name == "depth") {
      ASSERT_EQ(*std::max_element(image.image.pixels.begin(), image.image.pixels.end()), 0.0f);
    }
  }
  const std::vector<GridGeometry> eyeRule = placeCascadeLevels(
      e.settings.grid, 3, e.camera.position, e.camera.forward, e.settings.cascades.viewShift);
  for (std::size_t level = 0; level < 3; ++level)
    EXPECT_EQ(test::lpvOf(pipeline).levels()[level].geometry.origin, eyeRule[level].origin) << "level " << level;
}

LevelsSnapshot injectedLight(bool carry) {
  test::glTestContext();
  Experiment e = cornell({"cascades.levels=2", "propagation.iterations=0",
                          std::string("cascades.carry=") + (carry ? "true" : "false")});
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  return snapshot(pipeline);  // with no iterations, accumulated = injected (after carrying)
}

TEST(CascadePipeline, CarryingPutsTheSumOfTheChildrenIntoEachParentCellInsideTheChild) {
  const LevelsSnapshot carried = injectedLight(true);
  const LevelsSnapshot own = injectedLight(false);
  const GridGeometry& child = carried.placement[0];
  const GridGeometry& parent = carried.placement[1];
  const glm::ivec3 r = parent.resolution;
  const glm::ivec3 offset = childOffsetInParentCells(child, parent);
  const int coefficients = 4, cells = parent.cellCount();
  double insideDifference = 0.0, insideTotal = 0.0;
  int inside = 0, outside = 0;
  for (int z = 0; z < r.z; ++z)
    for (int y = 0; y < r.y; ++y)
      for (int x = 0; x < r.x; ++x) {
        const glm::ivec3 c(x, y, z), local = c - offset;
        const bool inChild = glm::all(glm::greaterThanEqual(local, glm::ivec3(0))) &&
                             glm::all(glm::lessThan(local, r / 2));
        for (int channel = 0; channel < 3; ++channel)
          for (int k = 0; k < coefficients; ++k) {
            const std::size_t at = std::size_t(shared::coefficientIndex(
                channel, k, coefficients, shared::cellIndex(c, r), cells));
            if (!inChild) {
              EXPECT_NEAR(carried.accumulated[1][at], own.accumulated[1][at],
                          1e-5 * (std::abs(own.accumulated[1][at]) + 1e-3));
              ++outside;
              continue;
            }
            double sum = 0.0;
            for (int corner = 0; corner < 8; ++corner) {
              const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
              sum += carried.accumulated[0][std::size_t(shared::coefficientIndex(
                  channel, k, coefficients, shared::cellIndex(2 * local + o, r), cells))];
            }
            EXPECT_NEAR(carried.accumulated[1][at], sum, 1e-5 * (std::abs(sum) + 1e-3));
            insideDifference += std::abs(own.accumulated[1][at] - sum);
            insideTotal += std::abs(sum);
            ++inside;
          }
      }
  EXPECT_GT(inside, 0);
  EXPECT_GT(outside, 0);
  ASSERT_GT(insideTotal, 0.0);
  // The parent's own injection differs (VPLs shifted by a parent cell, not a child cell).
  EXPECT_GT(insideDifference, 0.01 * insideTotal);
}

TEST(CascadePipeline, EveryLevelHasItsOwnGridsAndTheStrategiesScratchExistsOnce) {
  test::glTestContext();
  for (const std::string backend : {"gl", "cpu"})
  for (const int levels : {1, 3}) {
    Experiment e = cornell({"cascades.levels=" + std::to_string(levels),
                            "occlusion.type=\"geometry_volume\"", "compute.backend=" + backend});
    ShaderCompiler shaders;
    const std::size_t gridBytes = LightGrid::bytesPerGrid(e.settings.grid, 1);
    const std::size_t gvBytes = std::size_t(GeometryVolume::placementFor(e.settings.grid).cellCount()) *
                                GeometryVolume::kCoefficients * sizeof(float);
    Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
    const nlohmann::json bytes = pipeline.memoryReport();
    EXPECT_EQ(bytes.at("light_grid").get<std::size_t>(), std::size_t(levels) * 2 * gridBytes);
    EXPECT_EQ(bytes.at("geometry_volume").get<std::size_t>(), std::size_t(levels) * gvBytes);
    // One scratch grid, on GL or on the host (before a frame, the light grid has no host side).
    EXPECT_EQ(bytes.at("propagation").get<std::size_t>(), gridBytes) << backend;
  }
}

TEST(CascadePipeline, EightLevelsOfFourCellsGiveFiniteLight) {
  test::glTestContext();
  Experiment e = cornell({"cascades.levels=8", "grid.resolution=4", "propagation.iterations=20"});
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  for (int level = 0; level < 8; ++level)
    for (const float v : test::lpvOf(pipeline).readGrid(true, level)) ASSERT_TRUE(std::isfinite(v)) << level;
  for (const NamedImage& image : pipeline.readOutputs())
    for (const float v : image.image.pixels) ASSERT_TRUE(std::isfinite(v)) << image.name;
}

}  // namespace
}  // namespace lpvlab

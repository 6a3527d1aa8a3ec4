// The work each stage reports (Pipeline::workReport, strategy.h's WorkCount), apart from time:
//   a. the units follow the frame's shape exactly: cell-iterations = cells x iterations x levels,
//      VPLs = RSM texels over every light view x levels, pixels = the output's; totals are
//      units x per-unit figures;
//   b. the per-unit figures follow the kernels run: the CPU's factored gather (3 x 36N) against
//      GL's (3 x 60N), more with SH order 2, more with the GV;
//   c. a strategy that does not model its work is listed as not counted, never as zero;
//   e. the GL kernels' work (the GPU estimate's input) is the GL backend's whatever the backend,
//      and scales with the grid's cells and the iterations as the counters say;
//   d. the sweep summary turns the report into work.<stage>.* columns.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sweep_support.h"
#include "lpv_support.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/sweep_summary.h"
#include "framework/core/atomic_file.h"
#include "framework/pipeline/pipeline.h"
#include "io/temp_dir.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

struct Report {
  nlohmann::json work;
  nlohmann::json gpuWork;  // the GL kernels' (Pipeline::workReport(true))
  double cells = 0.0;
  int levels = 1;
  int iterations = 0;
  int rsmResolution = 0;
  int width = 0, height = 0;
};

Report workOf(std::vector<std::string> overrides) {
  test::glTestContext();
  overrides.insert(overrides.end(), {"output.width=64", "output.height=48"});
  Experiment e = loadExperiment("", overrides);
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  Report r;
  r.work = pipeline.workReport();
  r.gpuWork = pipeline.workReport(true);
  r.cells = double(e.settings.grid.cellCount());
  r.levels = int(test::lpvOf(pipeline).levels().size());
  r.iterations = test::lpvOf(pipeline).strategies().propagation->iterations();
  r.width = e.settings.width;
  r.height = e.settings.height;
  r.rsmResolution = e.settings.rsmResolution;
  return r;
}

const nlohmann::json& only(const nlohmann::json& stage) {
  EXPECT_EQ(stage.size(), 1u) << stage.dump();
  return stage.at(0);
}

void expectTotals(const nlohmann::json& w) {
  EXPECT_DOUBLE_EQ(w.at("multiply_adds").get<double>(),
                   w.at("units").get<double>() * w.at("multiply_adds_per_unit").get<double>());
  EXPECT_DOUBLE_EQ(w.at("bytes").get<double>(),
                   w.at("units").get<double>() * w.at("bytes_per_unit").get<double>());
}

TEST(WorkReport, UnitsFollowTheFramesShape) {
  for (const std::vector<std::string>& o :
       {std::vector<std::string>{"propagation.iterations=7"},
        {"propagation.iterations=5", "cascades.levels=3"}}) {
    const Report r = workOf(o);
    const nlohmann::json& propagation = only(r.work.at("propagation"));
    EXPECT_EQ(propagation.at("unit"), "cell-iteration");
    EXPECT_DOUBLE_EQ(propagation.at("units").get<double>(), r.cells * r.iterations * r.levels);
    expectTotals(propagation);
    const nlohmann::json& injection = only(r.work.at("injection"));
    EXPECT_EQ(injection.at("unit"), "VPL");
    // The RSM's texels over every light view: the shadow maps count the same views.
    const double views = only(r.work.at("rsm")).at("units").get<double>() /
                         (double(r.rsmResolution) * r.rsmResolution);
    EXPECT_GE(views, 1.0);
    EXPECT_EQ(views, std::floor(views));
    EXPECT_DOUBLE_EQ(injection.at("units").get<double>(),
                     views * r.rsmResolution * r.rsmResolution * r.levels);
    expectTotals(injection);
    const nlohmann::json& indirect = only(r.work.at("indirect"));
    EXPECT_DOUBLE_EQ(indirect.at("units").get<double>(), double(r.width) * r.height * r.levels);
    EXPECT_DOUBLE_EQ(only(r.work.at("gbuffer")).at("units").get<double>(), double(r.width) * r.height);
    // Direct light: per pixel and light (the built-in Cornell box has one).
    const nlohmann::json& direct = only(r.work.at("direct"));
    EXPECT_EQ(direct.at("unit"), "pixel-light");
    EXPECT_DOUBLE_EQ(direct.at("units").get<double>(), double(r.width) * r.height);
    expectTotals(direct);
  }
}

TEST(WorkReport, PerUnitFiguresFollowTheKernelsRun) {
  const auto perCell = [](const std::vector<std::string>& o) {
    return only(workOf(o).work.at("propagation")).at("multiply_adds_per_unit").get<double>();
  };
  const double cpu = perCell({}), gl = perCell({"compute.backend=gl"});
  // On llvmpipe "auto" gathers on the CPU, which skips the order-1 terms that vanish on
  // axis-aligned faces: per direction the far face keeps 2 of 4, each of the 4 side faces 3, and
  // each of the 6 axis lobes 2; three channels.
  EXPECT_DOUBLE_EQ(cpu, 3 * (6 * (2 + 4 * 3) + 6 * 2));
  EXPECT_DOUBLE_EQ(gl, 3 * 60 * 4);
  EXPECT_DOUBLE_EQ(perCell({"compute.backend=gl", "grid.sh_order=2"}), 3 * 60 * 9);
  // The GV adds its transmittances (on the CPU, found once per frame: one product per face).
  EXPECT_DOUBLE_EQ(perCell({"occlusion.type=\"geometry_volume\""}), cpu + 3 * 30);
  EXPECT_GT(perCell({"occlusion.type=\"geometry_volume\"", "compute.backend=gl"}), gl);
  // Direct light's taps: 16 comparisons on the CPU, the texture unit's 36 on GL.
  const auto directPerPixel = [](const std::vector<std::string>& o) {
    return only(workOf(o).work.at("direct")).at("multiply_adds_per_unit").get<double>();
  };
  EXPECT_LT(directPerPixel({}), directPerPixel({"compute.backend=gl"}));
}

TEST(WorkReport, GpuWorkIsTheGlKernelsAndScalesWithTheGridAndTheIterations) {
  for (const std::string type : {"standard", "directed"}) {
    const std::string propagation = "propagation.type=\"" + type + "\"";
    const Report cpu = workOf({propagation});  // "auto": the CPU on llvmpipe
    const Report gl = workOf({propagation, "compute.backend=gl"});
    EXPECT_NE(cpu.work.at("propagation"), gl.work.at("propagation")) << type;
    EXPECT_EQ(cpu.gpuWork, gl.work) << type;
    EXPECT_EQ(gl.gpuWork, gl.work) << type;
    // About twice the cells per axis and twice the iterations: the propagation's work grows as
    // cells x iterations (16 times for a cubic grid), the same per cell-iteration.
    const auto reportOf = [&](const std::string& resolution, const std::string& iterations) {
      return workOf(
          {propagation, "grid.resolution=" + resolution, "propagation.iterations=" + iterations});
    };
    const Report small = reportOf("12", "5"), large = reportOf("24", "10");
    const double growth = (large.cells * large.iterations) / (small.cells * small.iterations);
    EXPECT_GT(growth, 12.0) << type;
    const nlohmann::json& a = only(small.gpuWork.at("propagation"));
    const nlohmann::json& b = only(large.gpuWork.at("propagation"));
    for (const char* total : {"units", "multiply_adds", "bytes"})
      EXPECT_DOUBLE_EQ(b.at(total).get<double>(), growth * a.at(total).get<double>())
          << type << " " << total;
    EXPECT_GT(a.at("multiply_adds").get<double>(), 0.0) << type;
  }
}

TEST(WorkReport, StrategiesWithoutAModelAreListedAsNotCounted) {
  const Report r = workOf({"rendering.type=\"subsurface\""});
  const nlohmann::json& indirect = r.work.at("indirect");
  ASSERT_EQ(indirect.size(), 1u);
  EXPECT_EQ(indirect.at(0).at("not_counted"), "subsurface");
  EXPECT_FALSE(indirect.at(0).contains("multiply_adds"));
}

// The glossy march counts its samples apart from the pixels' diffuse read: marchSamples per pixel,
// each a diffuse read without the slope.
TEST(WorkReport, TheGlossyMarchCountsItsSamples) {
  const Report r = workOf({"rendering.type=\"glossy\"", "rendering.specular_albedo=0.5",
                           "rendering.step=0.5", "rendering.max_distance=5"});
  const nlohmann::json& indirect = r.work.at("indirect");
  ASSERT_EQ(indirect.size(), 2u);
  EXPECT_EQ(indirect.at(0).at("unit"), "pixel");
  EXPECT_EQ(indirect.at(1).at("unit"), "march-sample");
  EXPECT_DOUBLE_EQ(indirect.at(1).at("units").get<double>(), double(r.width) * r.height * r.levels * 10);
  const double n = 4;  // order 1
  EXPECT_DOUBLE_EQ(indirect.at(1).at("multiply_adds_per_unit").get<double>(), 27 * n + 8);
  for (const nlohmann::json& w : indirect) expectTotals(w);
}

TEST(WorkReport, TheSweepSummaryHasWorkColumns) {
  test::TempDir dir;
  const Report r = workOf({});
  const nlohmann::json manifest = {{"work", r.work},
                                   {"timing", {{"samples", {{"stage_ms", {{"total", {1.0}}}}}}}}};
  std::filesystem::create_directories(dir.file("c0"));
  writeTextAtomically(dir.file("c0/manifest.json"), manifest.dump());
  test::writeSweepIndex(dir.path(), {"c0"});
  writeSweepSummary(dir.path().string());
  std::ifstream csv(dir.file("summary.csv"));
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  for (const char* column : {"work.propagation.cell-iterations", "work.propagation.multiply_adds",
                             "work.injection.VPLs", "work.indirect.pixels", "work.shadow_maps.texels"})
    EXPECT_NE(header.find(column), std::string::npos) << column << " in " << header;
  EXPECT_EQ(header.find("work.gbuffer.multiply_adds"), std::string::npos)
      << "the raster passes' arithmetic is not modelled, so it has no column";
  const double cellIterations = only(r.work.at("propagation")).at("units").get<double>();
  EXPECT_NE(row.find(nlohmann::json(cellIterations).dump()), std::string::npos) << row;
}

}  // namespace
}  // namespace lpvlab

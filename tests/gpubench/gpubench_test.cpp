// lpvlab-gpubench (framework/gpubench, variants/**/*_gpubench.cpp), on llvmpipe:
//   a. every registered case computes what the strategy's CPU kernels compute from the same
//      inputs: its checksum equals theirs (the strategy on the CPU backend, with the GV and its
//      albedo where the case has them) at SH orders 1-3, on a grid that cuts the kernels'
//      work groups part way; a case this test does not know fails it;
//   b. the executable, on precompiled SPIR-V, gives the checksums the GLSL compiled here gives
//      (the gathers bit for bit; scattering's float atomics add in any order);
//   c. the executable needs only the C and C++ runtimes (GL is opened at run time) and is, with its
//      SPIR-V, under 5 MB stripped;
//   d. bad options are one error line and exit 2.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "executable_support.h"
#include "framework/gpubench/gpu_bench_inputs.h"
#include "framework/gpubench/gpu_bench_runner.h"
#include "io/temp_dir.h"
#include "propagation_rig.h"
#include "rendering_rig.h"
#include "framework/pipeline/cascade.h"
#include "framework/pipeline/light_grid.h"
#include "variants/injection/rsm_vpl_cpu.h"
#include "variants/occlusion/geometry_volume_cpu.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

// The strategy configuration each case runs, as this test knows it.
struct Known {
  std::string method;  // standard's; empty for another strategy
  bool withGv = false;
  bool bounces = false;
  std::string strategy = "standard";
  double leakDamping = 0.0;  // rendering strategies ("trilinear")
};

const std::map<std::string, Known>& knownCases() {
  static const std::map<std::string, Known> cases{
      {"standard_gather", {"gather"}},
      {"standard_gather_tiled", {"gather"}},
      {"standard_scatter", {"scatter"}},
      {"standard_gather_gv", {"gather", true}},
      {"standard_gather_tiled_gv", {"gather", true}},
      {"standard_scatter_gv", {"scatter", true}},
      {"standard_gather_gv_bounces", {"gather", true, true}},
      {"standard_gather_tiled_gv_bounces", {"gather", true, true}},
      {"tetrahedral", {"", false, false, "tetrahedral"}},
      {"directed", {"", false, false, "directed"}},
      {"directed_gv", {"", true, false, "directed"}},
      {"directed_tiled", {"", false, false, "directed"}},
      {"directed_tiled_gv", {"", true, false, "directed"}},
      {"trilinear", {"", false, false, "trilinear"}},
      {"rsm_vpl", {"", false, false, "rsm_vpl"}},
      {"gv_camera", {"", false, false, "gv_camera"}},
      {"gv_camera_albedo", {"", false, true, "gv_camera"}},  // bounces: here, the albedo sums
      {"gv_light", {"", false, false, "gv_light"}},
      {"cascade_carry", {"", false, false, "cascade_carry"}},
      {"gv_merge", {"", false, false, "gv_merge"}},
      {"rsm_vpl_normals", {"", false, true, "rsm_vpl"}},  // bounces: here, the normal grid
      {"trilinear_leak_damping", {"", false, false, "trilinear", 1.0}},
      {"tetrahedral_gv", {"", true, false, "tetrahedral"}}};
  return cases;
}


// The CPU backend's checksum of the same rendering from `inputs`: the G-buffer's pixels in a row
// (the kernel is per pixel), the grid at the origin with cells 1 / resolution.x wide (as
// trilinear_gpubench.cpp places it).
double cpuRenderingChecksum(const Known& k, const GpuBenchShape& shape, const GpuBenchInputs& inputs) {
  test::HandGrid grid({glm::vec3(0.0f), 1.0f / float(shape.resolution.x), shape.resolution},
                      shape.shOrder);
  grid.data = benchInput(inputs, "accumulated");
  const std::vector<float>& p = benchInput(inputs, "position");
  const std::vector<float>& n = benchInput(inputs, "normal");
  const std::vector<float>& a = benchInput(inputs, "albedo");
  std::vector<test::SurfacePixel> pixels;
  for (std::size_t i = 0; i < p.size() / 4; ++i)
    pixels.push_back({{p[4 * i], p[4 * i + 1], p[4 * i + 2]},
                      {n[4 * i], n[4 * i + 1], n[4 * i + 2]},
                      {a[4 * i], a[4 * i + 1], a[4 * i + 2]}});
  toml::table table;
  table.insert("leak_damping", k.leakDamping);
  const std::vector<glm::dvec3> out = test::renderPixels(
      k.strategy, table, {grid}, pixels, glm::vec3(0.5f, 0.5f, -1.0f), 0.0f, ComputeBackend::Cpu);
  std::vector<float> rgb;
  for (const glm::dvec3& v : out)
    for (int c = 0; c < 3; ++c) rgb.push_back(float(v[c]));
  return benchChecksum(rgb);
}

HostImage hostImage(const std::vector<float>& rgba, const glm::ivec2& size) {
  HostImage out{size.x, size.y, 1, {}};
  for (std::size_t i = 0; i < rgba.size(); i += 4)
    out.texels.emplace_back(rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]);
  return out;
}

// The CPU kernel's checksum of the same injection from `inputs`: one view's RSM of image.x texels
// square, into a zero grid at the origin with cells 1 / resolution.x wide (as
// rsm_vpl_gpubench.cpp places it), with the normal grid when the case has it.
double cpuInjectionChecksum(bool withNormals, const GpuBenchShape& shape,
                            const GpuBenchInputs& inputs) {
  auto image = [&](const char* name) {
    return hostImage(benchInput(inputs, name), {shape.image.x, shape.image.x});
  };
  const HostImage position = image("rsm_position"), normal = image("rsm_normal"),
                  flux = image("rsm_flux");
  const int coefficients = (shape.shOrder + 1) * (shape.shOrder + 1);
  const std::size_t cells = std::size_t(shape.resolution.x) * shape.resolution.y * shape.resolution.z;
  std::vector<float> grid(3 * coefficients * cells, 0.0f), normals(4 * cells, 0.0f);
  injectRsmVplsCpu({&position, &normal, &flux},
                   {glm::vec3(0.0f), 1.0f / float(shape.resolution.x), shape.resolution},
                   coefficients, 1.0f, grid.data(), withNormals ? normals.data() : nullptr);
  return benchChecksum(grid) + (withNormals ? benchChecksum(normals) : 0.0);
}

// The CPU kernel's checksum of the same GV from the camera's surfels: the GV of a light grid at the
// origin with cells 1 / resolution.x wide, the camera at (0.5, 0.5, -1) with a 60-degree vertical
// field of view (as geometry_volume_gpubench.cpp sets them).
double cpuGvChecksum(bool withAlbedo, const GpuBenchShape& shape, const GpuBenchInputs& inputs) {
  const HostImage position = hostImage(benchInput(inputs, "position"), shape.image),
                  normal = hostImage(benchInput(inputs, "normal"), shape.image),
                  albedo = hostImage(benchInput(inputs, "albedo"), shape.image);
  const float cell = 1.0f / float(shape.resolution.x);
  const GridGeometry gv{glm::vec3(-0.5f * cell), cell, shape.resolution + 1};
  std::vector<float> blocking(4 * std::size_t(gv.cellCount()), 0.0f), sums(blocking.size(), 0.0f);
  const float texelEdge = float(2.0 * std::tan(0.5 * M_PI / 3.0) / shape.image.y);
  addCameraSurfelsCpu({&position, &normal, &albedo}, glm::vec3(0.5f, 0.5f, -1.0f), texelEdge,
                      {.gv = gv, .blocking = blocking.data(),
                       .albedo = withAlbedo ? sums.data() : nullptr});
  return benchChecksum(blocking) + (withAlbedo ? benchChecksum(sums) : 0.0);
}

// The same from a light view's RSM surfels: the view buildLightViews gives a directional light
// along (-0.3, -1, -0.2) over the light grid's box (as geometry_volume_gpubench.cpp sets it).
double cpuGvLightChecksum(const GpuBenchShape& shape, const GpuBenchInputs& inputs) {
  const glm::ivec2 side(shape.image.x);
  const HostImage position = hostImage(benchInput(inputs, "position"), side),
                  normal = hostImage(benchInput(inputs, "normal"), side),
                  flux = hostImage(benchInput(inputs, "albedo"), side);
  const float cell = 1.0f / float(shape.resolution.x);
  const GridGeometry gv{glm::vec3(-0.5f * cell), cell, shape.resolution + 1};
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
  const LightViews records =
      buildLightViews({sun}, {glm::vec3(0.0f), glm::vec3(shape.resolution) * cell});
  std::vector<float> blocking(4 * std::size_t(gv.cellCount()), 0.0f);
  addRsmSurfelsCpu({&position, &normal, &flux}, records, {.gv = gv, .blocking = blocking.data()});
  return benchChecksum(blocking);
}

// The CPU carry's checksum of the same levels: the parent of the shape's resolution rounded down to
// a multiple of 4 with cells 1 / resolution.x wide, the child at half the cell size from parent
// cell resolution / 4 (as cascade_gpubench.cpp places them).
double cpuCarryChecksum(const GpuBenchShape& shape, const GpuBenchInputs& inputs) {
  const glm::ivec3 res = glm::max(glm::ivec3(4), shape.resolution / 4 * 4);
  const float cell = 1.0f / float(shape.resolution.x);
  LightGrid parent(GridGeometry{glm::vec3(0.0f), cell, res}, shape.shOrder);
  LightGrid child(GridGeometry{glm::vec3(res / 4) * cell, 0.5f * cell, res}, shape.shOrder);
  parent.current.host() = benchInput(inputs, "parent");
  child.current.host() = benchInput(inputs, "child");
  ShaderCompiler shaders;
  CascadeCarry(shaders, shape.shOrder, true).carry(child, parent);
  return benchChecksum(parent.current.hostRead());
}

// The CPU merge's checksum of the same two GVs with their albedo sums.
double cpuMergeChecksum(const GpuBenchInputs& inputs) {
  std::vector<float> target = benchInput(inputs, "target"), albedo = benchInput(inputs, "target_albedo");
  mergeGeometryVolumesCpu(target.data(), benchInput(inputs, "other").data(), int(target.size() / 4),
                          albedo.data(), benchInput(inputs, "other_albedo").data());
  return benchChecksum(target) + benchChecksum(albedo);
}

// The CPU backend's checksum of the same propagation (or rendering, or injection) from `inputs`.
double cpuChecksum(const Known& k, const GpuBenchShape& shape, const GpuBenchInputs& inputs) {
  if (k.strategy == "gv_merge") return cpuMergeChecksum(inputs);
  if (k.strategy == "cascade_carry") return cpuCarryChecksum(shape, inputs);
  if (k.strategy == "gv_light") return cpuGvLightChecksum(shape, inputs);
  if (k.strategy == "gv_camera") return cpuGvChecksum(k.bounces, shape, inputs);
  if (k.strategy == "rsm_vpl") return cpuInjectionChecksum(k.bounces, shape, inputs);
  if (k.strategy == "trilinear") return cpuRenderingChecksum(k, shape, inputs);
  toml::table table = test::iterationsTable(shape.iterations, k.method);
  if (k.bounces) table.insert("bounces", true);
  test::PropagationRig rig(k.strategy, shape.resolution, table, shape.shOrder, k.withGv,
                           ComputeBackend::Cpu);
  rig.load(benchInput(inputs, "current"), benchInput(inputs, "accumulated"));
  if (k.withGv) rig.loadGv(benchInput(inputs, "gv"), 1);
  if (k.bounces) rig.loadAlbedo(benchInput(inputs, "albedo"));
  if (k.strategy == "directed") rig.loadNormals(benchInput(inputs, "normals"));
  rig.propagate();
  return benchChecksum(rig.accumulated()) + benchChecksum(rig.current());
}

// 4^3 groups, 32x4 and 16x4 tiles and 8-plane spans cut part way, several tiles along each axis.
// The image of the rendering cases: 2,048 pixels (one row of them in the CPU rig).
const GpuBenchShape kShape{{37, 9, 11}, 1, 3, {64, 32}};

TEST(GpuBench, EveryCaseComputesWhatTheCpuKernelsCompute) {
  test::glTestContext();
  ShaderCompiler shaders;
  ASSERT_FALSE(gpuBenchCases().empty());
  for (const auto& [name, entry] : gpuBenchCases()) {
    ASSERT_TRUE(knownCases().contains(name)) << name << ": a case this test does not know";
    for (int order = 1; order <= 3; ++order) {
      GpuBenchShape shape = kShape;
      shape.shOrder = order;
      std::unique_ptr<GpuBenchCase> bench = entry.make();
      bench->prepare(shaders, shape);
      bench->reset();
      bench->run();
      const double gl = bench->checksum();
      const double cpu = cpuChecksum(knownCases().at(name), shape, bench->inputs());
      EXPECT_NEAR(gl, cpu, 1e-5 * std::abs(cpu)) << name << ", order " << order;
      // The propagation did something: the inputs' own checksum is far from it.
      // What the outputs' checksum was before the kernel ran: the grids' for propagation, the
      // parent's for the carry, zero for the outputs that start at zero.
      const std::string& strategy = knownCases().at(name).strategy;
      const GpuBenchInputs& in = bench->inputs();
      const double before =
          strategy == "cascade_carry" ? benchChecksum(benchInput(in, "parent"))
          : strategy == "gv_merge"
              ? benchChecksum(benchInput(in, "target")) + benchChecksum(benchInput(in, "target_albedo"))
          : strategy == "trilinear" || strategy == "rsm_vpl" || strategy.starts_with("gv_")
              ? 0.0
              : benchChecksum(benchInput(in, "accumulated")) + benchChecksum(benchInput(in, "current"));
      EXPECT_GT(std::abs(gl - before), 1e-3 * std::max(std::abs(before), 1.0))
          << name << ", order " << order;
    }
  }
}

fs::path gpubenchExecutable() { return test::lpvlabExecutable().parent_path() / "lpvlab-gpubench"; }

TEST(GpuBench, TheExecutableOnPrecompiledSpirvGivesTheseChecksums) {
  test::TempDir dir;
  const test::LpvlabResult r = test::runExecutable(
      gpubenchExecutable(),
      "--grids 10 --orders 2 --iterations 3 --image 16 --warmup 0 --repeats 2 --backend osmesa "
      "--json out.json",
      dir.path(), dir.path());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json json = nlohmann::json::parse(test::readFile(dir.path() / "out.json"));
  EXPECT_EQ(json["timing"]["clock"], "gl_timer_query");
  EXPECT_EQ(json["timing"]["repeats"], 2);
  ASSERT_EQ(json["results"].size(), gpuBenchCases().size());
  test::glTestContext();
  ShaderCompiler shaders;
  for (const nlohmann::json& row : json["results"]) {
    const std::string name = row["case"];
    ASSERT_TRUE(gpuBenchCases().contains(name)) << name;
    const GpuBenchShape shape{glm::ivec3(10), 2, 3, glm::ivec2(16)};
    const GpuBenchResult here = runGpuBench(name, gpuBenchCases().at(name), shaders, shape, 0, 1);
    // Float atomics (scattering, injection) add in any order.
    const bool atomics = knownCases().at(name).method == "scatter" ||
                         knownCases().at(name).strategy == "rsm_vpl" ||
                         knownCases().at(name).strategy.starts_with("gv_");
    const double tolerance = atomics ? 1e-6 * std::abs(here.checksum) : 0.0;
    EXPECT_NEAR(row["checksum"].get<double>(), here.checksum, tolerance) << name;
    EXPECT_GT(row["units_per_s"].get<double>(), 0.0) << name;
    const double units = row["unit"] == "cell-iteration" ? 1000.0 * 3
                         : row["unit"] == "parent-cell" ? 4.0 * 4 * 4  // half of 8^3
                         : row["unit"] == "gv-cell"     ? 11.0 * 11 * 11
                                                        : 16.0 * 16;
    EXPECT_EQ(row["units"].get<double>(), units) << name;
    EXPECT_NE(r.out.find(name), std::string::npos) << "no row for " << name;
  }
}

std::size_t bytesUnder(const fs::path& dir) {
  std::size_t bytes = 0;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) bytes += e.file_size();
  return bytes;
}

TEST(GpuBench, NeedsOnlyTheRuntimesAndIsUnderFiveMegabytesStripped) {
  test::TempDir dir;
  const fs::path exe = gpubenchExecutable();
  const std::string stripped = (dir.path() / "lpvlab-gpubench").string();
  ASSERT_EQ(std::system(("strip -o " + test::quoted(stripped) + " " + test::quoted(exe.string())).c_str()), 0);
  const std::size_t bytes = fs::file_size(stripped) + bytesUnder(exe.parent_path() / "spirv");
  std::cout << "lpvlab-gpubench stripped with its SPIR-V: " << bytes << " bytes\n";
  EXPECT_LT(bytes, 5u * 1000 * 1000);
  const fs::path needed = dir.path() / "needed.txt";
  ASSERT_EQ(std::system(("readelf -d " + test::quoted(exe.string()) + " > " +
                         test::quoted(needed.string())).c_str()), 0);
  std::istringstream lines(test::readFile(needed));
  const std::set<std::string> allowed{"libstdc++.so.6", "libm.so.6", "libgcc_s.so.1", "libc.so.6"};
  int count = 0;
  for (std::string line; std::getline(lines, line);) {
    const auto open = line.find("Shared library: ["), close = line.rfind(']');
    if (open == std::string::npos) continue;
    const std::string library = line.substr(open + 17, close - open - 17);
    EXPECT_TRUE(allowed.contains(library)) << "lpvlab-gpubench needs " << library;
    ++count;
  }
  EXPECT_GT(count, 0);
}

TEST(GpuBench, BadOptionsAreOneErrorAndExitTwo) {
  test::TempDir dir;
  for (const char* args : {"--grids 0", "--orders 4", "--cases standard_nosuch", "--frobnicate"}) {
    const test::LpvlabResult r =
        test::runExecutable(gpubenchExecutable(), args, dir.path(), dir.path());
    EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("lpvlab-gpubench: error: ", 0), 0u) << args << ": " << r.err;
  }
  const test::LpvlabResult r = test::runExecutable(gpubenchExecutable(), "--cases standard_nosuch",
                                                   dir.path(), dir.path());
  EXPECT_NE(r.err.find("standard_gather"), std::string::npos) << "the known cases are listed";
}

}  // namespace
}  // namespace lpvlab

// Sky injection ("sky_columns", shaders/injection/sky_columns.{comp,glsl}) on tiny hand-made
// scenes and on the Cornell box:
//   - an open floor receives exactly the flux pi L * (its area) (a constant sky of radiance L
//     gives irradiance pi L on a horizontal face), as a downward Lambertian lobe, one layer up;
//   - a roof shades the floor under it: those columns get nothing below the roof;
//   - the thesis's fill (every free cell up to the grid's top) puts pi L s^2 into each of them;
//   - the whole grid equals a double-precision C++ injection of ray-cast columns (independent of
//     rasterisation) through the shared sky_columns.glsl;
//   - very dim and very bright skies stay finite and proportional;
//   - a sky without a sky-injecting strategy is refused, naming [sky] radiance;
//   - end to end: a sky-lit Cornell box without its ceiling renders finite, non-zero indirect light.

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <toml++/toml.h>

#include "lpv_support.h"
#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/experiment/experiment.h"
#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/composition.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/pipeline.h"
#include "framework/pipeline/scene_gpu.h"
#include "variants/resources/sky_light.h"
#include "framework/pipeline/strategy.h"
#include "stand_in_requirements.h"
#include "pipeline_test_support.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/injection/sky_columns.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using Grid = std::vector<float>;

// A horizontal rectangle [x0, x1] x [z0, z1] at height y, facing up.
void addHorizontalQuad(Scene& scene, float x0, float x1, float z0, float z1, float y) {
  Mesh mesh;
  mesh.name = "quad" + std::to_string(scene.meshes.size());
  mesh.positions = {{x0, y, z0}, {x0, y, z1}, {x1, y, z1}, {x1, y, z0}};
  mesh.normals.assign(4, glm::vec3(0, 1, 0));
  mesh.uvs.assign(4, glm::vec2(0.0f));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = 0;
  scene.meshes.push_back(std::move(mesh));
}

Scene sceneOf(const std::vector<std::array<float, 5>>& quads) {
  Scene scene;
  scene.source = "sky injection test";
  scene.materials.push_back(Material{.name = "white"});
  for (const auto& q : quads) addHorizontalQuad(scene, q[0], q[1], q[2], q[3], q[4]);
  return scene;
}

// Cells of 0.1 m; the grid spans x in [-0.1, 0.9], y in [-0.1, 0.5], z in [-0.1, 0.7].
const GridGeometry kGrid{glm::vec3(-0.1f), 0.1f, glm::ivec3(10, 6, 8)};

// sky_columns created as an experiment creates it, injecting into its own light grid.
class SkyRig {
public:
  SkyRig(const Scene& scene, int shOrder, int texelsPerCell = 4, float shift = 1.0f,
         ComputeBackend backend = ComputeBackend::Gl, const std::string& fill = "lowest_free_cell")
      : scene_(scene) {
    table_.insert("type", "sky_columns");
    table_.insert("texels_per_cell", texelsPerCell);
    table_.insert("shift", double(shift));
    table_.insert("fill", fill);
    Params params(table_, "sky injection test", "injection");
    strategy_ = Registry<InjectionStrategy>::instance().create(params, "rsm_vpl");
    params.finish();
    requirements_ = test::standInRequirements(*strategy_, shOrder, {std::string(kSkyLight.name)});
    requirements_.backend = backend;
    EXPECT_TRUE(requirements_.has(kSkyLight));
    EXPECT_GE(strategy_->maxShOrder(), shOrder);
    grid_ = LightGrid(kGrid, shOrder);
  }

  // Prepared for a run with this sky (the run's constant, which prepare() sees), then injected.
  Grid inject(glm::vec3 sky) {
    strategy_->prepare({.shaders = shaders_,
                        .grid = kGrid,
                        .requirements = requirements_,
                        .scene = &scene_,
                        .skyRadiance = sky});
    grid_.current.zero();
    Frame frame{.scene = &scene_,
                .gbuffer = gbuffer_,
                .lightMaps = lightMaps_,
                .lightGrid = grid_,
                .indirect = indirect_};
    strategy_->inject(frame);
    checkGl("sky injection test");
    Grid data(grid_.floatsPerGrid());
    grid_.current.download(data.data(), data.size() * sizeof(float));
    return data;
  }
  int coefficients() const { return grid_.coefficients; }

private:
  struct Context {  // first member: the scene's GL buffers need the context
    Context() { test::glTestContext(); }
  } context_;
  SceneGpu scene_;
  toml::table table_;
  ShaderCompiler shaders_;
  std::unique_ptr<InjectionStrategy> strategy_;
  Requirements requirements_;
  LightGrid grid_;
  GBuffer gbuffer_;  // sky injection reads none of these
  LightMaps lightMaps_;
  DualImage indirect_;
};

std::size_t at(int coefficients, const glm::ivec3& cell, int channel, int k) {
  return std::size_t(shared::coefficientIndex(channel, k, coefficients,
                                              shared::cellIndex(cell, kGrid.resolution),
                                              kGrid.cellCount()));
}

// Flux of one channel: the sphere integral of every cell's intensity.
double channelFlux(const Grid& grid, int coefficients, int channel) {
  double flux = 0.0;
  for (int cell = 0; cell < kGrid.cellCount(); ++cell)
    flux += shared::shIntegralOfC0(
        grid[shared::coefficientIndex(channel, 0, coefficients, cell, kGrid.cellCount())]);
  return flux;
}

double columnLayerFlux(const Grid& grid, int coefficients, int x, int y, int z, int channel) {
  return shared::shIntegralOfC0(grid[at(coefficients, {x, y, z}, channel, 0)]);
}

TEST(SkyInjection, OpenFloorReceivesPiLTimesItsAreaAsADownwardLobe) {
  // Edges off the texel grid (texels of 0.025 m): coverage is decided at texel centres, so the
  // covered area differs from the true one by at most half a texel along the perimeter.
  const float x0 = 0.013f, x1 = 0.787f, z0 = 0.021f, z1 = 0.608f, y = 0.03f;
  const Scene scene = sceneOf({{x0, x1, z0, z1, y}});
  SkyRig rig(scene, 3);
  const glm::vec3 sky(1.0f, 0.5f, 0.25f);
  const Grid grid = rig.inject(sky);
  const int n = rig.coefficients();
  const double area = double(x1 - x0) * double(z1 - z0);
  const double texel = 0.1 / 4.0;
  const double areaTolerance = 0.5 * texel * 2.0 * (double(x1 - x0) + double(z1 - z0));
  for (int channel = 0; channel < 3; ++channel) {
    const double expected = M_PI * sky[channel] * area;
    const double flux = channelFlux(grid, n, channel);
    std::cout << "[ sky ] channel " << channel << ": grid flux " << flux << " W, pi L A "
              << expected << " W\n";
    EXPECT_NEAR(flux, expected, M_PI * sky[channel] * areaTolerance);
  }
  // All of it one cell above the floor's layer (y = 0.03 is in layer 1, so layer 2), as the
  // downward lobe: every coefficient in proportion to the clamped cosine about -y.
  const int layer = 2;
  for (int z = 0; z < kGrid.resolution.z; ++z)
    for (int x = 0; x < kGrid.resolution.x; ++x)
      for (int cy = 0; cy < kGrid.resolution.y; ++cy) {
        const double c0 = grid[at(n, {x, cy, z}, 0, 0)];
        if (cy != layer) {
          EXPECT_EQ(c0, 0.0) << "cell " << x << "," << cy << "," << z;
          continue;
        }
        for (int k = 1; k < n; ++k)
          EXPECT_NEAR(grid[at(n, {x, cy, z}, 0, k)],
                      c0 * shared::skyDownwardLobeAt(k) / shared::skyDownwardLobeAt(0),
                      1e-6 * std::abs(c0) + 1e-12)
              << "cell " << x << "," << z << " coefficient " << k;
      }
  // An interior column: a whole cell top of sky, pi L s^2.
  EXPECT_NEAR(columnLayerFlux(grid, n, 4, layer, 3, 0), M_PI * sky[0] * 0.01, 1e-6);
}

TEST(SkyInjection, ARoofShadesTheColumnsUnderIt) {
  // Floor over columns x 1..8, z 1..6; roof at y = 0.33 (layer 4) over columns x 4..5, z 3..4.
  const Scene scene = sceneOf({{0.0f, 0.8f, 0.0f, 0.6f, 0.03f}, {0.3f, 0.5f, 0.2f, 0.4f, 0.33f}});
  SkyRig rig(scene, 1);
  const Grid grid = rig.inject(glm::vec3(2.0f));
  const int n = rig.coefficients();
  for (int x = 4; x <= 5; ++x)
    for (int z = 3; z <= 4; ++z) {
      for (int y = 0; y <= 4; ++y)
        EXPECT_EQ(columnLayerFlux(grid, n, x, y, z, 0), 0.0) << "under the roof: " << x << "," << y << "," << z;
      EXPECT_NEAR(columnLayerFlux(grid, n, x, 5, z, 0), M_PI * 2.0 * 0.01, 1e-6);  // on the roof
    }
  // Beside the roof the floor is lit; the total is still the sky over the floor's outline.
  EXPECT_NEAR(columnLayerFlux(grid, n, 3, 2, 3, 0), M_PI * 2.0 * 0.01, 1e-6);
  EXPECT_NEAR(channelFlux(grid, n, 0), M_PI * 2.0 * 0.8 * 0.6, 1e-5);
}

// The thesis's fill: the light of a texel in every cell from the lowest free one up to the grid's
// top, pi L s^2 in each cell of an open column (not normalised: the column holds it once a cell).
TEST(SkyInjection, TheThesisFillPutsTheLightIntoEveryFreeCellAboveTheSurface) {
  // The roof scene: floor in layer 0 (lit from layer 2: y = 0.03 is layer 1), roof in layer 4.
  const Scene scene = sceneOf({{0.0f, 0.8f, 0.0f, 0.6f, 0.03f}, {0.3f, 0.5f, 0.2f, 0.4f, 0.33f}});
  for (const ComputeBackend backend : {ComputeBackend::Gl, ComputeBackend::Cpu}) {
    SkyRig rig(scene, 1, 4, 1.0f, backend, "every_free_cell");
    const Grid grid = rig.inject(glm::vec3(2.0f));
    const int n = rig.coefficients();
    const double cellTop = M_PI * 2.0 * 0.01;  // pi L s^2
    for (int y = 0; y < kGrid.resolution.y; ++y) {
      EXPECT_NEAR(columnLayerFlux(grid, n, 3, y, 3, 0), y >= 2 ? cellTop : 0.0, 1e-6) << "open column, layer " << y;
      EXPECT_NEAR(columnLayerFlux(grid, n, 4, y, 3, 0), y >= 5 ? cellTop : 0.0, 1e-6) << "roofed column, layer " << y;
    }
    // The floor's 48 columns: 4 layers each, but the 4 under the roof 1 layer.
    EXPECT_NEAR(channelFlux(grid, n, 0), cellTop * (44 * 4 + 4 * 1), 1e-5);
  }
}

// The injection in double precision from ray-cast columns: a vertical ray down through every
// texel centre from the grid's top, its first hit's height through the shared functions, into the
// injection cell or (everyFreeCell, the thesis's fill) every cell from there up.
Grid raycastInjection(const Scene& scene, glm::dvec3 sky, int texelsPerCell, double shift, int n,
                      bool everyFreeCell = false) {
  const test::SceneRaycaster raycaster(scene);
  Grid grid(std::size_t(3) * n * kGrid.cellCount(), 0.0f);
  std::vector<double> sum(grid.size(), 0.0);
  const double s = kGrid.cellSize, texel = s / texelsPerCell;
  const double top = double(kGrid.origin.y) + kGrid.resolution.y * s;
  const double height = kGrid.resolution.y * s;
  for (int j = 0; j < kGrid.resolution.z * texelsPerCell; ++j)
    for (int i = 0; i < kGrid.resolution.x * texelsPerCell; ++i) {
      const glm::dvec3 origin(kGrid.origin.x + (i + 0.5) * texel, top, kGrid.origin.z + (j + 0.5) * texel);
      const auto hit = raycaster.cast(origin, glm::dvec3(0, -1, 0), 0.0);
      if (!hit || hit->t >= height) continue;
      const double depth = hit->t / height;
      const double y = shared::skySurfaceHeight(depth, top, height);
      const glm::ivec3 cell(i / texelsPerCell,
                            shared::skyInjectionLayer(y, shift, kGrid.origin.y, s, kGrid.resolution.y),
                            j / texelsPerCell);
      const int top = everyFreeCell ? kGrid.resolution.y - 1 : cell.y;
      for (int layer = cell.y; layer <= top; ++layer)
        for (int k = 0; k < n; ++k)
          for (int c = 0; c < 3; ++c)
            sum[at(n, {cell.x, layer, cell.z}, c, k)] += sky[c] * texel * texel * shared::skyDownwardLobeAt(k);
    }
  for (std::size_t i = 0; i < grid.size(); ++i) grid[i] = float(sum[i]);
  return grid;
}

TEST(SkyInjection, GpuGridMatchesRayCastColumnsInDoublePrecision) {
  // Steps at several heights (none near a layer boundary, edges off texel centres), one of them
  // above the top layer's lower boundary so the shift is clamped there, at SH order 2.
  const Scene scene = sceneOf({{-0.04f, 0.87f, -0.06f, 0.66f, -0.07f},
                               {0.112f, 0.388f, 0.09f, 0.51f, 0.17f},
                               {0.52f, 0.77f, 0.33f, 0.64f, 0.255f},
                               {0.6f, 0.71f, 0.013f, 0.2f, 0.462f}});
  const glm::vec3 sky(0.7f, 1.3f, 0.2f);
  for (const int texels : {1, 3}) {
    for (const float shift : {0.0f, 1.0f, 2.5f}) {
      const bool every = shift == 1.0f;  // the thesis's fill at one shift
      SkyRig rig(scene, 2, texels, shift, ComputeBackend::Gl, every ? "every_free_cell" : "lowest_free_cell");
      const Grid gpu = rig.inject(sky);
      const Grid cpu = raycastInjection(scene, glm::dvec3(sky), texels, shift, rig.coefficients(), every);
      ASSERT_EQ(gpu.size(), cpu.size());
      double largest = 0.0;
      for (float v : cpu) largest = std::max(largest, double(std::abs(v)));
      ASSERT_GT(largest, 0.0);
      for (std::size_t i = 0; i < gpu.size(); ++i)
        ASSERT_NEAR(gpu[i], cpu[i], 1e-5 * largest)
            << "texels_per_cell " << texels << ", shift " << shift << ", grid index " << i;
    }
  }
}

// The CPU backend's kernel (sky_columns_cpu.h) against the same ray-cast model, at every order,
// and its grid bit for bit across thread counts.
TEST(SkyInjection, CpuGridMatchesRayCastColumnsAndDoesNotDependOnTheThreadCount) {
  const Scene scene = sceneOf({{-0.04f, 0.87f, -0.06f, 0.66f, -0.07f},
                               {0.112f, 0.388f, 0.09f, 0.51f, 0.17f},
                               {0.52f, 0.77f, 0.33f, 0.64f, 0.255f}});
  const glm::vec3 sky(0.7f, 1.3f, 0.2f);
  for (int order = 1; order <= 3; ++order)
    for (const float shift : {0.0f, 1.0f, 2.5f}) {
      const bool every = order == 2;  // the thesis's fill at one order
      SkyRig rig(scene, order, 3, shift, ComputeBackend::Cpu, every ? "every_free_cell" : "lowest_free_cell");
      const Grid onCpu = rig.inject(sky);
      const Grid model = raycastInjection(scene, glm::dvec3(sky), 3, shift, rig.coefficients(), every);
      double largest = 0.0;
      for (float v : model) largest = std::max(largest, double(std::abs(v)));
      ASSERT_GT(largest, 0.0);
      for (std::size_t i = 0; i < onCpu.size(); ++i)
        ASSERT_NEAR(onCpu[i], model[i], 1e-5 * largest) << "order " << order << " shift " << shift;
      Grid single;
      {
        const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        single = rig.inject(sky);
      }
      EXPECT_EQ(single, onCpu);
    }
}

TEST(SkyInjection, DimAndBrightSkiesStayFiniteAndProportional) {
  const Scene scene = sceneOf({{0.0f, 0.8f, 0.0f, 0.6f, 0.03f}});
  SkyRig rig(scene, 1);
  const double area = 0.8 * 0.6;
  for (const float radiance : {1e-6f, 1.0f, 1e6f}) {
    const Grid grid = rig.inject(glm::vec3(radiance));
    for (float v : grid) ASSERT_TRUE(std::isfinite(v));
    EXPECT_NEAR(channelFlux(grid, rig.coefficients(), 1), M_PI * radiance * area,
                1e-5 * M_PI * radiance * area);
  }
  // No sky: nothing injected.
  for (float v : rig.inject(glm::vec3(0.0f))) ASSERT_EQ(v, 0.0f);
}

std::vector<std::string> smallRun() {
  return {"output.width=64", "output.height=64", "light_maps.rsm_resolution=64",
          "light_maps.shadow_resolution=128", "timing.warmup=0", "timing.repeats=1"};
}

TEST(SkyInjection, ASkyWithoutSkyInjectionIsRefusedNamingTheSkyRadiance) {
  std::vector<std::string> overrides = smallRun();
  overrides.push_back("sky.radiance=[0.0, 0.0, 1.0]");
  try {
    loadExperiment("", overrides);
    FAIL() << "a sky without sky injection was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("[sky] radiance"), std::string::npos) << error.what();
  }
  overrides.push_back("injection.also=[{type = \"sky_columns\"}]");
  const Experiment e = loadExperiment("", overrides);
  ASSERT_EQ(test::lpvStrategies(e).injection.size(), 2u);
  EXPECT_EQ(test::lpvStrategies(e).injection[1]->name(), "sky_columns");
  // A zero sky needs no sky injection.
  EXPECT_NO_THROW(loadExperiment("", smallRun()));
}

TEST(SkyInjection, SkyLitOpenCornellBoxRendersFiniteIndirectLight) {
  test::glTestContext();
  std::vector<std::string> overrides = smallRun();
  overrides.insert(overrides.end(), {"sky.radiance=[1.0, 1.0, 1.0]",
                                     "injection.also=[{type = \"sky_columns\"}]",
                                     "propagation.iterations=8"});
  Experiment e = loadExperiment("", overrides);
  Scene& scene = e.scene;  // the box without its ceiling
  ASSERT_EQ(std::erase_if(scene.meshes, [](const Mesh& mesh) { return mesh.name == "ceiling"; }), 1u);
  ShaderCompiler shaders;
  Pipeline pipeline(scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  const InjectionBalance balance = test::lpvOf(pipeline).measureInjection();
  // The grid holds the RSM's flux (the whole box is inside it) plus the sky's through the open
  // top (floor and block tops), each reported for its own injection table.
  ASSERT_EQ(balance.byInjection.size(), 2u);
  EXPECT_EQ(balance.byInjection[0].first, "injection");
  EXPECT_EQ(balance.byInjection[1].first, "injection.also[0]");
  EXPECT_NEAR(balance.byInjection[0].second, balance.rsmFlux, 1e-4 * balance.rsmFlux);
  const double skyFlux = balance.byInjection[1].second;
  EXPECT_NEAR(balance.gridFlux, balance.rsmFlux + skyFlux, 1e-4 * balance.gridFlux);
  std::cout << "[ sky ] open box: sky flux in the grid " << skyFlux << " W (3 channels)\n";
  EXPECT_GT(skyFlux, 0.0);
  // At most the sky over the grid's whole top, 3 channels of pi L (x extent) (z extent).
  EXPECT_LE(skyFlux, 3.0 * M_PI * e.settings.grid.extent().x * e.settings.grid.extent().z);
  double indirect = 0.0;
  for (const NamedImage& image : pipeline.readOutputs())
    if (image.name == "indirect")
      for (float v : image.image.pixels) {
        ASSERT_TRUE(std::isfinite(v));
        indirect += v;
      }
  EXPECT_GT(indirect, 0.0);
}

}  // namespace
}  // namespace lpvlab

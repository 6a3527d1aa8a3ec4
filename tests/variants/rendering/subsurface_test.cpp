// The subsurface-scattering LPV (rendering "subsurface", variants/rendering/subsurface.{h,cpp};
// thesis 5.4), on a hand-made scene: an opaque floor, a translucent box on it, a sun straight
// down, a camera looking at the box from above and in front.
//   a. a scene without translucent materials gets exactly nothing (the indirect image unchanged);
//   b. injection: only translucent surfaces inject, their whole transmitted flux (the RSM holds
//      transmittance * E * (top area), the grid holds the RSM's flux), as lobes pointing INTO the
//      object (band-1 coefficients along -y under a sun straight down);
//   c. attenuation: from one VPL in an open grid, the light after k steps (and the accumulated
//      sum) is a^k times standard propagation's, a = exp(-sigma s);
//   d. the GPU's attenuated step against the double-precision C++ transfer (standard_faces.glsl)
//      on a random grid, and the GPU's shading against C++ (trilinear_weights.glsl and
//      subsurface.glsl) from the downloaded grid and G-buffer;
//   e. pixels of opaque surfaces (by ray casting, independent of the strategy's camera mask) keep
//      exactly what the indirect image held; translucent ones gain light.
// Every test runs on both backends (the CPU: subsurface_cpu.h and the standard CPU kernel).

#include <cmath>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "framework/core/parameters.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/solid_angle.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/light_views.h"
#include "framework/pipeline/raster_passes.h"
#include "framework/pipeline/scene_gpu.h"
#include "propagation_rig.h"
#include "variants/rendering/subsurface.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/rendering/trilinear_weights.glsl"
#include "shaders/subsurface/subsurface.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using namespace test;

constexpr double kSun = 2.0;                       // W/m^2 on a surface facing it
const glm::vec3 kTransmittance{0.5f, 0.3f, 0.2f};  // of the box
constexpr float kExtinction = 4.0f;                // 1/m
// The box: x in [-0.2, 0.2], y in [0, 0.2], z in [-0.15, 0.15].
const glm::vec3 kBoxMin{-0.2f, 0.0f, -0.15f}, kBoxMax{0.2f, 0.2f, 0.15f};
constexpr double kTopArea = 0.4 * 0.3;
constexpr int kWidth = 96, kHeight = 96;
constexpr float kPrefill = 0.125f;  // what the indirect image holds before the strategy adds

void addQuad(Scene& scene, int material, const std::string& name, glm::vec3 a, glm::vec3 b,
             glm::vec3 c, glm::vec3 d) {
  Mesh mesh;
  mesh.name = name;
  mesh.positions = {a, b, c, d};
  mesh.normals.assign(4, glm::normalize(glm::cross(b - a, c - a)));
  mesh.uvs.assign(4, glm::vec2(0.0f));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = material;
  scene.meshes.push_back(std::move(mesh));
}

Scene boxScene(bool translucent) {
  Scene scene;
  scene.source = "subsurface test";
  scene.materials = {Material{.name = "floor", .baseColor = glm::vec3(0.5f)},
                     Material{.name = "box", .baseColor = glm::vec3(0.3f)}};
  if (translucent) {
    scene.materials[1].transmittance = kTransmittance;
    scene.materials[1].extinction = kExtinction;
  }
  addQuad(scene, 0, "floor", {-0.6f, 0, -0.6f}, {-0.6f, 0, 0.6f}, {0.6f, 0, 0.6f}, {0.6f, 0, -0.6f});
  const glm::vec3 lo = kBoxMin, hi = kBoxMax;
  addQuad(scene, 1, "top", {lo.x, hi.y, lo.z}, {lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z});
  addQuad(scene, 1, "bottom", {lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z});
  addQuad(scene, 1, "front", {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, lo.y, lo.z});
  addQuad(scene, 1, "back", {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z});
  addQuad(scene, 1, "left", {lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z});
  addQuad(scene, 1, "right", {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z});
  scene.lights.push_back({.name = "sun", .type = LightType::Directional,
                          .direction = {0, -1, 0}, .intensity = float(kSun)});
  Camera camera{.name = "test", .position = {0.35f, 0.55f, -0.75f}};
  camera.forward = glm::normalize(glm::vec3(0.0f, 0.08f, 0.0f) - camera.position);
  camera.up = glm::normalize(glm::cross(glm::cross(camera.forward, glm::vec3(0, 1, 0)), camera.forward));
  camera.verticalFov = glm::radians(40.0f);
  scene.cameras.push_back(camera);
  return scene;
}

std::vector<float> readRgba(const gl::Texture& texture) {
  std::vector<float> data(std::size_t(texture.width()) * texture.height() * texture.depth() * 4);
  glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(data.size() * sizeof(float)),
                    data.data());
  return data;
}

template <class Buffer>  // gl::Buffer or DualBuffer
Grid download(const Buffer& buffer, std::size_t floats) {
  Grid data(floats);
  buffer.download(data.data(), data.size() * sizeof(float));
  return data;
}

// The strategy created as an experiment creates it, with the raster passes it stands on.
class SubsurfaceRig {
public:
  explicit SubsurfaceRig(const Scene& scene, int rsmResolution = 256, int iterations = 8,
                         ComputeBackend backend = ComputeBackend::Gl)
      : scene_(scene),
        camera_(scene.cameras.front()),
        gbuffer_(shaders_, kWidth, kHeight),
        maps_(shaders_, buildLightViews(scene.lights, scene.bounds()), 8, 8),
        indirect_(kWidth, kHeight, "test indirect") {
    table_.insert("type", "subsurface");
    table_.insert("resolution", 12);
    table_.insert("iterations", iterations);
    table_.insert("rsm_resolution", rsmResolution);
    Params params(table_, "subsurface test", "rendering");
    strategy_ = Registry<RenderingStrategy>::instance().create(params, "trilinear");
    params.finish();
    sub_ = dynamic_cast<SubsurfaceRendering*>(strategy_.get());
    // Prepared as a run prepares it: with the scene, its light views and the image size.
    Requirements requirements;
    requirements.backend = backend;
    const GridGeometry mainGrid;
    strategy_->prepare({.shaders = shaders_,
                        .grid = mainGrid,
                        .requirements = requirements,
                        .scene = &scene_.gpu,
                        .lightMaps = &maps_.lightMaps(),
                        .imageSize = {kWidth, kHeight}});
    EXPECT_EQ(sub_->onCpu(), backend == ComputeBackend::Cpu) << "the kernels run where asked";
    gbuffer_.render(scene_.gpu, camera_);
    for (glm::vec4& texel : indirect_.host().texels) texel = glm::vec4(kPrefill);
  }

  Frame frame() {
    return Frame{.scene = &scene_.gpu, .camera = &camera_, .gbuffer = gbuffer_.gbuffer(),
                 .lightMaps = maps_.lightMaps(), .lightGrid = mainGrid_, .indirect = indirect_,
                 .host = &host_};
  }
  void render() {
    host_.newFrame();
    Frame f = frame();
    strategy_->render(f);
    checkGl("subsurface test");
  }
  SubsurfaceRendering& sub() { return *sub_; }
  const GBuffer& gbuffer() const { return gbuffer_.gbuffer(); }
  std::vector<float> indirect() const {
    const HostImage& image = indirect_.hostRead();
    return {&image.texels.front().x, &image.texels.front().x + 4 * image.texels.size()};
  }

private:
  struct SceneWithContext {  // the context first: the scene's GL buffers need it
    explicit SceneWithContext(const Scene& scene) : context((glTestContext(), 0)), gpu(scene) {}
    int context;
    SceneGpu gpu;
  } scene_;
  Camera camera_;
  ShaderCompiler shaders_;
  GBufferPass gbuffer_;
  LightMapsPass maps_;
  LightGrid mainGrid_;
  DualImage indirect_;
  HostReadback host_;  // the raster passes' images for the CPU backend
  toml::table table_;
  std::unique_ptr<RenderingStrategy> strategy_;
  SubsurfaceRendering* sub_ = nullptr;
};

// ---- a. nothing translucent, nothing added --------------------------------------------------------

class Subsurface : public ::testing::TestWithParam<ComputeBackend> {
protected:
  ComputeBackend backend() const { return GetParam(); }
};

TEST_P(Subsurface, SceneWithoutTranslucentMaterialsGetsExactlyNothing) {
  SubsurfaceRig rig(boxScene(false), 256, 8, backend());
  rig.render();
  for (float v : rig.indirect()) ASSERT_EQ(v, kPrefill);
  EXPECT_EQ(rig.sub().memoryBytes(), 0u);  // nothing was even allocated
}

// ---- b. injection ---------------------------------------------------------------------------------

TEST_P(Subsurface, OnlyTranslucentSurfacesInjectTheirTransmittedFluxIntoTheObject) {
  SubsurfaceRig rig(boxScene(true), 512, 8, backend());
  Frame frame = rig.frame();
  rig.sub().renderRsm(frame);
  rig.sub().inject(frame);
  checkGl("subsurface injection test");

  // The RSM: under a sun straight down only the box's top is seen lit (its sides are edge-on);
  // the floor around it is lit too, but opaque: it must add nothing.
  const std::vector<float> flux = readRgba(rig.sub().rsm().rsmFlux);
  double rsmFlux = 0.0;
  for (std::size_t i = 0; i < flux.size(); i += 4) rsmFlux += flux[i] + flux[i + 1] + flux[i + 2];
  const double expected =
      kSun * kTopArea * (kTransmittance.x + kTransmittance.y + kTransmittance.z);
  std::cout << "[ subsurface ] RSM transmitted flux " << rsmFlux << " W, t E A = " << expected
            << " W\n";
  EXPECT_NEAR(rsmFlux, expected, 0.02 * expected);  // texel coverage of the top's edges

  // The grid: the RSM's whole flux (the grid is fitted to the box with a margin).
  const LightGrid& grid = rig.sub().grid();
  ASSERT_EQ(grid.coefficients, kCoefficients);
  const Grid current = download(grid.current, grid.floatsPerGrid());
  const Grid accumulated = download(grid.accumulated, grid.floatsPerGrid());
  const glm::ivec3 res = grid.geometry.resolution;
  EXPECT_NEAR(test::flux(current, res), rsmFlux, 1e-4 * rsmFlux);
  EXPECT_EQ(maxDifference(current, accumulated), 0.0);  // accumulation starts from the injection

  // Each injected cell holds Phi / pi * cosLobe(-y): band-1 along -y only, in proportion.
  const glm::dvec4 inward = shared::shCosineLobe({0, -1, 0});
  int injected = 0;
  forEachCell(res, [&](const glm::ivec3& c) {
    for (int channel = 0; channel < 3; ++channel) {
      const glm::dvec4 coefficients = cellOf(current, res, c, channel);
      if (coefficients[0] == 0.0) continue;
      ++injected;
      const glm::dvec3 b = linearPart(coefficients);
      EXPECT_LT(b.y, 0.0) << "cell " << c.x << "," << c.y << "," << c.z;
      const glm::dvec4 lobe = coefficients[0] / inward[0] * inward;
      for (int k = 0; k < kCoefficients; ++k)
        EXPECT_NEAR(coefficients[k], lobe[k], 1e-5 * coefficients[0]);
    }
  });
  EXPECT_GT(injected, 3 * 20);  // the top spans many cells
}

// ---- c. attenuation -------------------------------------------------------------------------------

TEST_P(Subsurface, AttenuatedPropagationIsTheStandardTimesAToTheK) {
  const glm::ivec3 res{9, 9, 9};
  const GridGeometry geometry{glm::vec3(0.0f), 0.1f, res};
  SubsurfaceRig rig(boxScene(true), 8, 1, backend());
  rig.sub().allocateGrid(geometry, 3.0f);
  const double a = std::exp(-3.0 * 0.1);
  EXPECT_NEAR(rig.sub().attenuation(), a, 1e-7);
  EXPECT_NEAR(SubsurfaceRendering::stepAttenuation(3.0f, 0.1f), a, 1e-7);

  const Grid source = pointSource(res, {4, 4, 4}, false, glm::normalize(glm::dvec3(1, 2, -1)));
  LightGrid& grid = rig.sub().grid();
  grid.current.upload(source.data(), source.size() * sizeof(float));
  grid.accumulated.upload(source.data(), source.size() * sizeof(float));
  PropagationRig standard("standard", res, iterationsTable(1));
  standard.load(source);
  Grid expectedSum = source;  // injection + sum_j a^j P^j (source)
  for (int k = 1; k <= 4; ++k) {
    rig.sub().propagate();
    standard.propagate();
    const Grid sub = download(grid.current, grid.floatsPerGrid());
    const Grid subSum = download(grid.accumulated, grid.floatsPerGrid());
    const Grid std = standard.current();
    const double ak = std::pow(a, k);
    const double subFlux = test::flux(sub, res), stdFlux = test::flux(std, res);
    std::cout << "[ subsurface ] step " << k << ": flux " << subFlux << " W, standard " << stdFlux
              << " W, ratio " << subFlux / stdFlux << " (a^k = " << ak << ")\n";
    EXPECT_NEAR(subFlux, ak * stdFlux, 1e-5 * stdFlux);
    Grid scaled = std;
    for (float& v : scaled) v = float(ak * v);
    expectClose(sub, scaled, 1e-5, "attenuated step");
    EXPECT_GT(subFlux, 0.0);
    for (std::size_t i = 0; i < expectedSum.size(); ++i) expectedSum[i] += float(ak * std[i]);
    expectClose(subSum, expectedSum, 1e-5, "attenuated accumulation");
  }
}

// ---- d. GPU against double-precision C++ --------------------------------------------------------

TEST_P(Subsurface, AttenuatedStepMatchesTheDoublePrecisionTransfer) {
  const glm::ivec3 res{6, 5, 7};
  const GridGeometry geometry{glm::vec3(0.0f), 0.05f, res};
  SubsurfaceRig rig(boxScene(true), 8, 1, backend());
  rig.sub().allocateGrid(geometry, 7.0f);
  const double a = rig.sub().attenuation();
  std::mt19937 random(42);
  const Grid source = randomFloats(std::size_t(3) * kCoefficients * cells(res), random);
  const Grid before = randomFloats(source.size(), random);
  LightGrid& grid = rig.sub().grid();
  grid.current.upload(source.data(), source.size() * sizeof(float));
  grid.accumulated.upload(before.data(), before.size() * sizeof(float));
  rig.sub().propagate();
  const Grid gpu = download(grid.current, grid.floatsPerGrid());
  const Grid gpuSum = download(grid.accumulated, grid.floatsPerGrid());

  static const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  Grid expected(source.size(), 0.0f), expectedSum = before;
  forEachCell(res, [&](const glm::ivec3& c) {
    for (int channel = 0; channel < 3; ++channel) {
      glm::dvec4 sum(0.0);
      for (const glm::ivec3& d : kAxes) {
        const glm::ivec3 from = c - d;
        if (!shared::cellInside(from, res)) continue;
        sum += shared::propagateToNeighbour(cellOf(source, res, from, channel), glm::dvec3(d),
                                            angles.farFace, angles.sideFace);
      }
      for (int k = 0; k < kCoefficients; ++k) {
        expected[at(res, c, channel, k)] = float(a * sum[k]);
        expectedSum[at(res, c, channel, k)] += float(a * sum[k]);
      }
    }
  });
  expectClose(gpu, expected, 1e-5, "attenuated step");
  expectClose(gpuSum, expectedSum, 1e-5, "accumulated");
}

// ---- d, e. shading ----------------------------------------------------------------------------------

TEST_P(Subsurface, TranslucentPixelsGainTheExitingLightAndOpaquePixelsNothing) {
  const Scene scene = boxScene(true);
  SubsurfaceRig rig(scene, 256, 12, backend());
  rig.render();
  const std::vector<float> out = rig.indirect();
  const std::vector<float> position = readRgba(rig.gbuffer().position);
  const std::vector<float> normal = readRgba(rig.gbuffer().normal);
  const std::vector<float> mask = readRgba(rig.sub().mask());
  const LightGrid& grid = rig.sub().grid();
  const Grid sum = download(grid.accumulated, grid.floatsPerGrid());
  const GridGeometry& g = grid.geometry;

  // Ray cast every pixel (rows bottom first, as the textures): which material it sees.
  const SceneRaycaster raycaster(scene);
  const Camera& camera = scene.cameras.front();
  std::vector<int> seen(std::size_t(kWidth) * kHeight, -1);  // -1 nothing, else material
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const auto hit = raycaster.cast(glm::dvec3(camera.position),
                                      cameraRay(camera, kWidth, kHeight, x, kHeight - 1 - y));
      if (hit) seen[std::size_t(y) * kWidth + x] = scene.meshes[hit->mesh].material;
    }
  const auto translucentNear = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int u = std::clamp(x + dx, 0, kWidth - 1), v = std::clamp(y + dy, 0, kHeight - 1);
        if (seen[std::size_t(v) * kWidth + u] == 1) return true;
      }
    return false;
  };

  int opaque = 0, translucent = 0, lit = 0, maskDisagrees = 0;
  double worst = 0.0, largest = 0.0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t p = std::size_t(y) * kWidth + x, i = 4 * p;
      const bool masked = mask[i] > 0.5f;
      maskDisagrees += masked != (seen[p] == 1);
      if (!translucentNear(x, y)) {  // e: exactly what it held, by an independent test
        ++opaque;
        for (int c = 0; c < 3; ++c) ASSERT_EQ(out[i + c], kPrefill) << "pixel " << x << "," << y;
      }
      if (!masked) continue;
      ++translucent;
      // d: the kernel's read, in double precision from the same inputs.
      const glm::dvec3 n(normal[i], normal[i + 1], normal[i + 2]);
      const glm::dvec3 centred =
          (glm::dvec3(position[i], position[i + 1], position[i + 2]) - glm::dvec3(g.origin)) /
              double(g.cellSize) - 0.5;
      const glm::dvec3 base = glm::floor(centred), f = centred - base;
      for (int channel = 0; channel < 3; ++channel) {
        double projected = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
          const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
          const glm::ivec3 cell = glm::clamp(glm::ivec3(base) + o, glm::ivec3(0), g.resolution - 1);
          double v = 0.0;
          for (int k = 0; k < kCoefficients; ++k)
            v += sum[at(g.resolution, cell, channel, k)] * shared::subsurfaceExitLobeAt(k, n);
          projected += shared::trilinearWeight(o, f) * v;
        }
        const double expected = kPrefill + shared::subsurfaceExitRadiance(projected, g.cellSize);
        worst = std::max(worst, std::abs(out[i + channel] - expected));
        largest = std::max(largest, expected - kPrefill);
      }
      lit += out[i] > kPrefill;
    }
  std::cout << "[ subsurface ] " << translucent << " translucent pixels (" << lit << " lit, largest "
            << largest << " W/(m^2 sr)), " << opaque << " opaque ones unchanged, mask and ray cast "
            << "disagree on " << maskDisagrees << "\n";
  EXPECT_GT(opaque, kWidth * kHeight / 2);
  EXPECT_GT(translucent, 500);
  EXPECT_GT(lit, translucent / 2);
  EXPECT_LE(maskDisagrees, kWidth * kHeight / 100);  // silhouette pixels only
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(worst, 1e-5 * largest + 1e-7);
}

INSTANTIATE_TEST_SUITE_P(Backends, Subsurface,
                         ::testing::Values(ComputeBackend::Gl, ComputeBackend::Cpu),
                         [](const auto& info) {
                           return info.param == ComputeBackend::Cpu ? "cpu" : "gl";
                         });

}  // namespace
}  // namespace lpvlab

// Occlusion "geometry_volume" (variants/occlusion/geometry_volume.cpp) and what the GV does to
// propagation:
//   - GV injection ground truth on the built-in Cornell box seen by the camera: every surfel adds
//     A_s / s^2 * cosLobe(-n), whose integral over the sphere is pi A_s / s^2, so the sum over GV
//     cells of shIntegral(c) / pi is the visible area over s^2. The visible area is computed
//     independently by casting the camera's rays at the scene's triangles in double precision
//     (pipeline_test_support.h): per pixel, the footprint of its ray's hit (with the kernel's
//     clamp of 1/|cos|), and, as the exact integral, the unclamped footprints of 3x3 rays per
//     pixel;
//   - merging by the larger coefficients: per GV cell the merged GV is the camera's cell or the
//     light views' cell, whichever has the larger c0;
//   - the CPU backend fills the GV and its albedo the GL kernels fill, within float rounding, for
//     every choice of sources, and independently of the thread count;
//   - a wall of fully blocking GV cells stops the light of a VPL behind it (exactly: the GV's
//     transmittance is 0 there), while without the GV the light passes;
//   - the parameters: skip_first_iteration sets GeometryVolume::firstOccludedIteration, and bad
//     `sources` are errors naming the key.

#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <toml++/toml.h>

#include "framework/core/error.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/composition.h"
#include "framework/pipeline/light_views.h"
#include "framework/pipeline/raster_inputs.h"
#include "framework/pipeline/raster_passes.h"
#include "framework/pipeline/scene_gpu.h"
#include "variants/resources/geometry_volume.h"
#include "error_support.h"
#include "propagation_rig.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/occlusion/surfel_area.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using test::Grid;

ResourceUses declared(const Strategy& strategy) {
  ResourceUses uses;
  strategy.declare(uses);
  return uses;
}

// What a propagation that is occluded by a GV declares (and, bouncing, reads its albedo).
ResourceUses gvReader(bool withAlbedo = false) {
  ResourceUses uses;
  uses.reads(kGeometryVolume);
  if (withAlbedo) uses.reads(kSurfaceAlbedo);
  return uses;
}

// The built-in Cornell box with its G-buffer and RSMs rendered, and GVs filled from them.
class GvScene {
public:
  GvScene() : experiment_(load()) {
    scene_ = std::make_unique<SceneGpu>(experiment_.scene);
    const PipelineSettings& s = experiment_.settings;
    gbufferPass_ = std::make_unique<GBufferPass>(shaders_, s.width, s.height);
    gbufferPass_->render(*scene_, experiment_.camera);
    lightMapsPass_ = std::make_unique<LightMapsPass>(
        shaders_, buildLightViews(experiment_.scene.lights, experiment_.scene.bounds()),
        s.rsmResolution, s.shadowResolution);
    lightMapsPass_->renderRsms(*scene_);
    grid_ = LightGrid(s.grid, 1);
  }

  // The GV's blocking coefficients after the strategy with these sources injected, on `backend`;
  // with `albedo`, the GV's albedo too (a composition that bounces).
  Grid inject(const std::vector<std::string>& sources, int* firstOccluded = nullptr,
              bool skipFirst = true, double blockingScale = 1.0,
              ComputeBackend backend = ComputeBackend::Gl, Grid* albedo = nullptr) {
    Filling filling(*this, sources, skipFirst, blockingScale, false, backend, albedo != nullptr);
    const GvFrame frame = filling.inject(experiment_.camera, 0);
    if (firstOccluded) *firstOccluded = filling.gv().firstOccludedIteration;
    if (albedo) *albedo = frame.albedo;
    return frame.blocking;
  }

  // The GV and its albedo after each of a sequence of frames (a camera and the geometry's version
  // each: Frame::geometryVersion), one strategy filling it frame after frame as the pipeline does
  // (cleared, then injected), with or without `history`.
  struct GvFrame {
    Grid blocking, albedo;
  };
  std::vector<GvFrame> injectFrames(const std::vector<std::string>& sources,
                                    const std::vector<std::pair<Camera, int>>& frames, bool history,
                                    ComputeBackend backend = ComputeBackend::Gl) {
    Filling filling(*this, sources, true, 1.0, history, backend, true);
    std::vector<GvFrame> out;
    for (const auto& [camera, version] : frames) out.push_back(filling.inject(camera, version));
    gbufferPass_->render(*scene_, experiment_.camera);  // as the other tests expect it
    return out;
  }

  const Experiment& experiment() const { return experiment_; }
  double cellSize() const { return grid_.geometry.cellSize; }

private:
  // One geometry_volume strategy, prepared once, with the level's resources as the pipeline
  // allocates them from the strategy's own declaration (which fixes its first occluded iteration).
  class Filling {
  public:
    Filling(GvScene& scene, const std::vector<std::string>& sources, bool skipFirst,
            double blockingScale, bool history, ComputeBackend backend, bool withAlbedo)
        : scene_(scene), withAlbedo_(withAlbedo) {
      toml::table table;
      toml::array list;
      for (const std::string& source : sources) list.push_back(source);
      table.insert("sources", list);
      table.insert("skip_first_iteration", skipFirst);
      table.insert("blocking_scale", blockingScale);
      table.insert("history", history);
      Params params(table, "occlusion test", "occlusion");
      strategy_ = Registry<OcclusionStrategy>::instance().create(params, "geometry_volume");
      params.finish();
      const std::map<std::string, ResourceAllocator> resources = resolveResources(
          {{"occlusion test", declared(*strategy_)}, {"a propagation", gvReader(withAlbedo)},
           {"the raster passes", raster::producedByRasterPasses()}});
      EXPECT_EQ(resources.count(std::string(kGeometryVolume.name)), 1u);
      // Nobody uses the albedo unless the propagation bounces.
      EXPECT_EQ(resources.count(std::string(kSurfaceAlbedo.name)), withAlbedo ? 1u : 0u);
      Requirements requirements;
      requirements.resources = resources;
      requirements.backend = backend;
      strategy_->prepare({.shaders = scene.shaders_, .grid = scene.grid_.geometry,
                          .requirements = requirements});
      for (const auto& [name, allocate] : resources)
        resources_.adopt(name, allocate({scene.grid_.geometry, 1, backend}));
    }

    GeometryVolume& gv() { return *resources_.find(kGeometryVolume); }

    GvFrame inject(const Camera& camera, int geometryVersion) {
      scene_.gbufferPass_->render(*scene_.scene_, camera);
      gv().clear();
      if (withAlbedo_) resources_.find(kSurfaceAlbedo)->clear();
      scene_.host_.newFrame();
      Frame frame{.scene = scene_.scene_.get(), .camera = &camera,
                  .gbuffer = scene_.gbufferPass_->gbuffer(),
                  .lightMaps = scene_.lightMapsPass_->lightMaps(), .lightGrid = scene_.grid_,
                  .indirect = scene_.indirect_, .resources = &resources_, .host = &scene_.host_,
                  .geometryVersion = geometryVersion};
      strategy_->inject(frame);
      glFinish();
      checkGl("occlusion test");
      GvFrame out;
      out.blocking.resize(std::size_t(gv().geometry.cellCount()) * 4);
      gv().blocking.download(out.blocking.data(), out.blocking.size() * sizeof(float));
      if (withAlbedo_) {
        out.albedo.resize(std::size_t(gv().geometry.cellCount()) * 4);
        resources_.find(kSurfaceAlbedo)->albedo.download(out.albedo.data(),
                                                         out.albedo.size() * sizeof(float));
      }
      return out;
    }

  private:
    GvScene& scene_;
    bool withAlbedo_;
    std::unique_ptr<OcclusionStrategy> strategy_;
    ResourceTable resources_;
  };

  static Experiment load() {
    test::glTestContext();
    return loadExperiment("", {"output.width=128", "output.height=128",
                               "light_maps.shadow_resolution=128", "light_maps.rsm_resolution=128"});
  }
  Experiment experiment_;
  ShaderCompiler shaders_;
  std::unique_ptr<SceneGpu> scene_;
  std::unique_ptr<GBufferPass> gbufferPass_;
  std::unique_ptr<LightMapsPass> lightMapsPass_;
  LightGrid grid_;
  DualImage indirect_;
  HostReadback host_;
};

// Sum over GV cells of shIntegral(c) / pi: the surfels' area in units of s^2.
double gvArea(const Grid& blocking) {
  const std::size_t cells = blocking.size() / 4;
  double sum = 0.0;
  for (std::size_t i = 0; i < cells; ++i) sum += shared::shIntegralOfC0(blocking[i]) / M_PI;
  return sum;
}

// The camera's visible area (m^2) by ray casting `samples`^2 rays per output pixel; `clamped`:
// with the kernel's clamp of 1/|cos| (surfel_area.glsl), else the exact footprints.
double raycastVisibleArea(const Experiment& e, int samples, bool clamped) {
  const test::SceneRaycaster raycaster(e.scene);
  const Camera& camera = e.camera;
  const int w = e.settings.width * samples, h = e.settings.height * samples;
  const double texelEdge = 2.0 * std::tan(0.5 * double(camera.verticalFov)) / h;
  double area = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::dvec3 ray = test::cameraRay(camera, w, h, x, y);
      const auto hit = raycaster.cast(glm::dvec3(camera.position), ray);
      if (!hit) continue;
      const double distance = hit->t * glm::length(ray);
      const double cosine = std::abs(glm::dot(hit->normal, ray)) / glm::length(ray);
      area += clamped ? shared::perspectiveSurfelArea(texelEdge, hit->t, distance, cosine)
                      : texelEdge * texelEdge * hit->t * hit->t * hit->t / (distance * cosine);
    }
  return area;
}

TEST(Occlusion, CameraSurfelsAddUpToTheVisibleArea) {
  GvScene scene;
  const Grid gv = scene.inject({"camera"});
  const double s2 = scene.cellSize() * scene.cellSize();
  const double gpu = gvArea(gv) * s2;
  const double clamped = raycastVisibleArea(scene.experiment(), 1, true);
  const double exact = raycastVisibleArea(scene.experiment(), 3, false);
  std::cout << "[ occlusion ] camera's visible area: GV " << gpu << " m^2, ray cast per pixel "
            << "(clamped 1/cos) " << clamped << " m^2, exact (3x3 rays per pixel) " << exact
            << " m^2\n";
  ASSERT_GT(exact, 0.1);
  EXPECT_NEAR(gpu, clamped, 0.01 * clamped) << "rasterised vs ray-cast pixels";
  // The clamp only removes area, and little of it in this view.
  EXPECT_LE(clamped, exact * 1.005);
  EXPECT_NEAR(gpu, exact, 0.03 * exact);
}

TEST(Occlusion, MergeKeepsPerCellTheSourceWithTheLargerC0) {
  GvScene scene;
  const Grid camera = scene.inject({"camera"});
  const Grid light = scene.inject({"light"});
  const Grid merged = scene.inject({"light", "camera"});
  const std::size_t cells = camera.size() / 4;
  ASSERT_GT(gvArea(light), 1.0) << "the spot's RSMs see surfaces";
  ASSERT_GT(gvArea(camera), 1.0);
  double scale = 0.0;
  for (float v : merged) scale = std::max(scale, double(std::abs(v)));
  const double tolerance = 1e-4 * scale;  // the atomics add in any order
  int fromCamera = 0, fromLight = 0, bothEmpty = 0;
  for (std::size_t i = 0; i < cells; ++i) {
    if (camera[i] == 0.0f && light[i] == 0.0f) {
      ++bothEmpty;
      for (int k = 0; k < 4; ++k) EXPECT_EQ(merged[k * cells + i], 0.0f);
      continue;
    }
    if (std::abs(camera[i] - light[i]) <= tolerance) continue;  // too close to call
    const Grid& winner = light[i] > camera[i] ? light : camera;
    (light[i] > camera[i] ? fromLight : fromCamera)++;
    for (int k = 0; k < 4; ++k)
      ASSERT_NEAR(merged[k * cells + i], winner[k * cells + i], tolerance) << "cell " << i;
  }
  std::cout << "[ occlusion ] merged GV: " << fromCamera << " cells from the camera, " << fromLight
            << " from the light views, " << bothEmpty << " empty\n";
  EXPECT_GT(fromCamera, 0);
  EXPECT_GT(fromLight, 0);
}

// blocking_scale multiplies every surfel's blocking, so the GV (merged by the larger c0, which
// the common factor does not change) is linear in it.
TEST(Occlusion, BlockingScaleMultipliesTheGv) {
  GvScene scene;
  const Grid one = scene.inject({"light", "camera"});
  const Grid scaled = scene.inject({"light", "camera"}, nullptr, true, 2.5);
  const Grid none = scene.inject({"light", "camera"}, nullptr, true, 0.0);
  double largest = 0.0;
  for (float v : one) largest = std::max(largest, double(std::abs(v)));
  ASSERT_GT(largest, 0.0);
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_NEAR(scaled[i], 2.5 * one[i], 1e-5 * 2.5 * largest) << "coefficient " << i;
    ASSERT_EQ(none[i], 0.0f) << "coefficient " << i;
  }
}

TEST(Occlusion, SkipFirstIterationSetsTheFirstOccludedIteration) {
  GvScene scene;
  int first = -1;
  scene.inject({"camera"}, &first, true);
  EXPECT_EQ(first, 1);
  scene.inject({"camera"}, &first, false);
  EXPECT_EQ(first, 0);
}

// Largest |a - b| over b's largest value.
double maxRelativeDifference(const Grid& a, const Grid& b) {
  return test::maxDifference(a, b) / test::maxAbs(b);
}

// The CPU backend's surfels (geometry_volume_cpu.h) are the GL kernels' shared functions summed
// per cell in double: the same GV and albedo within float rounding, for every choice of sources
// (the merge included), and bit for bit whatever the thread count.
TEST(Occlusion, CpuBackendFillsTheGvAndAlbedoOfTheGlKernels) {
  GvScene scene;
  for (const std::vector<std::string>& sources :
       {std::vector<std::string>{"camera"}, {"light"}, {"light", "camera"}}) {
    const std::string what = sources.size() == 2 ? "both" : sources[0];
    Grid glAlbedo, cpuAlbedo;
    const Grid gl = scene.inject(sources, nullptr, true, 1.5, ComputeBackend::Gl, &glAlbedo);
    const Grid cpu = scene.inject(sources, nullptr, true, 1.5, ComputeBackend::Cpu, &cpuAlbedo);
    ASSERT_GT(gvArea(gl), 1.0) << what;
    // GL sums a cell's hundreds of float surfels with atomics in any order (as the merge test
    // above allows); the CPU sums them in double.
    EXPECT_LT(maxRelativeDifference(cpu, gl), 1e-4) << what;
    EXPECT_LT(maxRelativeDifference(cpuAlbedo, glAlbedo), 1e-4) << what;
    double weight = 0.0;
    for (std::size_t i = 3; i < glAlbedo.size(); i += 4) weight += glAlbedo[i];
    EXPECT_GT(weight, 0.0) << what << ": the albedo was compared where there is some";
    Grid oneThreadAlbedo;
    Grid oneThread;
    {
      tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
      oneThread = scene.inject(sources, nullptr, true, 1.5, ComputeBackend::Cpu, &oneThreadAlbedo);
    }
    EXPECT_EQ(oneThread, cpu) << what;
    EXPECT_EQ(oneThreadAlbedo, cpuAlbedo) << what;
  }
}

// With `history` (thesis 4.3), each frame's GV is merged with the GV of the frames before by the
// same rule as two sources: per cell the whole cell, and its albedo sums, of the larger c0. The
// camera first looks into the box from outside, then from inside at the left wall; the second
// frame keeps what the first saw and the second does not. When the geometry moves
// (Frame::geometryVersion) the history starts anew. The CPU backend keeps the same history.
TEST(Occlusion, AGvHistoryKeepsPerCellTheLargerC0OfTheFramesBeforeWithItsAlbedo) {
  GvScene scene;
  const Camera outside = scene.experiment().camera;
  Camera inside = outside;
  inside.position = {0.45f, 0.3f, 0.3f};
  ASSERT_EQ(orientCamera(inside, {0.0f, 0.3f, 0.3f}, {0, 1, 0}), CameraOrientation::Oriented);
  const std::vector<std::pair<Camera, int>> frames = {{outside, 0}, {inside, 0}, {inside, 1}};
  const auto alone = scene.injectFrames({"camera"}, frames, false);
  const auto kept = scene.injectFrames({"camera"}, frames, true);
  const auto keptOnCpu = scene.injectFrames({"camera"}, frames, true, ComputeBackend::Cpu);
  const std::size_t cells = alone[0].blocking.size() / 4;
  double scale = 0.0;
  for (const auto& frame : alone)
    for (float v : frame.blocking) scale = std::max(scale, double(std::abs(v)));
  const double tolerance = 1e-4 * scale;  // the atomics add in any order
  ASSERT_GT(gvArea(alone[0].blocking), 0.5);
  ASSERT_GT(gvArea(alone[1].blocking), 0.1);

  // The first frame has no history; after the geometry moved, only the frame's own surfels.
  EXPECT_LT(test::maxDifference(kept[0].blocking, alone[0].blocking), tolerance);
  EXPECT_LT(test::maxDifference(kept[2].blocking, alone[2].blocking), tolerance);
  EXPECT_LT(test::maxDifference(kept[2].albedo, alone[2].albedo),
            1e-4 * test::maxAbs(alone[2].albedo));

  int fromHistory = 0, fromFrame = 0;
  for (std::size_t i = 0; i < cells; ++i) {
    const float before = alone[0].blocking[i], now = alone[1].blocking[i];
    if (std::abs(before - now) <= tolerance) continue;  // too close to call
    const auto& winner = before > now ? alone[0] : alone[1];
    (before > now ? fromHistory : fromFrame)++;
    for (int k = 0; k < 4; ++k) {
      ASSERT_NEAR(kept[1].blocking[k * cells + i], winner.blocking[k * cells + i], tolerance)
          << "cell " << i;
      ASSERT_NEAR(kept[1].albedo[4 * i + k], winner.albedo[4 * i + k],
                  1e-4 * test::maxAbs(winner.albedo))
          << "cell " << i << ": the albedo sums come with the kept cell";
    }
  }
  EXPECT_GT(fromHistory, 0) << "cells only the first frame saw keep blocking";
  EXPECT_GT(fromFrame, 0);
  EXPECT_GT(gvArea(kept[1].blocking), gvArea(alone[1].blocking));
  for (std::size_t f = 0; f < frames.size(); ++f) {
    EXPECT_LT(maxRelativeDifference(keptOnCpu[f].blocking, kept[f].blocking), 1e-4)
        << "frame " << f;
    EXPECT_LT(maxRelativeDifference(keptOnCpu[f].albedo, kept[f].albedo), 1e-4) << "frame " << f;
  }
  std::cout << "[ occlusion ] GV history, second frame: " << fromHistory
            << " cells kept from the first, " << fromFrame << " from the frame's own surfels\n";
}

void expectSourcesError(const std::vector<std::string>& sources, const std::string& phrase) {
  test::glTestContext();
  toml::table table;
  toml::array list;
  for (const std::string& source : sources) list.push_back(source);
  table.insert("sources", list);
  Params params(table, "test.toml", "occlusion");
  const std::string message = test::errorOf(
      [&] { Registry<OcclusionStrategy>::instance().create(params, "geometry_volume"); });
  EXPECT_TRUE(test::contains(message, "sources"));
  EXPECT_TRUE(test::contains(message, phrase));
}

TEST(Occlusion, BadSourcesAreErrorsNamingTheKey) {
  expectSourcesError({"sun"}, "unknown source 'sun'");
  expectSourcesError({}, "at least one");
  expectSourcesError({"camera", "camera"}, "twice");
}

// ---- a wall of opaque GV cells ---------------------------------------------------------------

TEST(Occlusion, AWallOfOpaqueGvCellsStopsTheLightOfAVplBehindIt) {
  const glm::ivec3 res{12, 7, 7};
  const int wall = 6;  // the GV cells centred on the plane x = 6 between light cells 5 and 6
  const int iterations = 14;
  // A +x Lambertian VPL of 1 W per channel in cell (2, 3, 3).
  Grid vpl(std::size_t(3) * test::kCoefficients * test::cells(res), 0.0f);
  const glm::dvec4 lobe = shared::shCosineLobe({1, 0, 0}) / M_PI;
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < test::kCoefficients; ++k) vpl[test::at(res, {2, 3, 3}, channel, k)] = float(lobe[k]);
  // Isotropic blocking of c0 Y0 = 2.8 > 1 in every GV cell of the wall: transmittance 0.
  const glm::ivec3 gvRes = res + 1;
  Grid gv(std::size_t(4) * test::cells(gvRes), 0.0f);
  for (int z = 0; z < gvRes.z; ++z)
    for (int y = 0; y < gvRes.y; ++y) gv[shared::cellIndex({wall, y, z}, gvRes)] = 10.0f;

  auto fluxBeyond = [&](const Grid& g, bool beyond) {
    return test::flux(g, res, [&](const glm::ivec3& c) { return (c.x >= wall) == beyond; });
  };
  for (const std::string method : {"gather", "scatter"}) {
    test::PropagationRig open("standard", res, test::iterationsTable(iterations, method));
    open.load(vpl);
    open.propagate();
    test::PropagationRig walled("standard", res, test::iterationsTable(iterations, method), 1, true);
    walled.load(vpl);
    walled.loadGv(gv, 0);
    walled.propagate();
    const double openBeyond = fluxBeyond(open.accumulated(), true);
    const double walledBeyond = fluxBeyond(walled.accumulated(), true);
    const double walledBefore = fluxBeyond(walled.accumulated(), false);
    std::cout << "[ occlusion ] " << method << ": accumulated flux beyond the wall " << walledBeyond
              << " W (without the GV " << openBeyond << " W), before it " << walledBefore << " W\n";
    EXPECT_GT(openBeyond, 0.5) << method;
    EXPECT_EQ(walledBeyond, 0.0) << method;
    EXPECT_GT(walledBefore, 3.0) << method;  // the light stays in front (3 W injected)
  }
}

}  // namespace
}  // namespace lpvlab

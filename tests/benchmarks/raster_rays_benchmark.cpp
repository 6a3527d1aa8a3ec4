// Rays per second of the raster passes by ray casting (framework/raster/ray_raster.h; Google
// Benchmark, in bench_cpu_kernels; prints figures, asserts nothing), beside Embree's own rate on
// the same coherent rays: each pass's rays cast again through the same packets (cast_view.h) with
// nothing done at the hits. The gap between the two is what the passes spend beyond Embree:
// building the rays, shading each hit by the shaders' arithmetic, texture lookups at the texel's
// level of detail, and the alpha tests at that level (the Embree-only casts test alpha masks at
// level 0, as the path tracer does).
//   gbuffer:       the camera's rays at the experiment's output size
//   shadow_map:    every light view's depth-only rays at the shadow-map resolution
//   rsm:           every light view's rays at the RSM resolution, with the RSM texel's flux
//   shadow_rays:   direct light's exact shadow rays ([light_maps] shadows = "rays"), one per
//                  covered pixel and light facing it (counted: pixels x lights, so an upper bound)
// On the default Cornell box (512x512, one spot light in five views) and, where ../shared holds
// it, Sponza under the sun at 320x180 (the frame of issue 43's goal; 262k triangles, foliage
// alpha-masked). Reported: rays/s of all cores (the median of 5 repetitions).

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "benchmark_support.h"

#include "framework/core/error.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "framework/pipeline/raster_passes.h"
#include "framework/pipeline/host_readback.h"
#include "framework/pipeline/light_views.h"
#include "framework/raster/cast_view.h"
#include "framework/raster/ray_raster.h"

namespace lpvlab {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// One scene's passes, built once: its experiment, light views, the ray raster and, for the
// Embree-only casts, the traced meshes without the passes' shading.
struct RasterCase {
  Experiment experiment;
  LightViews views;
  std::unique_ptr<RayRaster> raster;
  std::vector<SurfaceMaterial> materials;  // the traced scene points into them
  std::unique_ptr<EmbreeScene> traced;
  HostImage position, normal, albedo;
  std::size_t coveredPixels = 0;
};

struct CaseSpec {
  std::string name;
  std::string file;  // "" = the built-in default
  std::vector<std::string> overrides;
};

const std::vector<CaseSpec>& caseSpecs() {
  static const std::vector<CaseSpec> specs = {
      {"cornell_box", "", {}},
      {"sponza_sun_320x180", LPVLAB_SOURCE_DIR "/experiments/sponza_sun.toml",
       {"output.width=320", "output.height=180"}},
  };
  return specs;
}

// The case, loaded on first use; null (with the reason in `problem`) where its scene is missing.
RasterCase* loadCase(const CaseSpec& spec, std::string& problem) {
  static std::vector<std::unique_ptr<RasterCase>> cases(caseSpecs().size());
  static std::vector<std::string> problems(caseSpecs().size());
  const std::size_t index = std::size_t(&spec - caseSpecs().data());
  if (!cases[index] && problems[index].empty()) {
    try {
      auto c = std::make_unique<RasterCase>();
      c->experiment = loadExperiment(spec.file, spec.overrides);
      const Experiment& e = c->experiment;
      c->views = buildLightViews(e.scene.lights, e.scene.bounds(), directionalFollow(e.settings, e.camera));
      c->raster = std::make_unique<RayRaster>(e.scene);
      c->materials = prepareMaterials(e.scene);
      c->traced = std::make_unique<EmbreeScene>(e.scene, c->materials, RayEngineSettings{},
                                                [](const Mesh& m) { return m.rasterised; });
      const int w = e.settings.width, h = e.settings.height;
      for (HostImage* image : {&c->position, &c->normal, &c->albedo})
        *image = HostImage{w, h, 1, std::vector<glm::vec4>(std::size_t(w) * h)};
      c->raster->renderGBuffer(e.camera, cameraClipFromWorld(e.camera, w, h),
                               {.position = &c->position, .normal = &c->normal, .albedo = &c->albedo});
      for (const glm::vec4& p : c->position.texels) c->coveredPixels += p.w != 0.0f;
      cases[index] = std::move(c);
    } catch (const Error& error) {
      problems[index] = error.what();
    }
  }
  problem = problems[index];
  return cases[index].get();
}

// Each texel's hit distance stored (infinity for none), the least a pass does with a result.
void castOnly(const EmbreeScene& scene, const glm::mat4& clipFromWorld, int width, int height,
              std::vector<float>& distances) {
  distances.resize(std::size_t(width) * height);
  castView(scene, ViewRays(clipFromWorld, width, height), nullptr,
           [&](int x, int y, const ViewRay&, const RayHit* hit) {
             distances[std::size_t(y) * width + x] = hit ? hit->distance : kInfinity;
           });
  benchmark::DoNotOptimize(distances.data());
}

// Runs `pass` once untimed, then as timed iterations; `rays` per call.
void measure(benchmark::State& state, double rays, const std::function<void()>& pass) {
  pass();
  for (auto _ : state) pass();
  state.counters["rays_per_s"] =
      benchmark::Counter(rays, benchmark::Counter::kIsIterationInvariantRate);
}

enum class Pass { GBuffer, ShadowMap, Rsm, ShadowRays };

void rasterRays(benchmark::State& state, const CaseSpec* spec, Pass pass, bool embreeOnly) {
  std::string problem;
  RasterCase* c = loadCase(*spec, problem);
  if (!c) return state.SkipWithError(("scene not available: " + problem).c_str());
  const Experiment& e = c->experiment;
  const int w = e.settings.width, h = e.settings.height;
  const int views = int(c->views.views.size());
  const int rsm = e.settings.rsmResolution, shadow = e.settings.shadowResolution;
  std::vector<float> distances;
  const auto eachView = [&](int resolution) {
    for (const GpuView& view : c->views.views)
      castOnly(*c->traced, view.clipFromWorld, resolution, resolution, distances);
  };
  switch (pass) {
    case Pass::GBuffer: {
      const glm::mat4 clip = cameraClipFromWorld(e.camera, w, h);
      HostImage position = c->position, normal = c->normal, albedo = c->albedo;
      if (embreeOnly)
        return measure(state, double(w) * h, [&] { castOnly(*c->traced, clip, w, h, distances); });
      return measure(state, double(w) * h, [&] {
        c->raster->renderGBuffer(e.camera, clip, {.position = &position, .normal = &normal, .albedo = &albedo});
      });
    }
    case Pass::ShadowMap: {
      if (embreeOnly) return measure(state, double(views) * shadow * shadow, [&] { eachView(shadow); });
      HostDepthImage depth{shadow, shadow, views, std::vector<float>(std::size_t(views) * shadow * shadow)};
      return measure(state, double(views) * shadow * shadow,
                     [&] { c->raster->renderShadowMaps(c->views, shadow, depth); });
    }
    case Pass::Rsm: {
      if (embreeOnly) return measure(state, double(views) * rsm * rsm, [&] { eachView(rsm); });
      std::vector<HostImage> images(3, HostImage{rsm, rsm, views, std::vector<glm::vec4>(std::size_t(views) * rsm * rsm)});
      return measure(state, double(views) * rsm * rsm, [&] {
        c->raster->renderRsms(c->views, rsm, {.position = &images[0], .normal = &images[1], .flux = &images[2]});
      });
    }
    case Pass::ShadowRays: {
      std::vector<float> visibility;
      return measure(state, double(c->coveredPixels) * double(c->views.lights.size()),
                     [&] { c->raster->shadowRays(c->position, c->normal, c->views, visibility); });
    }
  }
}

const bool registered = [] {
  struct Named {
    const char* name;
    Pass pass;
    bool embreeOnly;
  };
  const Named passes[] = {{"gbuffer", Pass::GBuffer, false},      {"gbuffer/embree_only", Pass::GBuffer, true},
                          {"shadow_map", Pass::ShadowMap, false}, {"shadow_map/embree_only", Pass::ShadowMap, true},
                          {"rsm", Pass::Rsm, false},              {"rsm/embree_only", Pass::Rsm, true},
                          {"shadow_rays", Pass::ShadowRays, false}};
  for (const CaseSpec& spec : caseSpecs())
    for (const Named& p : passes)
      medianOf5(benchmark::RegisterBenchmark(("raster_rays/" + spec.name + "/" + p.name).c_str(), rasterRays,
                                             &spec, p.pass, p.embreeOnly));
  return true;
}();

}  // namespace
}  // namespace lpvlab

#pragma once
// The frame: (1) shadow maps and RSMs per light view, (2) the camera's G-buffer and direct light,
// then (3) the experiment's indirect method (indirect_method.h: LPV, the default, or another),
// which writes the indirect image. The pipeline renders only the raster inputs a run needs
// (raster_inputs.h) and never asks which method runs. Every stage is timed on the GPU (timestamp
// queries) and on the wall clock (the stage ends with glFinish).

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/gl/gpu_timer.h"
#include "framework/gl/shader_compiler.h"
#include "framework/io/image.h"
#include "framework/pipeline/direct_lighting.h"
#include "framework/pipeline/raster_passes.h"
#include "framework/pipeline/cascade.h"
#include "framework/pipeline/composition.h"
#include "framework/pipeline/host_raster.h"
#include "framework/pipeline/host_readback.h"
#include "framework/pipeline/indirect_method.h"

namespace lpvlab {

// How a directional light's shadow and RSM view is placed (light_views.h, [light_maps]
// directional in docs/experiments.md).
struct DirectionalViewSettings {
  float followWidth = 0.0f;  // 0: a box around the whole scene; > 0: a box this wide (m) that
                             // follows the camera, centred like the finer cascade levels
  bool snap = true;          // the followed box moves in whole texels of both maps
};

struct PipelineSettings {
  int width = 512;             // output pixels
  int height = 512;
  int rsmResolution = 256;     // RSM texels per side per light view
  int shadowResolution = 1024; // shadow-map texels per side per light view
  GridGeometry grid;           // where the light grid sits (resolved by the experiment)
  int shOrder = 1;             // SH order of the light grid, 1..3
  CascadeSettings cascades;    // levels = 1: `grid` alone
  glm::vec3 skyRadiance{0.0f}; // constant sky, W/(m^2 sr): needs an injection strategy for it
  ShadowSettings shadow;
  DirectionalViewSettings directional;
  std::string backend = "auto"; // [compute] backend: "auto", "gl" or "cpu" (strategy.h)
  // [compute] raster: "auto", "gl" or "embree" (framework/raster/raster_choice.h, which makes the
  // HostRaster the pipeline is given; recorded in the compute report).
  std::string raster = "auto";
  // Whether the run has GL: false with [gl] backend = "none", or "auto" where no GL context could
  // be made (the pipeline sets it from the context it runs in). Without GL, strategies and
  // methods that draw with GL are refused by the key that chose them.
  bool gl = true;
  // false: no shadow maps and no direct light (the direct image stays black), for callers that
  // use the indirect light alone (lpvlab fit, whose residuals compare indirect).
  bool directLight = true;
};

// Where a directional light's view follows `camera` (nullopt: it covers the whole scene).
std::optional<DirectionalFollow> directionalFollow(const PipelineSettings& settings,
                                                   const Camera& camera);

// How a stage's time was taken, by where it ran: GL timestamp queries around its GL work (on
// the GL renderer), or the steady clock around it when its strategies run on the CPU backend
// (transfers to and from GL included: GL timestamps do not see CPU work).
inline constexpr const char* kGlTimerQuery = "gl_timer_query";
inline constexpr const char* kCpuWallClock = "cpu_wall_clock";

// Stage name -> milliseconds, for one frame.
struct FrameTimes {
  std::map<std::string, double> stageMs;       // by the stage's own clock (below)
  std::map<std::string, std::string> clock;    // kGlTimerQuery or kCpuWallClock, per stage
  std::map<std::string, double> wallMs;        // steady clock, each stage ended by glFinish
  std::vector<std::string> order;              // the stages in the order they ran
  // Of them, the indirect method's (the rest are the raster passes and direct light, which every
  // configuration of a sweep pays alike).
  std::set<std::string> methodStages;
};

// Names a timing report gives its sums over stages (timing.h): no stage may be named so.
inline constexpr const char* kMethodTime = "method";  // the indirect method's stages
inline constexpr const char* kSharedTime = "shared";  // the raster passes and direct light
inline constexpr const char* kTotalTime = "total";    // every stage

class Pipeline {
public:
  // The pipeline's own stages, in the order a frame runs those it needs (the method's follow).
  static const std::vector<std::string>& stageNames();

  // `raster`: where the raster passes run (settings.raster, framework/raster/raster_choice.h);
  // by default every pass on GL. Shadow rays (settings.shadow.rays) need its host raster.
  Pipeline(const Scene& scene, const Camera& camera, const PipelineSettings& settings,
           std::unique_ptr<IndirectMethod> method, ShaderCompiler& shaders, RasterPlan raster = {});
  ~Pipeline();

  FrameTimes renderFrame();
  // The last frame's outputs, top row first: direct, indirect, combined, albedo, normal, depth
  // (view depth in metres; 0 where no surface was hit).
  std::vector<NamedImage> readOutputs() const;

  // Moves the camera, from the next frame on (the method follows it: LPV's finer cascade levels,
  // and directional light views that follow the camera).
  void setCamera(const Camera& camera);
  // The scene moved (a frame of an animation, framework/animation/animation.h): the lights and
  // the meshes' vertices are taken again from `scene`, which holds the same lights and meshes as
  // at construction, moved. The light views follow the lights, and the scene's bounds when geometry
  // moved.
  void moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved);
  // Geometry the raster passes draw beside the scene's meshes (extra_geometry.h: particles'
  // light-field billboards), from the next frame on; the caller keeps it alive as long as it
  // renders frames. An Error with a raster pass or shadow rays on the host, which see the scene's
  // meshes alone.
  void addExtraGeometry(const ExtraGeometry* extra);

  // The run's indirect method (LPV's levels and grid read-back are its own:
  // variants/methods/lpv/light_propagation_volumes.h).
  IndirectMethod& method() { return *method_; }
  const IndirectMethod& method() const { return *method_; }
  // Diagnostics (tests, audits): the last frame's light maps (shadow maps and RSMs).
  const LightMaps& lightMaps() const;
  // Diagnostics (lpvlab explain): the last frame's G-buffer, and its raster images on the host
  // (read back from GL once per frame, or made there by the ray-cast raster passes).
  const GBuffer& gbuffer() const;
  HostReadback& host() const { return hostReadback_; }
  // Whether the frame renders a raster input (raster_inputs.h).
  bool renders(std::string_view rasterInput) const;
  // The backend the run resolved ([compute] backend) and where each stage's kernels run:
  // {"backend": ..., "raster": the plan's record (where each pass ran and why) with the host
  // raster's report, "shadows": "map" or "rays", "direct": ..., and the method's computeReport()}.
  nlohmann::json computeReport() const;
  // What each stage does per frame (strategy.h's WorkCount), by stage name: a list of
  // {unit, units, multiply_adds_per_unit, bytes_per_unit, multiply_adds, bytes}; the raster
  // passes count their texels and pixels only (their arithmetic is the rasteriser's).
  // `glKernels`: the work of the GL kernels whatever the backend (what a GPU would run: the
  // analysis's GPU estimate, analysis/lpvlab_analysis/gpu_estimate.py, is made from it).
  nlohmann::json workReport(bool glKernels = false) const;
  // Bytes per resource group (GL buffers and textures; host buffers of kernels on the CPU).
  nlohmann::json memoryReport() const;

  // Derivatives through a frame (dual_frame.h): renders a frame, then the method's dual pass.
  // `seeds`: at most kDualSlots parameter keys ("<table>.<name>"), each one derivativeRefusal
  // accepts (an Error otherwise).
  using FrameDerivatives = IndirectMethod::FrameDerivatives;
  FrameDerivatives renderDerivatives(const std::vector<std::string>& seeds);
  // Why the derivatives with respect to `key` cannot be carried through this run's frames, or
  // "" if they can.
  std::string derivativeRefusal(const std::string& key) const;

private:
  template <class F>
  void stage(const std::string& name, FrameTimes& times, F&& work);
  // The light views for the current camera, lights and scene bounds.
  LightViews lightViews() const;
  // The raster passes of a frame, on GL or by the host raster into hostReadback_.
  void renderShadowMaps();
  void renderRsms();
  void renderGBuffer();

  PipelineSettings settings_;
  Camera camera_;
  std::vector<Light> lights_;  // as last placed (moveScene), with the scene's bounds then
  Bounds sceneBounds_;
  std::unique_ptr<IndirectMethod> method_;
  std::set<std::string> consumed_;  // the raster inputs the method reads
  ComputeBackend backend_ = ComputeBackend::Gl;
  std::unique_ptr<SceneGpu> scene_;
  std::vector<const ExtraGeometry*> extras_;
  std::unique_ptr<GBufferPass> gbufferPass_;
  std::unique_ptr<LightMapsPass> lightMapsPass_;
  std::unique_ptr<DirectLighting> direct_;
  DualImage directImage_, indirectImage_;  // the frame's outputs, on the side that wrote them
  GpuTimer gpuTimer_;
  std::set<std::string> cpuStages_;  // stages whose work runs on the CPU backend
  // This frame's images on the host: read back for CPU kernels, or made there by raster_.host
  // (mutable: readOutputs reads through it).
  mutable HostReadback hostReadback_;
  RasterPlan raster_;                // where each raster pass runs (host_raster.h)
  bool uploadRasterImages_ = false;  // host-made raster images go to GL too: a GL kernel reads them
};

}  // namespace lpvlab

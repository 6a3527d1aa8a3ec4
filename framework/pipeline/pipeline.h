#pragma once
// The LPV pipeline: per frame, (1) shadow maps and RSMs per light view, (2) the camera's
// G-buffer and direct light, (3) clearing the grids, (4) occlusion (the GV's blocking
// potential), (5) injection, (6) propagation, (7) rendering of indirect light. Stages 4-7 are the
// experiment's strategies; the resources they pass each other (named_resources.h: the GV, the
// normal grid, ...) exist only if one strategy produces them and another uses them.
// With cascades (cascade.h) stages 3-6 run once per level, and injection ends by carrying each
// level's light into its parent. Every stage is timed on the GPU (timestamp queries) and on the
// wall clock (the stage ends with glFinish).

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
#include "framework/pipeline/host_readback.h"

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
};

// Flux bookkeeping of injection (W, summed over RGB): what the RSMs reflect, and what the grid
// holds after injection (the difference fell outside the grid).
struct InjectionBalance {
  double rsmFlux = 0.0;
  double gridFlux = 0.0;
  // Flux each injection strategy added (its experiment table, e.g. "injection.also[0]"), in order.
  std::vector<std::pair<std::string, double>> byInjection;
};

class Pipeline {
public:
  // The stage names, in execution order.
  static const std::vector<std::string>& stageNames();

  Pipeline(const Scene& scene, const Camera& camera, const PipelineSettings& settings,
           Strategies strategies, ShaderCompiler& shaders);
  ~Pipeline();

  FrameTimes renderFrame();
  // The last frame's outputs, top row first: direct, indirect, combined, albedo, normal, depth
  // (view depth in metres; 0 where no surface was hit).
  std::vector<NamedImage> readOutputs() const;
  // Re-runs clearing and injection alone and measures the flux balance on the coarsest level
  // (which holds the whole scene; a diagnostic: reads the RSM and the grid back to the CPU).
  InjectionBalance measureInjection();
  // A level's current / accumulated coefficients as floats (grid.glsl layout); level 0 is the
  // finest (the only one without cascades).
  std::vector<float> readGrid(bool accumulated, int level = 0) const;

  // Moves the camera; finer cascade levels follow it from the next frame on (with "depth"
  // placement each frame places them after its G-buffer; the "clear" stage includes that
  // read-back), and so do directional light views that follow the camera.
  void setCamera(const Camera& camera);
  // The scene moved (a frame of an animation, framework/animation/animation.h): the lights and
  // the meshes' vertices are taken again from `scene`, which holds the same lights and meshes as
  // at construction, moved. The light views follow the lights, and the scene's bounds when geometry
  // moved.
  void moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved);
  // Geometry the raster passes draw beside the scene's meshes (extra_geometry.h: particles'
  // light-field billboards), from the next frame on; the caller keeps it alive as long as it
  // renders frames.
  void addExtraGeometry(const ExtraGeometry* extra) { extras_.push_back(extra); }
  // The light grids, finest first, where the last frame placed them.
  const std::vector<LightGrid>& levels() const { return levels_; }
  // Diagnostics (tests, audits): the last frame's light maps (the RSMs every injection reads),
  // and a level's resources (named_resources.h), e.g. to read the injected normal grid back.
  const LightMaps& lightMaps() const;
  const ResourceTable& resources(int level = 0) const { return resources_.at(level); }
  // Cells one propagation iteration updates, over every level (for cell-iterations/s).
  std::size_t propagatedCells() const;
  const Requirements& requirements() const { return requirements_; }
  const Strategies& strategies() const { return strategies_; }
  // The backend the run resolved ([compute] backend) and where each strategy's kernels run:
  // {"backend": ..., "raster_passes": "gl", "strategies": {table: "cpu" | "gl"}}.
  nlohmann::json computeReport() const;
  // What each stage does per frame (strategy.h's WorkCount), by stage name: a list of
  // {unit, units, multiply_adds_per_unit, bytes_per_unit, multiply_adds, bytes}; the raster
  // passes count their texels and pixels only (their arithmetic is the rasteriser's), and a
  // strategy that does not model its work yet is listed by table with "not_counted".
  // `glKernels`: the work of the GL kernels whatever the backend (what a GPU would run: the
  // analysis's GPU estimate, analysis/lpvlab_analysis/gpu_estimate.py, is made from it).
  nlohmann::json workReport(bool glKernels = false) const;
  // Bytes per resource group (GL buffers and textures; host buffers of strategies on the CPU).
  nlohmann::json memoryReport() const;

  // Derivatives through a frame (dual_frame.h): renders a frame, then runs the stages from the
  // first seeded one on dual numbers. `seeds`: at most kDualSlots parameter keys
  // ("<table>.<name>"), each one derivativeRefusal accepts (an Error otherwise).
  struct FrameDerivatives {
    Image indirect;                  // the dual pass's values, RGB, top row first
    std::vector<Image> derivatives;  // per seed: d indirect / d parameter, RGB, top row first
  };
  FrameDerivatives renderDerivatives(const std::vector<std::string>& seeds);
  // Why the derivatives with respect to `key` cannot be carried through this composition's
  // frames, or "" if they can.
  std::string derivativeRefusal(const std::string& key) const;

private:
  template <class F>
  void stage(const std::string& name, FrameTimes& times, F&& work);
  Frame frame(int level);
  // Places the finer cascade levels around `focus` ("depth" placement), or by the eye rule.
  void placeLevels(const std::optional<glm::vec3>& focus = std::nullopt);
  void clearGrids();
  // Stages clear to indirect: LPV's strategies (when the experiment has no other method).
  void renderLpvStages(FrameTimes& times);
  void injectAll(int level);
  // The light views for the current camera, lights and scene bounds.
  LightViews lightViews() const;

  PipelineSettings settings_;
  Camera camera_;
  std::vector<Light> lights_;  // as last placed (moveScene), with the scene's bounds then
  Bounds sceneBounds_;
  Strategies strategies_;
  std::unique_ptr<SceneGpu> scene_;
  std::vector<const ExtraGeometry*> extras_;
  std::unique_ptr<GBufferPass> gbufferPass_;
  std::unique_ptr<LightMapsPass> lightMapsPass_;
  std::unique_ptr<DirectLighting> direct_;
  Requirements requirements_;
  std::vector<LightGrid> levels_;  // finest first
  std::vector<ResourceTable> resources_;  // per level: the resources the composition uses
  std::unique_ptr<CascadeCarry> carry_;                            // with carrying cascades only
  DualImage directImage_, indirectImage_;  // the frame's outputs, on the side that wrote them
  GpuTimer gpuTimer_;
  std::set<std::string> cpuStages_;  // stages with a strategy on the CPU backend
  HostReadback hostReadback_;        // this frame's images read back for them
  int geometryVersion_ = 0;  // moves of the scene's geometry so far (Frame::geometryVersion)
  bool keepInjected_ = false;        // renderFrame keeps the injected grid (renderDerivatives)
  std::vector<float> injected_;
};

}  // namespace lpvlab

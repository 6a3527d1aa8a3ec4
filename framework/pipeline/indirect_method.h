#pragma once
// An indirect-light method ([indirect] method in the experiment file): LPV ("lpv", the default:
// variants/methods/lpv/, with its strategies), instant radiosity, radiosity, ... Every method runs
// after the same raster passes (shadow maps, RSMs, G-buffer) and the same direct light, and
// writes the same `indirect` image: so every run, whatever its method, has the same AOVs,
// per-stage timings, memory and work reports, and summaries, equal-time tables and plots need no
// case for it. The pipeline never asks which method runs: what a method needs it declares
// (consumes), what it reports it gives through the virtual functions below, and what only some
// methods can do (derivatives through a frame, diagnostics after the timed frames) is a
// capability every method answers, most by refusing.
//
// A method lives in variants/methods/<name>/, reads its parameters from the [indirect] table in
// its constructor (unread keys are errors) and registers itself:
//   LPVLAB_REGISTER(IndirectMethod, "instant_radiosity", "one-line description", InstantRadiosity);
// A method that reads further top-level tables names them (LPVLAB_REGISTER_READING): so that one
// file can sweep indirect.method over methods, those tables are read and checked whichever
// method runs, and recorded in the configuration only when theirs does.

#include <cstddef>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/registry.h"
#include "framework/io/image.h"
#include "framework/pipeline/strategy.h"

namespace lpvlab {

struct Camera;
struct GBuffer;
struct GridGeometry;
struct LightMaps;
struct PipelineSettings;
struct Scene;
class DualImage;
class HostReadback;
class SceneGpu;
class ShaderCompiler;

// What a method is prepared with, once per run.
struct MethodSetup {
  const Scene& scene;  // at construction (moveScene brings later frames' moves)
  const PipelineSettings& settings;
  ShaderCompiler& shaders;
  ComputeBackend backend;       // [compute] backend, resolved against the GL renderer
  const SceneGpu& sceneGpu;     // the scene on GL, as the raster passes draw it
  const LightMaps& lightMaps;   // allocated; each frame renders them before render()
  const Camera& camera;         // at construction (setCamera brings later moves)
};

// What one frame gives a method.
struct MethodFrame {
  const Camera& camera;
  const GBuffer& gbuffer;      // this frame's, on GL (read it on the host through `host`)
  const LightMaps& lightMaps;  // this frame's shadow maps and RSMs (those consumed)
  HostReadback& host;          // the raster passes' images on the CPU, read once per frame
  DualImage& indirect;         // the output: W/(m^2 sr), albedo included
  // Runs `work` as the timed stage `name` (one of the method's stageNames()).
  std::function<void(const std::string& name, const std::function<void()>& work)> stage;
};

// A method's light grid as it stood after the last frame ([output] dump_grid, lpvlab run
// --dump-grid): an array in C order with its axes named, and what a reader needs to place and
// interpret it.
struct GridDump {
  std::vector<std::size_t> shape;
  std::vector<std::string> axes;  // one name per axis of `shape`, outermost first
  std::vector<float> values;
  nlohmann::json description;     // units, basis, and per level where the cells are
};

// A WorkCount as the manifest's work report lists it.
nlohmann::json workCountJson(const WorkCount& work);

class IndirectMethod {
public:
  virtual ~IndirectMethod() = default;

  // Its stages in the order a frame runs them (timing and work-report names), e.g. {"vpls",
  // "indirect"}. The stage that writes the image is called "indirect".
  virtual std::vector<std::string> stageNames() const = 0;
  // The raster inputs it reads (raster_inputs.h); the pipeline renders only those (and the
  // G-buffer, and shadow maps for direct light).
  virtual std::set<std::string> consumes() const = 0;
  // Whether its kernels run on the CPU.
  virtual bool runsOnCpu() const { return true; }
  // Whether, after prepare, a kernel of it reads the raster passes' images as GL textures (not
  // through MethodFrame::host): then images the ray-cast raster passes make on the host are
  // uploaded to GL each frame (host_raster.h). By default when it does not run on the CPU.
  virtual bool readsRasterImagesOnGl() const { return !runsOnCpu(); }
  // The stages whose work runs on the CPU after prepare (their time is then wall time, which
  // GL timestamps do not see). By default every stage if runsOnCpu().
  virtual std::set<std::string> cpuStages() const;
  // Refuses, with an Error, what cannot run with these settings (checked when the experiment is
  // read, before any GL); "cpu" as the backend checks that every kernel has a CPU version.
  virtual void check(const PipelineSettings& settings) const { (void)settings; }
  virtual void prepare(const MethodSetup& setup) = 0;
  // Renders one frame. The output image is zeros when it starts.
  virtual void render(MethodFrame& frame) = 0;
  // The scene moved (an animation's frame): `scene` holds the same lights and meshes as at
  // prepare, moved.
  virtual void moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved) = 0;
  // The camera moved (from the next frame on).
  virtual void setCamera(const Camera& camera) { (void)camera; }
  // Whether a frame depends on the frames before it (see Strategy::keepsStateBetweenFrames).
  virtual bool keepsStateBetweenFrames() const { return false; }

  // The last frame's work per stage (WorkCount, strategy.h), counted as it ran (a method's work
  // can depend on the scene: VPLs a random walk found, rays it traced).
  virtual std::map<std::string, std::vector<WorkCount>> work() const = 0;
  // The work report's entries by stage (workCountJson each, or an entry naming what is not
  // counted). `glKernels`: the work of the GL kernels whatever the backend (what a GPU would
  // run); by default work() as it ran.
  virtual nlohmann::json workReport(bool glKernels) const;
  // Bytes the method holds (host and GL).
  virtual std::size_t memoryBytes() const = 0;
  // The memory report's entries, by group: {"indirect_method": memoryBytes()} by default.
  virtual nlohmann::json memoryReport() const;
  // Where its kernels run, for the manifest's "compute": {"indirect_method": {"name", "runs_on"}}
  // by default.
  virtual nlohmann::json computeReport() const;
  // The configuration keys ("<table>.<name>") that tell this method's configurations apart in a
  // sweep's summary.csv (columns param.<key>) beside the swept ones, e.g. LPV's strategy types and
  // grid. None by default: a sweep's swept keys already name what varies.
  virtual std::vector<std::string> summaryKeys() const { return {}; }
  // What the last frame did (e.g. VPL counts, the energy a clamp removed); an object.
  virtual nlohmann::json statistics() const { return nlohmann::json::object(); }
  // The manifest's entries about the method, given each stage's median time (ms):
  // {"indirect_method": {"name", "statistics"}} by default.
  virtual nlohmann::json describe(const std::map<std::string, double>& medianStageMs) const;
  // Whether it keeps a light grid that dumpGrid() gives (LPV's SH grid); asked when the
  // experiment is read, before any frame.
  virtual bool hasLightGrid() const { return false; }
  // Its light grid after the last frame (only where hasLightGrid()).
  virtual GridDump dumpGrid() const;
  // Diagnostics measured after the timed frames, which may re-run part of a frame (LPV's
  // injection flux balance): manifest entries, none by default. A "warnings" array among them
  // (sentences) joins the run's warnings instead.
  virtual nlohmann::json audit() { return nlohmann::json::object(); }

  // lpvlab explain's grid oracles (framework/explain/, docs/explain.md): why this method's frame
  // cannot be explained stage by stage, or "" if it can. By default none can (no light grid).
  virtual std::string explainRefusal() const;
  // Fills one level's accumulated light grid: given its placement and SH coefficients per
  // channel, the floats in grid.glsl's layout.
  using GridFill = std::function<std::vector<float>(const GridGeometry& geometry, int coefficients)>;
  // After a frame: the indirect image (RGB, top row first) the method's own rendering makes from
  // the grids `fill` gives every level, in place of the propagated ones. Only where
  // explainRefusal() is "".
  virtual Image renderFromGrids(const GridFill& fill);
  // Whether its propagation blocks light by the scene's geometry (LPV with a GV): the exact grid
  // it is compared with is then the one with visibility.
  virtual bool gridBlocksLight() const { return false; }

  // Derivatives through a frame (dual_frame.h): why d indirect / d `key` ("<table>.<name>")
  // cannot be carried through this method's frames, or "" if it can. By default none can.
  virtual std::string derivativeRefusal(const std::string& key) const;
  struct FrameDerivatives {
    Image indirect;                  // the dual pass's values, RGB, top row first
    std::vector<Image> derivatives;  // per seed: d indirect / d parameter, RGB, top row first
  };
  // Renders a frame with `renderFrame` (the pipeline's), then the derivatives of its indirect
  // image with respect to `seeds`, each one derivativeRefusal accepts.
  virtual FrameDerivatives renderDerivatives(const std::vector<std::string>& seeds,
                                             const std::function<void()>& renderFrame);

  // The registered name, set when the experiment creates the method.
  const std::string& name() const { return name_; }
  void setRegisteredName(std::string name) { name_ = std::move(name); }

private:
  std::string name_;
};

}  // namespace lpvlab

#pragma once
// An indirect-light method other than LPV ([indirect] method in the experiment file; "lpv", the
// default, is the pipeline's own stages and strategies). A method runs after the same raster
// passes (shadow maps, RSMs, G-buffer) and the same direct light as LPV, in place of LPV's
// clear, occlusion, injection, propagation and indirect stages, and writes the same `indirect`
// image: so every run, whatever its method, has the same AOVs, per-stage timings, memory and work
// reports, and summaries, equal-time tables and plots need no case for it.
//
// A method lives in variants/methods/<name>/, reads its parameters from the [indirect] table in
// its constructor (unread keys are errors) and registers itself:
//   LPVLAB_REGISTER(IndirectMethod, "instant_radiosity", "one-line description", InstantRadiosity);

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/registry.h"
#include "framework/pipeline/strategy.h"

namespace lpvlab {

struct Camera;
struct GBuffer;
struct LightMaps;
struct PipelineSettings;
struct Scene;
class DualImage;
class HostReadback;
class ShaderCompiler;

// What a method is prepared with, once per run.
struct MethodSetup {
  const Scene& scene;  // at construction (moveScene brings later frames' moves)
  const PipelineSettings& settings;
  ShaderCompiler& shaders;
};

// What one frame gives a method.
struct MethodFrame {
  const Camera& camera;
  const GBuffer& gbuffer;      // this frame's, on GL (read it on the host through `host`)
  const LightMaps& lightMaps;  // this frame's shadow maps and RSMs
  HostReadback& host;          // the raster passes' images on the CPU, read once per frame
  DualImage& indirect;         // the output, zeros when the frame starts: W/(m^2 sr), albedo included
  // Runs `work` as the timed stage `name` (one of the method's stageNames()).
  std::function<void(const std::string& name, const std::function<void()>& work)> stage;
};

class IndirectMethod {
public:
  virtual ~IndirectMethod() = default;

  // Its stages in the order a frame runs them (timing and work-report names), e.g. {"vpls",
  // "indirect"}. The stage that writes the image is called "indirect", as LPV's is.
  virtual std::vector<std::string> stageNames() const = 0;
  // Whether its kernels run on the CPU (its stages' device time is then their wall time).
  virtual bool runsOnCpu() const { return true; }
  virtual void prepare(const MethodSetup& setup) = 0;
  virtual void render(MethodFrame& frame) = 0;
  // The scene moved (an animation's frame): `scene` holds the same lights and meshes as at
  // prepare, moved.
  virtual void moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved) = 0;
  // Whether a frame depends on the frames before it (see Strategy::keepsStateBetweenFrames).
  virtual bool keepsStateBetweenFrames() const { return false; }
  // Whether it reads the reflective shadow maps (the pipeline renders them only then: a method
  // that makes its VPLs otherwise has no "rsm" stage).
  virtual bool readsReflectiveShadowMaps() const = 0;
  // Whether emissive surfaces light the scene through it (area lights): a scene lit only by them
  // then runs (the pipeline otherwise needs a point, spot or directional light).
  virtual bool lightsWithEmissiveSurfaces() const { return false; }

  // The last frame's work per stage (WorkCount, strategy.h), counted as it ran (a method's work
  // can depend on the scene: VPLs a random walk found, rays it traced).
  virtual std::map<std::string, std::vector<WorkCount>> work() const = 0;
  // Bytes the method holds (host and GL).
  virtual std::size_t memoryBytes() const = 0;
  // What the last frame did, for the run's manifest (e.g. VPL counts, the energy a clamp
  // removed); an object.
  virtual nlohmann::json statistics() const { return nlohmann::json::object(); }

  // The registered name, set when the experiment creates the method.
  const std::string& name() const { return name_; }
  void setRegisteredName(std::string name) { name_ = std::move(name); }

private:
  std::string name_;
};

}  // namespace lpvlab

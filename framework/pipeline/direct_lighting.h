#pragma once
// Direct light: Lambertian, shadow-mapped, plus emission (shaders/lighting/direct_light.glsl), on
// GL (direct.comp) or, on the CPU backend, on the CPU (direct_lighting_cpu.h) from the frame's
// host images; there, with [light_maps] shadows = "rays", shadowed by exact rays instead
// (HostRaster::shadowRays).

#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/dual_image.h"
#include "framework/pipeline/host_raster.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"

namespace lpvlab {

struct ShadowSettings {
  float normalOffsetTexels = 1.5f;  // move the lookup point this many shadow texels along n
  float depthBias = 2e-5f;          // window-depth units subtracted before comparing
  // [light_maps] shadows = "rays": exact shadow rays (HostRaster::shadowRays) instead of the
  // shadow maps, which are then not rendered for direct light; on the CPU only.
  bool rays = false;
};

class DirectLighting {
public:
  // onCpu: run on the CPU (the backend is "cpu", or "auto" on a software GL renderer).
  // shadowRays: what traces settings.rays' shadow rays (kept by the caller); an Error when they
  // are asked for without it or on GL.
  DirectLighting(ShaderCompiler& shaders, ShadowSettings settings, bool onCpu,
                 HostRaster* shadowRays = nullptr);
  // `host`: the frame's read-back images (used on the CPU).
  void render(const GBuffer& gbuffer, const LightMaps& maps, DualImage& direct, HostReadback& host);
  bool onCpu() const { return onCpu_; }
  // What it does per frame (strategy.h's WorkCount), for `pixels` and `lights`, by its kernel
  // (`glKernel` false) or by the GL kernel whatever the backend (true).
  WorkCount work(double pixels, int lights, bool glKernel = false) const;

private:
  void renderOnCpu(const GBuffer& gbuffer, const LightMaps& maps, DualImage& direct,
                   HostReadback& host);

  Program program_;
  ShadowSettings settings_;
  bool onCpu_;
  HostRaster* shadowRays_ = nullptr;
  std::vector<float> visibility_;  // the last frame's shadow rays, pixels x lights
};

}  // namespace lpvlab

#pragma once
// Direct light on the CPU (the CPU backend, strategy.h): every G-buffer pixel through the GL
// kernel's own per-pixel function (shaders/lighting/direct_light.glsl, compiled as C++ in single
// precision, as GL runs it); the shadow taps are GL's LINEAR depth-compare filtering written out
// (shaders/lighting/shadow_tap.glsl) on the shadow maps read back once per frame. Rows of pixels
// are shared out by oneTBB; each pixel is written by one task, so the image does not depend on the
// thread count.

#include <vector>

#include "framework/core/cpu_dispatch.h"
#include "framework/pipeline/host_readback.h"
#include "framework/pipeline/light_views.h"

namespace lpvlab {

struct DirectCpuInputs {
  const HostImage* position = nullptr;  // the G-buffer (RGBA; position.w = 0: no surface)
  const HostImage* normal = nullptr;
  const HostImage* albedo = nullptr;
  const HostImage* emission = nullptr;  // null: no surface emits
  const HostDepthImage* shadowDepth = nullptr;  // one layer per light view (unread with visibility)
  // Exact shadow rays ([light_maps] shadows = "rays", HostRaster::shadowRays): per pixel and
  // light, 1 where the way is open; null: the shadow maps.
  const std::vector<float>* visibility = nullptr;
  const LightViews* records = nullptr;
  float normalOffsetTexels = 0.0f;  // ShadowSettings
  float depthBias = 0.0f;
  CpuKernelLevel instructions = pixelKernelLevel();  // cpu_dispatch.h
};

// `out` (the G-buffer's size) gets the direct radiance, W/(m^2 sr), alpha 1 where there is a
// surface and 0 elsewhere, as the GL kernel writes. Throws an Error for images of different sizes,
// a shadow map without a layer per view, or a visibility of another size than pixels x lights.
void directLightingCpu(const DirectCpuInputs& in, HostImage& out);

}  // namespace lpvlab

// direct_light.glsl's reads (see its header) over host copies: the light and view records and the
// shadow maps read back; shadow_tap.glsl filters as GL's texture unit does. Included between
// LPVLAB_SHARED_GLSL_BEGIN and _END (framework/math/shared.h), after shared.h, so it takes the
// including translation unit's precision: single in the CPU kernel (direct_lighting_cpu.cpp),
// double in the tests that check it.
#include "shaders/common/lights_gpu.glsl"
using glm::mix;
struct DirectLightKernel {
  const GpuLight* lights;
  const GpuView* views;
  const float* depths;  // layer `view`, row y, texel x at (view * resolution + y) * resolution + x
  int resolution;
  // Exact shadow rays' results ([light_maps] shadows = "rays"): rayVisibility[pixel * lightCount
  // + light], for the pixel being shaded; null: the shadow maps.
  const float* rayVisibility = nullptr;
  int lightCount = 0;
  std::size_t pixel = 0;
  GpuLight directLight(int i) { return lights[i]; }
  GpuView directView(int v) { return views[v]; }
  real shadowDepth(int view, ivec2 texel) {
    return real(depths[(std::size_t(view) * resolution + std::size_t(texel.y)) * resolution +
                       std::size_t(texel.x)]);
  }
  real shadowTaps3x3(int view, vec2 uv, real reference) {
    return shadowTaps3x3Bilinear(view, uv, reference, resolution);
  }
  real lightVisibility(int light, int view, vec3 p, vec3 n, real offset, int resolution, real depthBias) {
    if (rayVisibility) return real(rayVisibility[pixel * std::size_t(lightCount) + std::size_t(light)]);
    return shadowVisibility(view, p + n * offset, resolution, depthBias);
  }
#include "shaders/lighting/shadow_tap.glsl"
#define LPVLAB_DIRECT_LIGHT_VISIBILITY 1
#include "shaders/lighting/direct_light.glsl"
#undef LPVLAB_DIRECT_LIGHT_VISIBILITY
};

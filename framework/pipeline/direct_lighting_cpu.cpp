#include "framework/pipeline/direct_lighting_cpu.h"

#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/math/shared.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/common/lights_gpu.glsl"
using glm::mix;
// direct_light.glsl's reads (see its header) over the frame's host copies: the records in double
// precision and the shadow maps read back; shadow_tap.glsl filters as GL's texture unit does.
struct DirectLightKernel {
  const GpuLight* lights;
  const GpuView* views;
  const float* depths;
  int resolution;
  GpuLight directLight(int i) { return lights[i]; }
  GpuView directView(int v) { return views[v]; }
  real shadowDepth(int view, ivec2 texel) {
    return real(depths[(std::size_t(view) * resolution + std::size_t(texel.y)) * resolution +
                       std::size_t(texel.x)]);
  }
  real shadowTaps3x3(int view, vec2 uv, real reference) {
    return shadowTaps3x3Bilinear(view, uv, reference, resolution);
  }
#include "shaders/lighting/shadow_tap.glsl"
#include "shaders/lighting/direct_light.glsl"
};
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

void directLightingCpu(const DirectCpuInputs& in, HostImage& out) {
  const std::size_t pixels = in.position->texels.size();
  for (const HostImage* image : {in.normal, in.albedo, in.emission, static_cast<const HostImage*>(&out)})
    if (image->texels.size() != pixels)
      throw Error("direct light (CPU): the G-buffer's images and the output differ in size");
  const HostDepthImage& shadow = *in.shadowDepth;
  if (shadow.width != shadow.height || std::size_t(shadow.layers) < in.records->views.size())
    throw Error("direct light (CPU): the shadow maps are not square or lack a layer per view");
  const auto [lights, views] = sharedLightViews<shared::GpuLight, shared::GpuView>(*in.records);
  const int width = in.position->width;
  tbb::parallel_for(tbb::blocked_range<int>(0, in.position->height), [&](const tbb::blocked_range<int>& rows) {
    shared::DirectLightKernel kernel{lights.data(), views.data(), shadow.depths.data(), shadow.width};
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        const std::size_t i = std::size_t(y) * width + x;
        const glm::vec4 p = in.position->texels[i];
        if (p.w == 0.0f) {
          out.texels[i] = glm::vec4(0.0f);
          continue;
        }
        const glm::dvec3 radiance = kernel.directRadiance(
            glm::dvec3(p), glm::dvec3(in.normal->texels[i]), glm::dvec3(in.albedo->texels[i]),
            glm::dvec3(in.emission->texels[i]), int(lights.size()), shadow.width,
            double(in.normalOffsetTexels), double(in.depthBias));
        out.texels[i] = glm::vec4(glm::vec3(radiance), 1.0f);
      }
  });
}

}  // namespace lpvlab

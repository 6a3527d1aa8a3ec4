#include "framework/pipeline/direct_lighting_cpu.h"

#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/cpu_dispatch.h"
#include "framework/core/error.h"
#define LPVLAB_SHARED_SINGLE_PRECISION 1
#include "framework/math/shared.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "framework/pipeline/direct_light_kernel.h"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

void directLightingCpu(const DirectCpuInputs& in, HostImage& out) {
  const std::size_t pixels = in.position->texels.size();
  for (const HostImage* image : {in.normal, in.albedo, in.emission, static_cast<const HostImage*>(&out)})
    if (image && image->texels.size() != pixels)
      throw Error("direct light (CPU): the G-buffer's images and the output differ in size");
  static const HostDepthImage noMaps;
  const HostDepthImage& shadow = in.shadowDepth ? *in.shadowDepth : noMaps;
  const std::size_t lightCount = in.records->lights.size();
  if (in.visibility && in.visibility->size() != pixels * lightCount)
    throw Error("direct light (CPU): the shadow rays' visibility is not one value per pixel and light");
  if (!in.visibility && (!in.shadowDepth || shadow.width != shadow.height ||
                         std::size_t(shadow.layers) < in.records->views.size()))
    throw Error("direct light (CPU): the shadow maps are missing, not square or lack a layer per view");
  // Named members, not a structured binding: clang 14 cannot capture bindings in lambdas.
  const auto lightViews = sharedLightViews<shared::GpuLight, shared::GpuView>(*in.records);
  const auto& lights = lightViews.lights;
  const auto& views = lightViews.views;
  const int width = in.position->width;
  tbb::parallel_for(tbb::blocked_range<int>(0, in.position->height), [&](const tbb::blocked_range<int>& rows) {
    shared::DirectLightKernel kernel{lights.data(), views.data(), shadow.depths.data(), shadow.width,
                                     in.visibility ? in.visibility->data() : nullptr, int(lightCount)};
    for (int y = rows.begin(); y < rows.end(); ++y)
      runAtLevel(in.instructions, [&] {  // a row at the level asked for (cpu_dispatch.h)
        for (int x = 0; x < width; ++x) {
          const std::size_t i = std::size_t(y) * width + x;
          const glm::vec4 p = in.position->texels[i];
          kernel.pixel = i;
          if (p.w == 0.0f) {
            out.texels[i] = glm::vec4(0.0f);
            continue;
          }
          const glm::vec3 radiance = kernel.directRadiance(
              glm::vec3(p), glm::vec3(in.normal->texels[i]), glm::vec3(in.albedo->texels[i]),
              in.emission ? glm::vec3(in.emission->texels[i]) : glm::vec3(0.0f), int(lights.size()), shadow.width,
              in.normalOffsetTexels, in.depthBias);
          out.texels[i] = glm::vec4(radiance, 1.0f);
        }
      });
  });
}

}  // namespace lpvlab

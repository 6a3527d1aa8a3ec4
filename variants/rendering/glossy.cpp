// Rendering "glossy": "trilinear" (trilinear.cpp, the same kernel and its parameters) plus a
// glossy reflection read by marching the accumulated grid along the reflected view direction
// (thesis 5.5, 6.9.4/7.4.4; Kaplanyan and Dachsbacher 2010): at each step the intensity arriving
// from around the march direction, weighted by a normalised Phong lobe of the given exponent
// (shaders/rendering/phong_lobe.glsl), as radiance I / cellSize^2; the steps' mean times
// specular_albedo is added to `indirect`. The path-traced reference is Lambertian, so
// specular_albedo defaults to 0: then the output is trilinear's exactly and the march is not
// even compiled in. docs/variants/glossy.md#glossy.
//
// | parameter       | type  | default | meaning                                                |
// |-----------------|-------|---------|--------------------------------------------------------|
// | normal_offset   | float | 0.0     | as trilinear (also where the march starts)             |
// | leak_damping    | float | 0.0     | as trilinear (damps the Lambertian part only)          |
// | specular_albedo | float | 0.0     | specular reflectance added on top of the albedo (0..1) |
// | exponent        | float | 32.0    | Phong exponent m of the lobe (1..1e6)                  |
// | step            | float | 1.0     | march step, cells (0.01..16)                           |
// | max_distance    | float | 16.0    | march length, cells (0.01..4096); samples at           |
// |                 |       |         | (j + 1/2) step, j < round(max_distance / step),        |
// |                 |       |         | at most 4096                                           |

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "variants/rendering/trilinear_kernel.h"

namespace lpvlab {

TrilinearKernelOptions TrilinearKernelOptions::readGlossy(Params& params) {
  TrilinearKernelOptions options = readDiffuse(params);
  options.specularAlbedo = params.get<float>("specular_albedo", 0.0f, {.min = 0.0f, .max = 1.0f});
  options.phongExponent = params.get<float>("exponent", 32.0f, {.min = 1.0f, .max = 1e6f});
  options.marchStepCells = params.get<float>("step", 1.0f, {.min = 0.01f, .max = 16.0f});
  const float maxDistance = params.get<float>("max_distance", 16.0f, {.min = 0.01f, .max = 4096.0f});
  // At least one sample, so a march shorter than a step still reads the grid next to the surface.
  const double samples = std::max(1.0, std::round(double(maxDistance) / options.marchStepCells));
  constexpr int kMaxSamples = 4096;  // per pixel: bounds the kernel's time
  if (samples > kMaxSamples) {
    std::ostringstream message;
    message << params.where("max_distance") << " / " << params.where("step") << " asks for "
            << samples << " march samples per pixel; at most " << kMaxSamples
            << " (raise step or lower max_distance)";
    throw Error(message.str());
  }
  options.marchSamples = int(samples);
  return options;
}

namespace {

class GlossyRendering final : public TrilinearKernelRendering {
public:
  explicit GlossyRendering(Params& params)
      : TrilinearKernelRendering(TrilinearKernelOptions::readGlossy(params)) {}
};

LPVLAB_REGISTER(RenderingStrategy, "glossy",
                "trilinear plus glossy reflections ray-marched through the grid along the "
                "reflected view direction (thesis 5.5); specular_albedo = 0: trilinear",
                GlossyRendering);

}  // namespace
}  // namespace lpvlab

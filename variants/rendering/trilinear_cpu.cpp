#include "variants/rendering/trilinear_cpu.h"

#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/cpu_dispatch.h"
#include "framework/core/error.h"
#define LPVLAB_SHARED_SINGLE_PRECISION 1
#include "framework/math/shared.h"

// trilinear_diffuse.glsl reads the accumulated grid through gridCoefficient: here from the level
// being rendered, copied cell by cell (the 3N coefficients of a cell together, so the 8 corners a
// pixel reads are 8 short runs); cascade_weight.glsl reads the levels' placement. Both are set
// before each level's pass over the pixels and only read during it.
LPVLAB_SHARED_GLSL_BEGIN
const float* gridCells = nullptr;
real gridCoefficient(int channel, int k, int coefficients, int cell, int) {
  return real(gridCells[(std::size_t(cell) * 3 + std::size_t(channel)) * std::size_t(coefficients) + std::size_t(k)]);
}
const TrilinearCpuLevel* cascadeLevels = nullptr;
vec3 cascadeLevelOrigin(int level) { return cascadeLevels[level].geometry.origin; }
real cascadeLevelCellSize(int level) { return cascadeLevels[level].geometry.cellSize; }
#include "shaders/rendering/glossy_march.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

namespace blend_kernel {
#include "shaders/common/cascade_blend_interface.glsl"
}

namespace {

// Row y of one level's pass, run at the instruction-set level asked for (cpu_dispatch.h). All it
// calls is inlined into it, so the shared functions' loops over the N coefficients per channel,
// known when compiling, unroll.
template <int N>
void shadeRow(const HostImage& position, const HostImage& normal, const HostImage& albedo,
              std::span<const TrilinearCpuLevel> levels, int current,
              const TrilinearCpuSettings& settings, HostImage& indirect, int y) {
  const TrilinearCpuLevel& level = levels[std::size_t(current)];
  const GridGeometry& g = level.geometry;
  const bool glossy = settings.specularAlbedo > 0.0f;
  const shared::GlossyMarch march{settings.phongExponent, settings.marchStepCells,
                                  settings.marchSamples,  current,
                                  int(levels.size()),     g.resolution,
                                  settings.blendCells};
  for (int x = 0; x < position.width; ++x) {
    const std::size_t i = std::size_t(y) * position.width + x;
    const glm::vec4 p = position.texels[i];
    if (p.w == 0.0f) continue;
    const float weight = shared::cascadeLevelWeight(glm::vec3(p), current, int(levels.size()),
                                                    g.resolution, settings.blendCells);
    if (weight == 0.0f && !glossy) continue;
    const glm::vec3 n(normal.texels[i]);
    glm::vec3 radiance = weight * shared::trilinearDiffuse(glm::vec3(p), n, glm::vec3(albedo.texels[i]),
                                                           g.origin, g.cellSize, g.resolution, N,
                                                           settings.normalOffsetCells,
                                                           settings.leakDamping);
    if (glossy)
      radiance += shared::glossyRadiance(glm::vec3(p), n, settings.cameraPosition,
                                         settings.specularAlbedo, settings.normalOffsetCells,
                                         march, g.origin, g.cellSize, N);
    indirect.texels[i] += glm::vec4(settings.scale * radiance, weight);
  }
}

// One level's pass over the pixels, its grid first copied cell by cell.
template <int N>
void addLevel(const HostImage& position, const HostImage& normal, const HostImage& albedo,
              std::span<const TrilinearCpuLevel> levels, int current,
              const TrilinearCpuSettings& settings, HostImage& indirect) {
  const TrilinearCpuLevel& level = levels[std::size_t(current)];
  const std::size_t cells = std::size_t(level.geometry.cellCount());
  std::vector<float> byCell(cells * 3 * N);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < N; ++k)
      for (std::size_t cell = 0; cell < cells; ++cell)
        byCell[(cell * 3 + std::size_t(channel)) * N + std::size_t(k)] =
            level.accumulated[(std::size_t(channel) * N + std::size_t(k)) * cells + cell];
  shared::gridCells = byCell.data();
  shared::cascadeLevels = levels.data();
  tbb::parallel_for(tbb::blocked_range<int>(0, position.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      runAtLevel(settings.instructions, [&] { shadeRow<N>(position, normal, albedo, levels, current, settings, indirect, y); });
  });
  shared::gridCells = nullptr;
  shared::cascadeLevels = nullptr;
}

}  // namespace

void trilinearDiffuseCpu(const HostImage& position, const HostImage& normal,
                         const HostImage& albedo, std::span<const TrilinearCpuLevel> levels,
                         const TrilinearCpuSettings& settings, HostImage& indirect) {
  for (const HostImage* image : {&normal, &albedo, static_cast<const HostImage*>(&indirect)})
    if (image->width != position.width || image->height != position.height)
      throw Error("trilinear rendering (CPU): the G-buffer and the output differ in size");
  if (levels.size() > std::size_t(blend_kernel::CASCADE_MAX_LEVELS))
    throw Error("trilinear rendering (CPU): at most " +
                std::to_string(blend_kernel::CASCADE_MAX_LEVELS) + " levels can be rendered");
  for (int current = 0; current < int(levels.size()); ++current) {
    switch (settings.coefficients) {
      case 4: addLevel<4>(position, normal, albedo, levels, current, settings, indirect); break;
      case 9: addLevel<9>(position, normal, albedo, levels, current, settings, indirect); break;
      case 16: addLevel<16>(position, normal, albedo, levels, current, settings, indirect); break;
      default:
        throw Error("trilinear rendering (CPU): " + std::to_string(settings.coefficients) +
                    " SH coefficients per channel is not 4, 9 or 16");
    }
  }
}

}  // namespace lpvlab

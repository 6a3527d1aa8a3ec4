// The CPU trilinear rendering's pass over the pixels (trilinear_cpu.h), included by each
// translation unit that compiles it, after framework/math/shared.h of its precision:
// trilinear_cpu.cpp in single precision (as GL runs it), trilinear_cpu_dual.cpp on dual numbers
// (the derivatives). One text: the kernel's types are the shared GLSL's (shared::real, vec3,
// vec4), the grid holds shared::real, and it defines addLevels for the images of that precision.
// Not a header of its own: no include guard, no declarations for other files.

// trilinear_diffuse.glsl reads the accumulated grid through gridCoefficient: here from the level
// being rendered, copied cell by cell (the 3N coefficients of a cell together, so the 8 corners a
// pixel reads are 8 short runs); cascade_weight.glsl reads the levels' placement. Both are set
// before each level's pass over the pixels and only read during it.
LPVLAB_SHARED_GLSL_BEGIN
const real* gridCells = nullptr;
real gridCoefficient(int channel, int k, int coefficients, int cell, int) {
  return real(gridCells[(std::size_t(cell) * 3 + std::size_t(channel)) * std::size_t(coefficients) + std::size_t(k)]);
}
const TrilinearLevelOf<real>* cascadeLevels = nullptr;
vec3 cascadeLevelOrigin(int level) { return vec3(cascadeLevels[level].geometry.origin); }
real cascadeLevelCellSize(int level) { return real(cascadeLevels[level].geometry.cellSize); }
#include "shaders/rendering/glossy_march.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

namespace {

using TrilinearLevel = TrilinearLevelOf<shared::real>;
using TrilinearSettings = TrilinearSettingsOf<shared::real>;

// Row y of one level's pass, run at the instruction-set level asked for (cpu_dispatch.h). All it
// calls is inlined into it, so the shared functions' loops over the N coefficients per channel,
// known when compiling, unroll.
template <int N, class Image>
void shadeRow(const HostImage& position, const HostImage& normal, const HostImage& albedo,
              std::span<const TrilinearLevel> levels, int current,
              const TrilinearSettings& settings, Image& indirect, int y) {
  using shared::real;
  using shared::vec3;
  using shared::vec4;
  const TrilinearLevel& level = levels[std::size_t(current)];
  const GridGeometry& g = level.geometry;
  const vec3 origin(g.origin);
  const real cellSize(g.cellSize);
  const bool glossy = settings.specularAlbedo > 0.0f;
  const shared::GlossyMarch march{settings.phongExponent, settings.marchStepCells,
                                  settings.marchSamples,  current,
                                  int(levels.size()),     g.resolution,
                                  settings.blendCells};
  for (int x = 0; x < position.width; ++x) {
    const std::size_t i = std::size_t(y) * position.width + x;
    const glm::vec4 p = position.texels[i];
    if (p.w == 0.0f) continue;
    const vec3 at(p);
    const real weight = shared::cascadeLevelWeight(at, current, int(levels.size()), g.resolution,
                                                   settings.blendCells);
    if (weight == real(0.0f) && !glossy) continue;
    const vec3 n(normal.texels[i]);
    vec3 radiance = weight * shared::trilinearDiffuse(at, n, vec3(albedo.texels[i]), origin,
                                                      cellSize, g.resolution, N,
                                                      settings.normalOffsetCells,
                                                      settings.leakDamping);
    if (glossy)
      radiance += shared::glossyRadiance(at, n, vec3(settings.cameraPosition),
                                         settings.specularAlbedo, settings.normalOffsetCells,
                                         march, origin, cellSize, N);
    indirect.texels[i] += vec4(settings.scale * radiance, weight);
  }
}

// One level's pass over the pixels, its grid first copied cell by cell.
template <int N, class Image>
void addLevel(const HostImage& position, const HostImage& normal, const HostImage& albedo,
              std::span<const TrilinearLevel> levels, int current,
              const TrilinearSettings& settings, Image& indirect) {
  const TrilinearLevel& level = levels[std::size_t(current)];
  const std::size_t cells = std::size_t(level.geometry.cellCount());
  std::vector<shared::real> byCell(cells * 3 * N);
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

// Every level, for the SH order of the settings.
template <class Image>
void addLevels(const HostImage& position, const HostImage& normal, const HostImage& albedo,
               std::span<const TrilinearLevel> levels, const TrilinearSettings& settings,
               Image& indirect) {
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

}  // namespace

}  // namespace lpvlab

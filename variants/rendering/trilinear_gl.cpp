#include "variants/rendering/trilinear_gl.h"

#include "framework/gl/dispatch.h"
#include "framework/pipeline/cascade_blend.h"

namespace lpvlab {
namespace {
namespace kernel {
#include "shaders/rendering/trilinear_interface.glsl"
}
}  // namespace

TrilinearGlWork trilinearGlWork(const TrilinearKernelOptions& options, int coefficients) {
  const double n = coefficients;
  const double reads = options.leakDamping > 0.0f ? 2.0 : 1.0;
  TrilinearGlWork w{.pixelMultiplyAdds = reads * (24 * n + 8 + 3 * n) + n,
                    .pixelBytes = 3 * 16 + 2 * 16 + reads * 96 * n};
  if (options.specularAlbedo > 0.0f) {
    w.pixelMultiplyAdds += n;
    w.sampleMultiplyAdds = 24 * n + 8 + 3 * n;
    w.sampleBytes = 96 * n;
  }
  return w;
}

TrilinearGlKernel::TrilinearGlKernel(ShaderCompiler& shaders, const TrilinearKernelOptions& options,
                                     int coefficients)
    : options_(options),
      program_(shaders.compute("rendering/trilinear.comp",
                               {SpecConstant::i(0, coefficients),
                                SpecConstant::b(1, options.leakDamping > 0.0f),
                                SpecConstant::b(2, options.specularAlbedo > 0.0f)})) {}

void TrilinearGlKernel::render(const TrilinearGlTarget& target,
                               std::span<const TrilinearGlLevel> levels, float blendCells,
                               const glm::vec3& cameraPosition) const {
  using namespace kernel;
  program_.use();
  glBindTextureUnit(UNIT_G_POSITION, target.position);
  glBindTextureUnit(UNIT_G_NORMAL, target.normal);
  glBindTextureUnit(UNIT_G_ALBEDO, target.albedo);
  glBindImageTexture(IMAGE_OUT_INDIRECT, target.indirect, 0, GL_FALSE, 0, GL_READ_WRITE,
                     GL_RGBA32F);
  glUniform1f(LOCATION_NORMAL_OFFSET_CELLS, options_.normalOffsetCells);
  glUniform1f(LOCATION_INDIRECT_SCALE, options_.scale);
  // An option that is off is compiled out with its uniforms, which then must not be set.
  if (options_.leakDamping > 0.0f) glUniform1f(LOCATION_LEAK_DAMPING_STRENGTH, options_.leakDamping);
  if (options_.specularAlbedo > 0.0f) {
    glUniform3fv(LOCATION_CAMERA_POSITION, 1, &cameraPosition[0]);
    glUniform1f(LOCATION_SPECULAR_ALBEDO, options_.specularAlbedo);
    glUniform1f(LOCATION_PHONG_EXPONENT, options_.phongExponent);
    glUniform1f(LOCATION_MARCH_STEP_CELLS, options_.marchStepCells);
    glUniform1i(LOCATION_MARCH_SAMPLES, options_.marchSamples);
  }
  std::vector<GridGeometry> placements;
  for (const TrilinearGlLevel& level : levels) placements.push_back(level.geometry);
  // One dispatch per cascade level, each adding its weighted share.
  for (std::size_t level = 0; level < levels.size(); ++level) {
    const GridGeometry& grid = levels[level].geometry;
    levels[level].accumulated->bindStorage(BUFFER_ACCUMULATED);
    glUniform3fv(LOCATION_GRID_ORIGIN, 1, &grid.origin[0]);
    glUniform1f(LOCATION_CELL_SIZE, grid.cellSize);
    glUniform3iv(LOCATION_RESOLUTION, 1, &grid.resolution[0]);
    setCascadeBlendUniforms(placements, int(level), blendCells);
    dispatchCovering({target.width, target.height, 1}, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                     GL_ALL_BARRIER_BITS);
  }
}

}  // namespace lpvlab

#include "variants/injection/rsm_vpl_gl.h"

#include "framework/gl/dispatch.h"

namespace lpvlab {
namespace {
namespace kernel {
#include "shaders/injection/rsm_vpl_interface.glsl"
}
}  // namespace

KernelWork rsmVplGlWork(int coefficients, bool withNormals) {
  const double n = coefficients, normals = withNormals ? 4.0 : 0.0;
  return {4 * n + 10 + normals, 3 * 16 + 8 * (3 * n + normals)};
}

RsmVplGlKernel::RsmVplGlKernel(ShaderCompiler& shaders, int coefficients, bool withNormals,
                               float shiftCells)
    : withNormals_(withNormals), shiftCells_(shiftCells),
      program_(shaders.compute("injection/rsm_vpl.comp", {SpecConstant::i(0, coefficients),
                                                          SpecConstant::b(1, withNormals)})) {}

void RsmVplGlKernel::inject(const RsmVplGlMaps& maps, const GridGeometry& geometry,
                            DualBuffer& grid, const gl::Buffer* normals) const {
  using namespace kernel;
  program_.use();
  glBindTextureUnit(UNIT_RSM_POSITION, maps.position);
  glBindTextureUnit(UNIT_RSM_NORMAL, maps.normal);
  glBindTextureUnit(UNIT_RSM_FLUX, maps.flux);
  grid.bindStorage(BUFFER_GRID);
  if (withNormals_) normals->bindStorage(BUFFER_NORMALS);
  glUniform3fv(LOCATION_GRID_ORIGIN, 1, &geometry.origin[0]);
  glUniform1f(LOCATION_CELL_SIZE, geometry.cellSize);
  glUniform3iv(LOCATION_RESOLUTION, 1, &geometry.resolution[0]);
  glUniform1f(LOCATION_SHIFT_CELLS, shiftCells_);
  glUniform1i(LOCATION_RSM_RESOLUTION, maps.resolution);
  dispatchCovering({maps.resolution, maps.resolution, maps.views},
                   {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z}, GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace lpvlab

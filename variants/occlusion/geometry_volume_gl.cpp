#include "variants/occlusion/geometry_volume_gl.h"

#include "framework/gl/dispatch.h"
#include "variants/resources/geometry_volume.h"

namespace lpvlab {
namespace {
namespace surfel_kernel {
#include "shaders/occlusion/gv_surfel_interface.glsl"
}
namespace camera_kernel {
#include "shaders/occlusion/gv_camera_interface.glsl"
}
namespace rsm_kernel {
#include "shaders/common/light_records_interface.glsl"
#include "shaders/occlusion/gv_rsm_interface.glsl"
}
namespace merge_kernel {
#include "shaders/occlusion/gv_merge_interface.glsl"
}
}  // namespace

KernelWork gvSurfelGlWork(bool withAlbedo) {
  const double sums = withAlbedo ? 8.0 : 4.0;
  return {20 + sums, 3 * 16 + 2 * 4 * sums};
}

GeometryVolumeGlKernels::GeometryVolumeGlKernels(ShaderCompiler& shaders, bool fromCamera,
                                                 bool fromLight, bool withAlbedo, bool merges)
    : withAlbedo_(withAlbedo) {
  const std::vector<SpecConstant> constants = {SpecConstant::b(0, withAlbedo)};
  if (fromCamera) camera_ = shaders.compute("occlusion/gv_camera.comp", constants);
  if (fromLight) rsm_ = shaders.compute("occlusion/gv_rsm.comp", constants);
  if (merges) merge_ = shaders.compute("occlusion/gv_merge.comp");
  if (merges && withAlbedo) mergeAlbedo_ = shaders.compute("occlusion/gv_merge.comp", constants);
}

// What both injection kernels read first (gv_surfel_interface.glsl): the GV's placement, the
// blocking scale, the surfels' positions, normals and what gives their albedo, the GV they add
// to and, when it is used, the GV's albedo.
void GeometryVolumeGlKernels::use(const Program& program, const GvGlSurfels& surfels,
                                  const GvGlTarget& target) const {
  using namespace surfel_kernel;
  program.use();
  glUniform3fv(LOCATION_GV_ORIGIN, 1, &target.gv.origin[0]);
  glUniform1f(LOCATION_CELL_SIZE, target.gv.cellSize);
  glUniform3iv(LOCATION_GV_RESOLUTION, 1, &target.gv.resolution[0]);
  glUniform1f(LOCATION_BLOCKING_SCALE, target.blockingScale);
  glBindTextureUnit(UNIT_SURFEL_POSITION, surfels.position);
  glBindTextureUnit(UNIT_SURFEL_NORMAL, surfels.normal);
  target.blocking->bindStorage(BUFFER_TARGET);
  if (withAlbedo_) {
    glBindTextureUnit(UNIT_SURFEL_ALBEDO, surfels.albedoSource);
    target.albedo->bindStorage(BUFFER_ALBEDO);
  }
}

void GeometryVolumeGlKernels::injectCamera(const GvGlSurfels& gbuffer, int width, int height,
                                           const glm::vec3& cameraPosition, float texelEdge,
                                           const GvGlTarget& target) const {
  using namespace camera_kernel;
  use(camera_, gbuffer, target);
  glUniform3fv(LOCATION_CAMERA_POSITION, 1, &cameraPosition[0]);
  glUniform1f(LOCATION_TEXEL_EDGE, texelEdge);
  glUniform2i(LOCATION_SIZE, width, height);
  dispatchCovering({width, height, 1}, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                   GL_SHADER_STORAGE_BARRIER_BIT);
}

void GeometryVolumeGlKernels::injectLightViews(const GvGlSurfels& rsm, int rsmResolution, int views,
                                               const gl::Buffer& lightRecords,
                                               const gl::Buffer& viewRecords,
                                               const GvGlTarget& target) const {
  using namespace rsm_kernel;
  use(rsm_, rsm, target);
  lightRecords.bindStorage(BUFFER_LIGHTS);
  viewRecords.bindStorage(BUFFER_VIEWS);
  glUniform1i(LOCATION_RSM_RESOLUTION, rsmResolution);
  dispatchCovering({rsmResolution, rsmResolution, views}, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                   GL_SHADER_STORAGE_BARRIER_BIT);
}

void GeometryVolumeGlKernels::merge(const gl::Buffer& target, const gl::Buffer& other,
                                    const gl::Buffer* targetAlbedo,
                                    const gl::Buffer* otherAlbedo) const {
  using namespace merge_kernel;
  const bool albedo = targetAlbedo && otherAlbedo;
  (albedo ? mergeAlbedo_ : merge_).use();
  target.bindStorage(BUFFER_TARGET);
  other.bindStorage(BUFFER_OTHER);
  if (albedo) {
    targetAlbedo->bindStorage(BUFFER_TARGET_ALBEDO);
    otherAlbedo->bindStorage(BUFFER_OTHER_ALBEDO);
  }
  const int cells = int(target.size() / (GeometryVolume::kCoefficients * sizeof(float)));
  glUniform1i(LOCATION_CELLS, cells);
  dispatchCovering({cells, 1, 1}, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                   GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace lpvlab

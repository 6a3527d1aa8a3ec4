#pragma once
// The GL kernels of the geometry volume (occlusion "geometry_volume") and how they are
// dispatched: the camera's surfels (shaders/occlusion/gv_camera.comp: covered G-buffer pixels),
// the light views' surfels (gv_rsm.comp: RSM texels) and the merge of two GVs by the larger c0
// (gv_merge.comp). The strategy (geometry_volume.cpp) and lpvlab-gpubench
// (geometry_volume_gpubench.cpp) both run them through this class. Also their work model.

#include <glad/gl.h>
#include <glm/glm.hpp>

#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/grid_geometry.h"
#include "framework/pipeline/kernel_work.h"

namespace lpvlab {

// Where surfels go: the GV's placement and blocking scale, its blocking buffer (4 coefficients
// per GV cell, coefficient-major, added to) and, with albedo, its (rho A, A) sums.
struct GvGlTarget {
  GridGeometry gv;
  float blockingScale = 1.0f;
  const gl::Buffer* blocking = nullptr;
  const gl::Buffer* albedo = nullptr;
};

// Surfels as textures (RGBA32F): positions (w = 1 where covered), normals and what gives their
// albedo (the G-buffer's albedo; the RSM's flux).
struct GvGlSurfels {
  GLuint position = 0, normal = 0, albedoSource = 0;
};

// Per surfel: its position, normal and albedo source read (3 x 16 B), its area and lobe (about
// 20), 4 coefficients and, with the albedo, 4 sums, each added atomically (read and write, 4 B).
KernelWork gvSurfelGlWork(bool withAlbedo);

class GeometryVolumeGlKernels {
public:
  GeometryVolumeGlKernels() = default;
  // The kernels the sources need; withAlbedo: they add the albedo sums too; merges: merge()
  // will be called (two sources, or a history).
  GeometryVolumeGlKernels(ShaderCompiler& shaders, bool fromCamera, bool fromLight,
                          bool withAlbedo, bool merges);

  // The camera's covered pixels (width x height), seen from `cameraPosition`; texelEdge: a
  // pixel's edge at unit depth.
  void injectCamera(const GvGlSurfels& gbuffer, int width, int height,
                    const glm::vec3& cameraPosition, float texelEdge,
                    const GvGlTarget& target) const;
  // Every light view's RSM texels (the views' and lights' GPU records, light_views.h).
  void injectLightViews(const GvGlSurfels& rsm, int rsmResolution, int views,
                        const gl::Buffer& lightRecords, const gl::Buffer& viewRecords,
                        const GvGlTarget& target) const;
  // `other` into `target` by the larger c0, with the albedo buffers when both are given.
  void merge(const gl::Buffer& target, const gl::Buffer& other, const gl::Buffer* targetAlbedo,
             const gl::Buffer* otherAlbedo) const;

private:
  void use(const Program& program, const GvGlSurfels& surfels, const GvGlTarget& target) const;

  bool withAlbedo_ = false;
  Program camera_, rsm_, merge_, mergeAlbedo_;
};

}  // namespace lpvlab

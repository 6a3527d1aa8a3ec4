#pragma once
// Geometry-volume injection on the CPU (the CPU backend, strategy.h): every covered G-buffer pixel
// or RSM texel becomes a surfel through the shared functions of
// shaders/occlusion/gv_surfel_sources.glsl and shaders/common/geometry_volume.glsl (compiled as
// C++ in double precision), the very text the GL kernels run. Without atomics: each surfel's GV
// cell is found (in parallel), the surfels are sorted by cell keeping their order, and each cell
// then sums its own (in parallel over cells), so the GV does not depend on the thread count.

#include <glm/glm.hpp>

#include "framework/math/grid_geometry.h"
#include "framework/pipeline/host_readback.h"
#include "framework/pipeline/light_views.h"

namespace lpvlab {

// Where surfels are added: the GV's placement, blocking_scale, and its buffers (layout of
// variants/resources/geometry_volume.h), added to.
struct GvTarget {
  GridGeometry gv;
  float blockingScale = 1.0f;
  float* blocking = nullptr;  // 4 coefficients x GV cells, coefficient-major
  float* albedo = nullptr;    // (rho A, A) per GV cell, or null: no albedo
};

struct GBufferImages {
  const HostImage* position = nullptr;  // RGBA: world position, w = 1 where covered
  const HostImage* normal = nullptr;    // RGBA: unit normal, w = view depth
  const HostImage* albedo = nullptr;    // RGBA: albedo (read only when the target has albedo)
};

// The camera's surfels: seen from `cameraPosition` through pixels of edge `texelEdge` at unit
// depth (2 tan(vertical fov / 2) / height).
void addCameraSurfelsCpu(const GBufferImages& gbuffer, const glm::vec3& cameraPosition,
                         float texelEdge, const GvTarget& target);

// The light views' surfels: layer v of the RSM is view v of `records`. Throws an Error for images
// of different sizes or a layer without its view.
void addRsmSurfelsCpu(const RsmImages& rsm, const LightViews& records, const GvTarget& target);

// Merging two sources' GVs by the larger coefficients (gvMergeTakesOther): into `first`. With
// albedo buffers (4 floats per cell), a cell taken from `other` takes its albedo sums too (the GV
// of the frames before, merged into a frame's; gv_merge.comp's WITH_ALBEDO).
void mergeGeometryVolumesCpu(float* first, const float* other, int cells,
                             float* firstAlbedo = nullptr, const float* otherAlbedo = nullptr);

}  // namespace lpvlab

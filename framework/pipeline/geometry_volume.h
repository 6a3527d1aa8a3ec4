#pragma once
// The geometry volume (GV, thesis 4.1 and 4.3): a coarse picture of the scene's surfaces as
// blocking potential B(w), the fraction of the light travelling in direction w that a cell's
// surfaces stop (eq. 4.4). Its cells are the light grid's shifted by half a cell, so that GV cell
// centres sit on light-grid cell corners: one more cell along each axis than the light grid,
// origin half a cell lower. A propagation step reads B where its direction crosses the face
// shared by two light-grid cells, interpolating between the four GV cells around that face.
//
// Layout, as the light grid's (shaders/common/grid.glsl), one scalar channel:
//   blocking: order-1 SH of B(w), 4 floats per GV cell, index coefficient * cellCount + cell
//   albedo:   only if requested: per GV cell, RGB albedo times weight and the weight (4 floats
//             interleaved), so a weighted mean albedo is albedo.rgb / albedo.w
// The kernels' side is shaders/common/geometry_volume.glsl.

#include <cstddef>

#include "framework/gl/resources.h"
#include "framework/math/grid_geometry.h"

namespace lpvlab {

struct GeometryVolume {
  static constexpr int kCoefficients = 4;

  GridGeometry geometry;
  gl::Buffer blocking;
  gl::Buffer albedo;  // empty unless Requirements::surfaceAlbedo
  // Propagation iterations before this one ignore the GV (set by the occlusion strategy): 1
  // lets light leave the injected cells unblocked (a VPL's own surface would block it).
  int firstOccludedIteration = 0;

  GeometryVolume() = default;
  GeometryVolume(const GridGeometry& lightGrid, bool withAlbedo);

  // The GV placement for a light grid: half a cell lower, one more cell per axis.
  static GridGeometry placementFor(const GridGeometry& lightGrid);

  void clear();
  std::size_t memoryBytes() const { return blocking.size() + albedo.size(); }
};

// The flux-weighted mean normal of the VPLs injected into each light-grid cell, for directed
// propagation (thesis 5.2): vec4 per cell, xyz = sum of Phi n, w = sum of Phi.
struct NormalGrid {
  gl::Buffer normals;

  NormalGrid() = default;
  explicit NormalGrid(const GridGeometry& lightGrid);
  void clear() { normals.zero(); }
  std::size_t memoryBytes() const { return normals.size(); }
};

}  // namespace lpvlab

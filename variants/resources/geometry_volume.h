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
//   albedo:   (SurfaceAlbedo) per GV cell, RGB albedo times weight and the weight (4 floats
//             interleaved), so a weighted mean albedo is albedo.rgb / albedo.w
// The kernels' side is shaders/common/geometry_volume.glsl. All three are resources
// (named_resources.h): the occlusion strategy produces the GV and the albedo, the RSM injection the
// normal grid, and a propagation consumes or reads them.

#include <cstddef>

#include "framework/gl/resources.h"
#include "framework/math/grid_geometry.h"
#include "framework/pipeline/named_resources.h"

namespace lpvlab {

struct GeometryVolume {
  static constexpr int kCoefficients = 4;

  GridGeometry geometry;
  gl::Buffer blocking;
  // Propagation iterations before this one ignore the GV, fixed by its producer for the run: 1
  // lets light leave the injected cells unblocked (a VPL's own surface would block it).
  int firstOccludedIteration = 0;

  GeometryVolume() = default;
  GeometryVolume(const GridGeometry& lightGrid, int firstOccludedIteration);
  GeometryVolume(const ResourceSetup& setup, int firstOccludedIteration)
      : GeometryVolume(setup.grid, firstOccludedIteration) {}

  // The GV placement for a light grid: half a cell lower, one more cell per axis.
  static GridGeometry placementFor(const GridGeometry& lightGrid);

  void place(const GridGeometry& lightGrid) { geometry = placementFor(lightGrid); }
  void clear() { blocking.zero(); }
  std::size_t memoryBytes() const { return blocking.size(); }
};

// The albedo of the GV's surfaces (multiple bounces re-emit the light the GV blocks with it),
// on the GV's cells.
struct SurfaceAlbedo {
  gl::Buffer albedo;

  SurfaceAlbedo() = default;
  explicit SurfaceAlbedo(const GridGeometry& lightGrid);
  explicit SurfaceAlbedo(const ResourceSetup& setup) : SurfaceAlbedo(setup.grid) {}
  void clear() { albedo.zero(); }
  std::size_t memoryBytes() const { return albedo.size(); }
};

// The flux-weighted mean normal of the VPLs injected into each light-grid cell, for directed
// propagation (thesis 5.2): vec4 per cell, xyz = sum of Phi n, w = sum of Phi.
struct NormalGrid {
  gl::Buffer normals;

  NormalGrid() = default;
  explicit NormalGrid(const GridGeometry& lightGrid);
  explicit NormalGrid(const ResourceSetup& setup) : NormalGrid(setup.grid) {}
  void clear() { normals.zero(); }
  std::size_t memoryBytes() const { return normals.size(); }
};

inline constexpr ResourceKey<GeometryVolume> kGeometryVolume{
    "geometry_volume", "the blocking potential of the scene's surfaces per GV cell"};
inline constexpr ResourceKey<SurfaceAlbedo> kSurfaceAlbedo{
    "surface_albedo", "the albedo of the geometry volume's surfaces per GV cell"};
inline constexpr ResourceKey<NormalGrid> kNormalGrid{
    "normal_grid", "the injected VPLs' flux-weighted normal per light-grid cell"};

}  // namespace lpvlab

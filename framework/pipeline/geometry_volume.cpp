#include "framework/pipeline/geometry_volume.h"

namespace lpvlab {

GridGeometry GeometryVolume::placementFor(const GridGeometry& lightGrid) {
  GridGeometry gv = lightGrid;
  gv.origin -= glm::vec3(0.5f * lightGrid.cellSize);
  gv.resolution += glm::ivec3(1);
  return gv;
}

GeometryVolume::GeometryVolume(const GridGeometry& lightGrid, bool withAlbedo)
    : geometry(placementFor(lightGrid)) {
  const std::size_t cells = std::size_t(geometry.cellCount());
  blocking = gl::Buffer(cells * kCoefficients * sizeof(float), "geometry volume (blocking)");
  if (withAlbedo) albedo = gl::Buffer(cells * 4 * sizeof(float), "geometry volume (albedo)");
}

void GeometryVolume::clear() {
  blocking.zero();
  if (albedo.size() > 0) albedo.zero();
}

NormalGrid::NormalGrid(const GridGeometry& lightGrid)
    : normals(std::size_t(lightGrid.cellCount()) * 4 * sizeof(float), "normal grid") {}

}  // namespace lpvlab

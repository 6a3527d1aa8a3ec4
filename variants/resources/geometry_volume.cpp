#include "variants/resources/geometry_volume.h"

namespace lpvlab {

GridGeometry GeometryVolume::placementFor(const GridGeometry& lightGrid) {
  GridGeometry gv = lightGrid;
  gv.origin -= glm::vec3(0.5f * lightGrid.cellSize);
  gv.resolution += glm::ivec3(1);
  return gv;
}

GeometryVolume::GeometryVolume(const GridGeometry& lightGrid, int firstOccludedIteration)
    : geometry(placementFor(lightGrid)),
      blocking(std::size_t(geometry.cellCount()) * kCoefficients * sizeof(float),
               "geometry volume (blocking)"),
      firstOccludedIteration(firstOccludedIteration) {}

SurfaceAlbedo::SurfaceAlbedo(const GridGeometry& lightGrid)
    : albedo(std::size_t(GeometryVolume::placementFor(lightGrid).cellCount()) * 4 * sizeof(float),
             "geometry volume (albedo)") {}

NormalGrid::NormalGrid(const GridGeometry& lightGrid)
    : normals(std::size_t(lightGrid.cellCount()) * 4 * sizeof(float), "normal grid") {}

}  // namespace lpvlab

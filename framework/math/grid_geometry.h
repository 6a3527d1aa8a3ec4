#pragma once
// Where a grid sits in the world (see shaders/common/grid.glsl for the coordinate conventions).

#include <glm/glm.hpp>

namespace lpvlab {

struct Bounds;

struct GridGeometry {
  glm::vec3 origin{0.0f};   // world position of the corner of cell (0,0,0), metres
  float cellSize = 1.0f;    // edge of a cubic cell, metres
  glm::ivec3 resolution{1}; // cells along x, y, z

  int cellCount() const { return resolution.x * resolution.y * resolution.z; }
  bool operator==(const GridGeometry&) const = default;
  glm::vec3 extent() const { return glm::vec3(resolution) * cellSize; }

  // Cubic cells fitted to `bounds`: `cellsAlongLongestAxis` cells span the longest axis of the
  // bounds widened by `marginCells` cells on every side; the other axes get just enough cells to
  // cover theirs (so a long, flat scene isn't given a cube of empty cells), centred on the
  // bounds. Degenerate (flat or point) bounds still give a valid grid.
  static GridGeometry fitted(const Bounds& bounds, int cellsAlongLongestAxis, float marginCells);
};

}  // namespace lpvlab

#pragma once
// Where the levels of a cascade of light grids sit (thesis 5.1; Kaplanyan and Dachsbacher 2010).
//
// The coarsest level is the experiment's grid (fitted to the scene, so it always holds all of it).
// Each finer level has the same cell counts and half its parent's cell size, and follows the
// camera: its centre is the eye moved `viewShift` times the level's longest extent along the view
// direction (so the level covers what the camera looks at, not what is behind it), clamped so the
// level stays inside its parent, and snapped to whole cells of the parent. Snapping to the
// parent's cells (a) keeps each level's cells at fixed world positions while the camera moves, so
// a move of less than a cell changes nothing (no flicker), and (b) nests the levels exactly: every
// cell of a parent inside its child is the union of 2x2x2 child cells, which carrying light from
// fine to coarse levels (shaders/cascade/restrict.comp) relies on.

#include <vector>

#include <glm/glm.hpp>

#include "framework/math/grid_geometry.h"

namespace lpvlab {

// Levels finest first; the last one is `coarsest` itself. levels >= 1.
std::vector<GridGeometry> placeCascadeLevels(const GridGeometry& coarsest, int levels,
                                             const glm::vec3& eye, const glm::vec3& viewDirection,
                                             float viewShift);

// Where `child` (a level placed by placeCascadeLevels) starts inside `parent`, in parent cells
// (exact: child origins are snapped to whole parent cells).
glm::ivec3 childOffsetInParentCells(const GridGeometry& child, const GridGeometry& parent);

}  // namespace lpvlab

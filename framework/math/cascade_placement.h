#pragma once
// Where the levels of a cascade of light grids sit (thesis 5.1; Kaplanyan and Dachsbacher 2010).
//
// The coarsest level is the experiment's grid (fitted to the scene, so it always holds all of it).
// Each finer level has the same cell counts and half its parent's cell size, and follows the
// camera. Its wanted centre is, by [cascades] placement:
//   "eye":   the eye moved `viewShift` times the level's longest extent along the view direction
//            (so the level covers what the camera looks at, not what is behind it);
//   "depth": the focus, what the camera sees (visibleFocus: the per-axis median of the G-buffer's
//            world positions), the same point for every finer level.
// The level is then clamped to stay inside its parent and snapped to whole cells of the parent
// (unless `snap` is off: [cascades] snap = false, an ablation of the snapping's effect on
// flicker, which leaves the levels unnested and so cannot carry light to their parents).
// Snapping to the parent's cells (a) keeps each level's cells at fixed world positions: the
// placement is a piecewise-constant function of the wanted centre, which changes only where the
// centre crosses a plane half-way between two parent-cell offsets, and then by whole parent cells
// (no flicker: a move of the eye, or of the focus, that crosses no such plane changes nothing), and
// (b) nests the levels exactly: every cell of a parent inside its child is the union of 2x2x2
// child cells, which carrying light from fine to coarse levels (shaders/cascade/restrict.comp)
// relies on. A focus inside the coarsest grid is inside every level when the cell counts are even
// (the snapped centre is at most half a parent cell, one child cell, from the focus, and a level
// clamped at its parent's side spans half the parent from that side).

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "framework/math/grid_geometry.h"

namespace lpvlab {

// Levels finest first; the last one is `coarsest` itself. levels >= 1.
std::vector<GridGeometry> placeCascadeLevels(const GridGeometry& coarsest, int levels,
                                             const glm::vec3& eye, const glm::vec3& viewDirection,
                                             float viewShift, bool snap = true);

// Levels finest first, every finer one centred as near `focus` as its parent allows ("depth").
std::vector<GridGeometry> placeCascadeLevels(const GridGeometry& coarsest, int levels,
                                             const glm::vec3& focus, bool snap = true);

// The point "depth" placement centres the finer levels on: per axis, the median of the world
// positions of the surfaces the camera sees (one per G-buffer pixel, so weighted by screen area:
// what fills the image pulls hardest). A median, not a mean, so a few far pixels (a distant wall
// through a door) do not drag the fine levels into the air between. Empty: nothing seen.
std::optional<glm::vec3> visibleFocus(std::vector<glm::vec3> positions);

// Where `child` (a level placed by placeCascadeLevels with snapping) starts inside `parent`, in
// parent cells (exact: snapped child origins are on whole parent cells).
glm::ivec3 childOffsetInParentCells(const GridGeometry& child, const GridGeometry& parent);

}  // namespace lpvlab

#include "framework/math/cascade_placement.h"

#include <algorithm>
#include <cmath>

namespace lpvlab {

namespace {

// A level with half the parent's cell size, centred as near `centre` as the parent allows,
// starting on a whole parent cell when `snap` is set.
GridGeometry placeChild(const GridGeometry& parent, const glm::vec3& centre, bool snap) {
  GridGeometry child;
  child.resolution = parent.resolution;
  child.cellSize = parent.cellSize * 0.5f;
  const glm::vec3 wanted = (centre - 0.5f * child.extent() - parent.origin) / parent.cellSize;
  // The child spans resolution/2 parent cells; it fits at offsets 0 .. parent.res - res/2.
  const glm::ivec3 last = parent.resolution - (child.resolution + 1) / 2;
  glm::vec3 offset;
  for (int axis = 0; axis < 3; ++axis)
    offset[axis] = std::clamp(snap ? std::round(wanted[axis]) : wanted[axis], 0.0f,
                              float(std::max(last[axis], 0)));
  child.origin = parent.origin + offset * parent.cellSize;
  return child;
}

}  // namespace

std::vector<GridGeometry> placeCascadeLevels(const GridGeometry& coarsest, int levels,
                                             const glm::vec3& eye, const glm::vec3& viewDirection,
                                             float viewShift, bool snap) {
  std::vector<GridGeometry> placed(std::size_t(std::max(levels, 1)));
  placed.back() = coarsest;
  const float length = glm::length(viewDirection);
  const glm::vec3 forward = length > 0.0f ? viewDirection / length : glm::vec3(0.0f);
  for (int level = int(placed.size()) - 2; level >= 0; --level) {
    const GridGeometry& parent = placed[std::size_t(level) + 1];
    const float longest = 0.5f * parent.cellSize * float(glm::max(
        parent.resolution.x, glm::max(parent.resolution.y, parent.resolution.z)));
    placed[std::size_t(level)] = placeChild(parent, eye + forward * (viewShift * longest), snap);
  }
  return placed;
}

std::vector<GridGeometry> placeCascadeLevels(const GridGeometry& coarsest, int levels,
                                             const glm::vec3& focus, bool snap) {
  return placeCascadeLevels(coarsest, levels, focus, glm::vec3(0.0f), 0.0f, snap);
}

std::optional<glm::vec3> visibleFocus(std::vector<glm::vec3> positions) {
  if (positions.empty()) return std::nullopt;
  const auto middle = positions.begin() + std::ptrdiff_t(positions.size() / 2);
  glm::vec3 focus;
  for (int axis = 0; axis < 3; ++axis) {
    std::nth_element(positions.begin(), middle, positions.end(),
                     [axis](const glm::vec3& a, const glm::vec3& b) { return a[axis] < b[axis]; });
    focus[axis] = (*middle)[axis];
  }
  return focus;
}

glm::ivec3 childOffsetInParentCells(const GridGeometry& child, const GridGeometry& parent) {
  return glm::ivec3(glm::round((child.origin - parent.origin) / parent.cellSize));
}

}  // namespace lpvlab

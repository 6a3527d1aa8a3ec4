#include "framework/raster/view_rays.h"

#include <cmath>

#include <glm/gtc/matrix_access.hpp>

#include "framework/core/error.h"

namespace lpvlab {

ViewRays::ViewRays(const glm::mat4& clipFromWorld, int width, int height)
    : width_(width), height_(height) {
  if (width <= 0 || height <= 0) throw Error("ray-cast raster: a view of no texels");
  const glm::dmat4 clip(clipFromWorld);
  const double determinant = glm::determinant(clip);
  if (!std::isfinite(determinant) || determinant == 0.0)
    throw Error("ray-cast raster: a view whose projection is singular or not finite");
  const glm::dmat4 world = glm::inverse(clip);
  // ndc = p * (2 / size) - 1 along each axis, at depth -1 (near) or +1 (far).
  const glm::dvec4 perX = world[0] * (2.0 / width), perY = world[1] * (2.0 / height);
  const glm::dvec4 centre = world[3] - world[0] - world[1];
  near_[0] = glm::vec4(centre - world[2]);
  far_[0] = glm::vec4(centre + world[2]);
  near_[1] = far_[1] = glm::vec4(perX);
  near_[2] = far_[2] = glm::vec4(perY);
  depthRow_ = glm::row(clipFromWorld, 2);
  wRow_ = glm::row(clipFromWorld, 3);
}

}  // namespace lpvlab

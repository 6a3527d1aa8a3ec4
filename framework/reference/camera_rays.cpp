#include "framework/reference/camera_rays.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "framework/core/error.h"
#include "framework/math/view_matrix.h"

namespace lpvlab {

namespace {

void requireFiniteVec(const glm::vec3& v, const std::string& where, const char* what) {
  for (int i = 0; i < 3; ++i) requireFinite(v[i], where, what);
}

}  // namespace

CameraRays::CameraRays(const Camera& camera, int width, int height) {
  const std::string where = "path tracer camera '" + camera.name + "'";
  requireFiniteVec(camera.position, where, "position");
  requireFiniteVec(camera.forward, where, "forward");
  requireFiniteVec(camera.up, where, "up");
  requireFinite(camera.verticalFov, where, "vertical field of view");
  requireFinite(camera.nearPlane, where, "near plane");
  requireFinite(camera.farPlane, where, "far plane");
  if (!(camera.verticalFov > 0.0f && camera.verticalFov < float(M_PI)))
    throwAt(where, "vertical field of view must be in (0, pi) radians");
  if (!(camera.nearPlane > 0.0f && camera.farPlane > camera.nearPlane))
    throwAt(where, "needs 0 < near plane < far plane");

  const glm::mat4 view = viewFromWorld(camera.position, camera.forward, camera.up);
  const glm::mat4 clipFromView = glm::perspective(camera.verticalFov, float(width) / float(height),
                                                  camera.nearPlane, camera.farPlane);
  // lookAt's rows are the view axes in world space (right, up, backwards); perspective's
  // diagonal holds 1 / (aspect tan(fov/2)) and 1 / tan(fov/2), the inverse image-plane extents.
  const glm::vec3 right(view[0][0], view[1][0], view[2][0]);
  const glm::vec3 up(view[0][1], view[1][1], view[2][1]);
  const glm::vec3 backwards(view[0][2], view[1][2], view[2][2]);
  for (const glm::vec3& axis : {right, up, backwards})
    if (!std::isfinite(axis.x + axis.y + axis.z) || glm::length(axis) < 0.5f)
      throwAt(where, "forward and up must be non-zero and not parallel");

  origin_ = camera.position;
  forward_ = -backwards;
  right_ = right / clipFromView[0][0];
  up_ = up / clipFromView[1][1];
  cameraForward_ = camera.forward;
  inverseWidth_ = 1.0f / float(width);
  inverseHeight_ = 1.0f / float(height);
  nearPlane_ = camera.nearPlane;
  farPlane_ = camera.farPlane;
}

}  // namespace lpvlab

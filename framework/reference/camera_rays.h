#pragma once
// Camera rays exactly as the LPV pipeline's G-buffer sees the scene: the view of
// glm::lookAt(position, position + forward, up) and the projection of
// glm::perspective(verticalFov, width / height), with image row 0 at the top. The ray through
// image position (px, py) in pixels ((0, 0) the top-left corner of the top-left pixel) is the
// line of points that project there; rays start and stop at the camera's near and far planes
// (view depth, as the rasteriser clips), so both renderers see the same surfaces.

#include <glm/glm.hpp>

#include "framework/scene/scene.h"

namespace lpvlab {

class CameraRays {
public:
  // Throws an Error when the camera is not finite or cannot form a view (e.g. up parallel to
  // forward, a field of view outside (0, pi), far plane not beyond the near plane).
  CameraRays(const Camera& camera, int width, int height);

  glm::vec3 origin() const { return origin_; }
  // Unit direction through image position (px, py).
  glm::vec3 direction(float px, float py) const {
    const float ndcX = 2.0f * px * inverseWidth_ - 1.0f;
    const float ndcY = 1.0f - 2.0f * py * inverseHeight_;  // row 0 is the top (ndc y = +1)
    return glm::normalize(forward_ + ndcX * right_ + ndcY * up_);
  }
  // Ray parameters of the near and far planes along a unit direction: the planes are at constant
  // view depth, so they are further along oblique rays.
  float nearDistance(const glm::vec3& direction) const {
    return nearPlane_ / depthPerDistance(direction);
  }
  float farDistance(const glm::vec3& direction) const {
    return farPlane_ / depthPerDistance(direction);
  }
  // View depth (m) of a point: what the G-buffer's depth holds.
  float viewDepth(const glm::vec3& point) const {
    return glm::dot(point - origin_, cameraForward_);
  }

private:
  float depthPerDistance(const glm::vec3& direction) const { return glm::dot(direction, forward_); }

  glm::vec3 origin_;
  glm::vec3 forward_;        // unit, the view's -z axis
  glm::vec3 right_, up_;     // view axes scaled to the image plane's half extent at unit depth
  glm::vec3 cameraForward_;  // Camera::forward as given (the G-buffer's depth axis)
  float inverseWidth_, inverseHeight_;
  float nearPlane_, farPlane_;
};

}  // namespace lpvlab

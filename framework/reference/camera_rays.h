#pragma once
// Camera rays exactly as the LPV pipeline's G-buffer sees the scene: the view of
// viewFromWorld(position, forward, up) (glm::lookAt's, framework/math/view_matrix.h) and the projection of
// glm::perspective(verticalFov, width / height), with image row 0 at the top. The ray through
// image position (px, py) in pixels ((0, 0) the top-left corner of the top-left pixel) is the
// line of points that project there; rays start and stop at the camera's near and far planes
// (view depth, as the rasteriser clips), so both renderers see the same surfaces.

#include <glm/glm.hpp>
#include <optional>

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
  // The point at view depth `depth` on the ray through image position (px, py): a surface point
  // from a depth AOV, the inverse of viewDepth along that ray.
  glm::vec3 surfacePoint(float px, float py, float depth) const {
    const glm::vec3 d = direction(px, py);
    return origin_ + d * (depth / glm::dot(d, cameraForward_));
  }
  // The image position (px, py) a point projects to, the inverse of direction(); nothing for a
  // point at or behind the camera's plane (it projects nowhere).
  std::optional<glm::vec2> imagePosition(const glm::vec3& point) const {
    const glm::vec3 v = point - origin_;
    const float depth = glm::dot(v, forward_);
    if (!(depth > 0.0f)) return std::nullopt;
    const float ndcX = glm::dot(v, right_) / (glm::dot(right_, right_) * depth);
    const float ndcY = glm::dot(v, up_) / (glm::dot(up_, up_) * depth);
    return glm::vec2((ndcX + 1.0f) / (2.0f * inverseWidth_),
                     (1.0f - ndcY) / (2.0f * inverseHeight_));
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

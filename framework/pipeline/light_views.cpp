#include "framework/pipeline/light_views.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <numeric>

#include "framework/core/error.h"
#include "framework/math/view_matrix.h"

namespace lpvlab {

namespace {
// GpuLight::positionType.w: lights_gpu.glsl's LIGHT_POINT, LIGHT_SPOT, LIGHT_DIRECTIONAL.
constexpr int kLightPoint = 0, kLightSpot = 1, kLightDirectional = 2;
}  // namespace

glm::vec4 lightViewViewer(const LightViews& views, int view) {
  const GpuLight& light = views.lights.at(std::size_t(views.views.at(std::size_t(view)).params.z));
  if (int(light.positionType.w) == kLightDirectional)
    return glm::vec4(-glm::vec3(light.directionCosOuter), 0.0f);
  return glm::vec4(glm::vec3(light.positionType), 1.0f);
}

namespace {

// Cube faces in the order +x, -x, +y, -y, +z, -z, with up vectors as in GL cube maps.
const glm::vec3 kFaceAxis[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const glm::vec3 kFaceUp[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};

// Angle between a cube face's axis and the corners of its frustum: acos(1 / sqrt(3)).
const float kFaceHalfDiagonal = std::acos(1.0f / std::sqrt(3.0f));

void checkLight(const Light& light) {
  const std::string where = "light '" + light.name + "'";
  auto finite = [&](const glm::vec3& v, const char* what) {
    for (int i = 0; i < 3; ++i) requireFinite(v[i], where, what);
  };
  finite(light.position, "position");
  finite(light.direction, "direction");
  finite(light.color, "colour");
  requireFinite(light.intensity, where, "intensity");
  if (light.intensity < 0.0f || glm::any(glm::lessThan(light.color, glm::vec3(0.0f))))
    throwAt(where, "negative colour or intensity");
  if (light.type != LightType::Point && glm::length(light.direction) < 1e-6f)
    throwAt(where, "direction has zero length");
  if (light.type == LightType::Spot &&
      !(light.outerConeAngle > 0.0f && light.outerConeAngle <= 0.5f * float(M_PI) &&
        light.innerConeAngle >= 0.0f && light.innerConeAngle <= light.outerConeAngle))
    throwAt(where, "cone angles must satisfy 0 <= inner <= outer <= pi/2 and outer > 0");
}

// The up vector of a light's orthographic view (glm::lookAt's), for any direction but straight up
// or down, where it takes x.
glm::vec3 lightViewUp(const glm::vec3& direction) {
  return std::abs(direction.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
}

// The orthographic view of a light shining along `direction` (unit): a box `halfWidth` each side
// of `centre` across the light, and 1.5 `sceneRadius` each side of it along the light (the scene's
// bounding sphere, when `centre` is level with the sphere's centre along the light, well inside).
GpuView orthographicView(const glm::vec3& direction, const glm::vec3& centre, float halfWidth,
                         float sceneRadius, int lightIndex) {
  const glm::mat4 view = viewFromWorld(centre - direction * 2.0f * sceneRadius, direction, lightViewUp(direction));
  const glm::mat4 clipFromView = glm::ortho(-halfWidth, halfWidth, -halfWidth, halfWidth,
                                            0.5f * sceneRadius, 3.5f * sceneRadius);
  return {clipFromView * view, glm::vec4(1.0f, 2.0f * halfWidth, float(lightIndex), 0)};
}

// The followed box's centre: the camera's point, snapped to whole steps along the view's image
// axes (those of glm::lookAt in orthographicView) and put level with the scene's centre along the
// light, so that the box's depth range holds the scene's bounding sphere.
glm::vec3 followedCentre(const glm::vec3& direction, const DirectionalFollow& follow,
                         const glm::vec3& sceneCentre) {
  const glm::vec3 right = glm::normalize(glm::cross(direction, lightViewUp(direction)));
  const glm::vec3 imageUp = glm::cross(right, direction);
  // Coordinates in double: a camera kilometres from the origin still snaps to millimetre steps.
  auto snapped = [&](const glm::vec3& axis) {
    const double along = glm::dot(glm::dvec3(follow.centre), glm::dvec3(axis));
    return follow.texel > 0.0f ? std::round(along / follow.texel) * follow.texel : along;
  };
  return glm::vec3(glm::dvec3(right) * snapped(right) + glm::dvec3(imageUp) * snapped(imageUp) +
                   glm::dvec3(direction) * double(glm::dot(sceneCentre, direction)));
}

}  // namespace

float directionalSnapStep(float halfWidth, int rsmResolution, int shadowResolution) {
  return 2.0f * halfWidth / float(std::gcd(rsmResolution, shadowResolution));
}

LightViews buildLightViews(const std::vector<Light>& lights, const Bounds& bounds,
                           const std::optional<DirectionalFollow>& follow) {
  if (bounds.empty()) throw Error("light views: the scene has no geometry");
  const float diagonal = std::max(glm::length(bounds.extent()), 1e-3f);
  LightViews out;
  for (const Light& light : lights) {
    checkLight(light);
    const int lightIndex = int(out.lights.size());
    GpuLight record{};
    const glm::vec3 direction =
        light.type == LightType::Point ? glm::vec3(0, -1, 0) : glm::normalize(light.direction);
    const int type = light.type == LightType::Point ? kLightPoint
                     : light.type == LightType::Spot ? kLightSpot : kLightDirectional;
    record.positionType = glm::vec4(light.position, float(type));
    const bool spot = light.type == LightType::Spot;
    record.directionCosOuter =
        glm::vec4(direction, spot ? std::cos(light.outerConeAngle) : -1.0f);
    record.intensityCosInner =
        glm::vec4(light.color * light.intensity, spot ? std::cos(light.innerConeAngle) : -1.0f);
    record.viewOfFace0123 = glm::ivec4(-1);
    record.viewOfFace45 = glm::ivec4(-1);

    if (light.type == LightType::Directional) {
      // Looking along the light, over the scene's bounding sphere or the followed box.
      const float radius = 0.5f * diagonal;
      record.viewOfFace0123.x = int(out.views.size());
      if (follow)
        out.views.push_back(orthographicView(direction,
                                             followedCentre(direction, *follow, bounds.center()),
                                             follow->halfWidth, radius, lightIndex));
      else
        out.views.push_back(
            orthographicView(direction, bounds.center(), radius, radius, lightIndex));
    } else {
      // The near plane scales with the scene; far reaches the farthest corner of the bounds.
      float farthest = 0.0f;
      for (int corner = 0; corner < 8; ++corner)
        farthest = std::max(farthest, glm::length(bounds.corner(corner) - light.position));
      const float nearPlane = std::max(1e-4f, 1e-4f * diagonal);
      const float farPlane = std::max(farthest * 1.01f, 2.0f * nearPlane);
      const glm::mat4 clipFromView = glm::perspective(0.5f * float(M_PI), 1.0f, nearPlane, farPlane);
      for (int face = 0; face < 6; ++face) {
        if (spot) {
          const float angle = std::acos(std::clamp(glm::dot(kFaceAxis[face], direction), -1.0f, 1.0f));
          if (angle > light.outerConeAngle + kFaceHalfDiagonal) continue;  // can't meet the cone
        }
        const glm::mat4 faceView = viewFromWorld(light.position, kFaceAxis[face], kFaceUp[face]);
        const int view = int(out.views.size());
        if (face < 4) record.viewOfFace0123[face] = view;
        else record.viewOfFace45[face - 4] = view;
        out.views.push_back({clipFromView * faceView, glm::vec4(0.0f, 1.0f, lightIndex, 0)});
      }
    }
    out.lights.push_back(record);
  }
  return out;
}

}  // namespace lpvlab

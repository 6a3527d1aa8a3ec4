#include "framework/scene/scene.h"

namespace lpvlab {

std::size_t Scene::triangleCount() const {
  std::size_t count = 0;
  for (const Mesh& mesh : meshes) count += mesh.indices.size() / 3;
  return count;
}

Bounds Scene::bounds() const {
  Bounds b;
  for (const Mesh& mesh : meshes)
    for (const glm::vec3& p : mesh.positions) b.extend(p);
  return b;
}

CameraOrientation orientCamera(Camera& camera, const glm::vec3& target, const glm::vec3& up) {
  const glm::vec3 forward = target - camera.position;
  if (!(glm::length(forward) >= 1e-6f)) return CameraOrientation::TargetAtPosition;
  const glm::vec3 right = glm::cross(glm::normalize(forward), up);
  if (!(glm::length(right) >= 1e-6f)) return CameraOrientation::UpAlongView;
  camera.forward = glm::normalize(forward);
  camera.up = glm::normalize(glm::cross(glm::normalize(right), camera.forward));
  return CameraOrientation::Oriented;
}

const char* lightTypeName(LightType type) {
  switch (type) {
    case LightType::Point: return "point";
    case LightType::Spot: return "spot";
    case LightType::Directional: return "directional";
  }
  return "unknown";
}

}  // namespace lpvlab

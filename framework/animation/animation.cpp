#include "framework/animation/animation.h"

#include <cmath>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

std::string at(double seconds) { return "at " + std::to_string(seconds) + " s"; }

void applyCamera(const CameraMotion& motion, double seconds, Camera& camera) {
  camera.position = glm::vec3(motion.position.sample(seconds));
  switch (orientCamera(camera, glm::vec3(motion.lookAt.sample(seconds)), motion.up)) {
    case CameraOrientation::TargetAtPosition:
      throw Error("camera path " + at(seconds) + ": the camera is at the point it looks at");
    case CameraOrientation::UpAlongView:
      throw Error("camera path " + at(seconds) + ": the camera looks along its up vector");
    case CameraOrientation::Oriented:
      break;
  }
  if (!motion.verticalFov.empty()) camera.verticalFov = float(motion.verticalFov.sample(seconds));
}

void applyLight(const LightMotion& motion, double seconds, Light& light) {
  if (!motion.position.empty()) light.position = glm::vec3(motion.position.sample(seconds));
  if (!motion.direction.empty()) {
    const glm::dvec3 d = motion.direction.sample(seconds);
    if (!(glm::length(d) > 1e-9))
      throw Error("light '" + light.name + "' " + at(seconds) +
                  ": its direction interpolates to zero "
                  "(keys pointing opposite ways: add a key between them)");
    light.direction = glm::vec3(glm::normalize(d));
  }
  if (!motion.intensity.empty()) light.intensity = float(motion.intensity.sample(seconds));
  if (!motion.color.empty()) light.color = glm::vec3(motion.color.sample(seconds));
}

void applyMeshes(const MeshMotion& motion, double seconds, Scene& scene) {
  const glm::dvec3 translation =
      motion.translation.empty() ? glm::dvec3(0.0) : motion.translation.sample(seconds);
  const glm::dmat3 rotation =
      motion.rotation.empty() ? glm::dmat3(1.0) : glm::mat3_cast(motion.rotation.sample(seconds));
  const glm::dvec3 offset = motion.pivot + translation;
  for (std::size_t m = 0; m < motion.meshes.size(); ++m) {
    Mesh& mesh = scene.meshes[std::size_t(motion.meshes[m])];
    const std::vector<glm::vec3>& positions = motion.restPositions[m];
    const std::vector<glm::vec3>& normals = motion.restNormals[m];
    for (std::size_t i = 0; i < positions.size(); ++i)
      mesh.positions[i] = glm::vec3(offset + rotation * (glm::dvec3(positions[i]) - motion.pivot));
    for (std::size_t i = 0; i < normals.size(); ++i)
      mesh.normals[i] = glm::vec3(glm::normalize(rotation * glm::dvec3(normals[i])));
  }
}

}  // namespace

Camera cameraAt(const Animation& animation, double seconds, Camera camera) {
  if (animation.camera) applyCamera(*animation.camera, seconds, camera);
  return camera;
}

void applyAnimation(const Animation& animation, double seconds, Scene& scene, Camera& camera) {
  camera = cameraAt(animation, seconds, camera);
  for (const LightMotion& motion : animation.lights)
    applyLight(motion, seconds, scene.lights[std::size_t(motion.light)]);
  for (const MeshMotion& motion : animation.meshes) applyMeshes(motion, seconds, scene);
}

}  // namespace lpvlab

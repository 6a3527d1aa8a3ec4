#pragma once
// A test scene for the many-light methods whose light transport has a bounded geometry term.

#include <array>
#include <string>

#include <glm/glm.hpp>

#include "framework/scene/scene.h"
#include "reference/test_scenes.h"

namespace lpvlab::test {

// Two parallel plates 1 m apart (floor and ceiling, 2 m square, albedo 0.7 and 0.6) and a cube
// floating between them (0.3 m above the floor, 0.4 m below the ceiling), lit by a point light:
// no two surfaces touch, so G = cos cos / d^2 stays below 1 / 0.3^2 everywhere and an
// unclamped VPL estimate has finite variance (in a room's corners it has not). The walls are
// left open; the camera looks in from outside.
inline Scene platesScene() {
  Scene scene;
  scene.source = "test:plates";
  for (const glm::vec3 colour : {glm::vec3(0.7f), glm::vec3(0.6f, 0.6f, 0.5f), glm::vec3(0.8f, 0.3f, 0.2f)}) {
    Material material;
    material.name = "m" + std::to_string(scene.materials.size());
    material.baseColor = colour;
    scene.materials.push_back(material);
  }
  scene.meshes.push_back(testing::horizontalSquare("floor", 0, 1.0f, 0.0f));
  scene.meshes.push_back(testing::quad("ceiling", 1,
                                       {glm::vec3(-1, 1, -1), glm::vec3(1, 1, -1),
                                        glm::vec3(1, 1, 1), glm::vec3(-1, 1, 1)}));
  // The cube [-0.25, 0.25] x [0.3, 0.6] x [-0.25, 0.25], faces outwards.
  const float a = 0.25f, lo = 0.3f, hi = 0.6f;
  const auto face = [&](const char* name, std::array<glm::vec3, 4> corners) {
    scene.meshes.push_back(testing::quad(name, 2, corners));
  };
  face("top", {glm::vec3(-a, hi, a), glm::vec3(a, hi, a), glm::vec3(a, hi, -a), glm::vec3(-a, hi, -a)});
  face("bottom", {glm::vec3(-a, lo, -a), glm::vec3(a, lo, -a), glm::vec3(a, lo, a), glm::vec3(-a, lo, a)});
  face("front", {glm::vec3(-a, lo, a), glm::vec3(a, lo, a), glm::vec3(a, hi, a), glm::vec3(-a, hi, a)});
  face("back", {glm::vec3(a, lo, -a), glm::vec3(-a, lo, -a), glm::vec3(-a, hi, -a), glm::vec3(a, hi, -a)});
  face("right", {glm::vec3(a, lo, a), glm::vec3(a, lo, -a), glm::vec3(a, hi, -a), glm::vec3(a, hi, a)});
  face("left", {glm::vec3(-a, lo, -a), glm::vec3(-a, lo, a), glm::vec3(-a, hi, a), glm::vec3(-a, hi, -a)});
  Light light;
  light.name = "bulb";
  light.type = LightType::Point;
  light.position = glm::vec3(0.45f, 0.85f, 0.2f);
  light.intensity = 2.0f;
  scene.lights.push_back(light);
  return scene;
}

inline Camera platesCamera() {
  Camera camera;
  camera.name = "side";
  camera.position = glm::vec3(0.2f, 0.55f, 2.2f);
  orientCamera(camera, glm::vec3(0.0f, 0.35f, 0.0f), glm::vec3(0, 1, 0));
  camera.verticalFov = 0.75f;
  camera.nearPlane = 0.01f;
  camera.farPlane = 20.0f;
  return camera;
}

}  // namespace lpvlab::test

// The built-in Cornell box against Cornell's published data and the choices in cornell_box.cpp.

#include <cmath>

#include <gtest/gtest.h>

#include "framework/scene/scene_loader.h"

namespace lpvlab {
namespace {

const Mesh& meshNamed(const Scene& scene, const std::string& name) {
  for (const Mesh& mesh : scene.meshes)
    if (mesh.name == name) return mesh;
  ADD_FAILURE() << "no mesh " << name;
  return scene.meshes.front();
}

// The average of a mesh's vertices (a point inside a block).
glm::vec3 centroid(const Mesh& mesh) {
  glm::vec3 sum(0.0f);
  for (const glm::vec3& p : mesh.positions) sum += p;
  return sum / static_cast<float>(mesh.positions.size());
}

float degrees(float radians) { return radians * 180.0f / 3.14159265358979f; }

TEST(CornellBox, HasTwoTrianglesPerPublishedQuad) {
  const int roomQuads = 5;        // floor, ceiling, back, left and right walls
  const int blockQuads = 2 * 5;   // each block's top and four sides (no bottom)
  EXPECT_EQ(makeCornellBox().triangleCount(), static_cast<std::size_t>(2 * (roomQuads + blockQuads)));
}

TEST(CornellBox, BoundsArePublishedExtentsInMetres) {
  const Bounds bounds = makeCornellBox().bounds();
  const glm::vec3 min(0.0f), max(0.556f, 0.5488f, 0.5592f);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(bounds.min[i], min[i], 1e-6f);
    EXPECT_NEAR(bounds.max[i], max[i], 1e-6f);
  }
}

TEST(CornellBox, TrianglesAreCounterClockwiseSeenFromTheirUnitNormals) {
  for (const Mesh& mesh : makeCornellBox().meshes) {
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
      const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                      c = mesh.positions[mesh.indices[t + 2]];
      const glm::vec3 n = mesh.normals[mesh.indices[t]];
      EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
      EXPECT_GT(glm::dot(glm::cross(b - a, c - a), n), 0.0f) << mesh.name;
    }
  }
}

TEST(CornellBox, RoomSurfacesFaceTheInside) {
  const Scene scene = makeCornellBox();
  const glm::vec3 inside(0.278f, 0.274f, 0.28f);
  const std::pair<const char*, glm::vec3> surfaces[] = {
      {"floor", {0, 1, 0}},      {"ceiling", {0, -1, 0}},    {"back wall", {0, 0, -1}},
      {"right wall", {1, 0, 0}}, {"left wall", {-1, 0, 0}}};
  for (const auto& [name, facing] : surfaces) {
    const Mesh& mesh = meshNamed(scene, name);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      EXPECT_GT(glm::dot(mesh.normals[i], inside - mesh.positions[i]), 0.0f) << name;
      EXPECT_GT(glm::dot(mesh.normals[i], facing), 0.999f) << name;  // the real box is skewed
    }
  }
}

TEST(CornellBox, BlockFacesFaceOutwards) {
  const Scene scene = makeCornellBox();
  for (const char* name : {"short block", "tall block"}) {
    const Mesh& mesh = meshNamed(scene, name);
    const glm::vec3 centre = centroid(mesh);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      EXPECT_LT(glm::dot(mesh.normals[i], centre - mesh.positions[i]), 0.0f) << name;
  }
}

TEST(CornellBox, ReflectancesAreExactAndOnTheRightWalls) {
  const Scene scene = makeCornellBox();
  const auto colourOf = [&](const char* mesh) {
    return scene.materials[meshNamed(scene, mesh).material].baseColor;
  };
  const glm::vec3 white(0.725f, 0.71f, 0.68f);
  for (const char* name : {"floor", "ceiling", "back wall", "short block", "tall block"})
    EXPECT_EQ(colourOf(name), white) << name;
  EXPECT_EQ(colourOf("left wall"), glm::vec3(0.63f, 0.065f, 0.05f));
  EXPECT_EQ(colourOf("right wall"), glm::vec3(0.14f, 0.45f, 0.091f));
  for (const glm::vec3& p : meshNamed(scene, "left wall").positions) EXPECT_GT(p.x, 0.549f);
  for (const glm::vec3& p : meshNamed(scene, "right wall").positions) EXPECT_EQ(p.x, 0.0f);
  for (const Material& material : scene.materials) EXPECT_EQ(material.baseColorTexture, -1);
}

TEST(CornellBox, HasThePublishedCamera) {
  const Scene scene = makeCornellBox();
  ASSERT_EQ(scene.cameras.size(), 1u);
  const Camera& camera = scene.cameras[0];
  EXPECT_EQ(camera.name, "default");
  EXPECT_EQ(camera.position, glm::vec3(0.278f, 0.273f, -0.8f));
  EXPECT_EQ(camera.forward, glm::vec3(0, 0, 1));
  EXPECT_EQ(camera.up, glm::vec3(0, 1, 0));
  EXPECT_NEAR(degrees(camera.verticalFov), 2.0f * degrees(std::atan(12.5f / 35.0f)), 0.01f);
  EXPECT_NEAR(degrees(camera.verticalFov), 39.31f, 1e-4f);
  EXPECT_EQ(camera.nearPlane, 0.01f);
  EXPECT_EQ(camera.farPlane, 10.0f);
}

TEST(CornellBox, HasASpotWithTheMeasuredLightsOnAxisIntensity) {
  const Scene scene = makeCornellBox();
  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& light = scene.lights[0];
  EXPECT_EQ(light.name, "spot");
  EXPECT_EQ(light.type, LightType::Spot);
  EXPECT_EQ(light.position, glm::vec3(0.278f, 0.5478f, 0.2795f));
  EXPECT_EQ(light.direction, glm::vec3(0, -1, 0));
  EXPECT_NEAR(degrees(light.outerConeAngle), 60.0f, 1e-4f);
  EXPECT_NEAR(degrees(light.innerConeAngle), 55.0f, 1e-4f);
  // Radiance (17, 12, 4) W/(m^2 sr) times the 0.130 m x 0.105 m light's area.
  const glm::vec3 intensity = light.color * light.intensity;
  const glm::vec3 expected = glm::vec3(17, 12, 4) * 0.130f * 0.105f;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(intensity[i], expected[i], 1e-6f);
  EXPECT_EQ(std::max({light.color.r, light.color.g, light.color.b}), 1.0f);
}

TEST(CornellBox, SpotDoesNotReachTheCeiling) {
  const Scene scene = makeCornellBox();
  const Light& light = scene.lights[0];
  const Mesh& ceiling = meshNamed(scene, "ceiling");
  EXPECT_LT(light.outerConeAngle, 3.14159265f / 2.0f);
  EXPECT_LT(light.position.y, ceiling.positions[0].y);
  for (const glm::vec3& corner : ceiling.positions) {
    const float angle = std::acos(glm::dot(light.direction, glm::normalize(corner - light.position)));
    EXPECT_GT(angle, light.outerConeAngle);
  }
}

TEST(CornellBox, IsLoadedByName) {
  EXPECT_EQ(loadSceneByName("builtin:cornell_box").source, "builtin:cornell_box");
  EXPECT_EQ(sceneHash(loadSceneByName("builtin:cornell_box")), sceneHash(makeCornellBox()));
}

}  // namespace
}  // namespace lpvlab

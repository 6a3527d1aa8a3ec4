#pragma once
// Small scenes and helpers for the path tracer's tests: geometry whose light transport has a
// closed form, and the camera geometry recomputed independently of the tracer's CameraRays.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "framework/io/image.h"
#include "framework/scene/scene.h"

namespace lpvlab::testing {

// A planar quad (corners counter-clockwise seen from the side `normal` points to) as two
// triangles; uv (0,0) at corner 0, (1,0) at corner 1, (1,1) at corner 2.
inline Mesh quad(const std::string& name, int material, const std::array<glm::vec3, 4>& corners) {
  Mesh mesh;
  mesh.name = name;
  mesh.material = material;
  const glm::vec3 normal =
      glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
  const glm::vec2 uvs[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) {
    mesh.positions.push_back(corners[i]);
    mesh.normals.push_back(normal);
    mesh.uvs.push_back(uvs[i]);
  }
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

// One triangle in the plane z = 0 with corners (0,0), (1,0), (0,1) and vertex colours red, green
// and blue there, so the point (a, b, 0) has colour (1 - a - b, a, b); material 0's base colour
// (0.5, 0.8, 1.0).
inline Scene colouredTriangle() {
  Scene scene;
  scene.source = "test:coloured triangle";
  scene.materials.push_back(Material{.name = "grey", .baseColor = glm::vec3(0.5f, 0.8f, 1.0f)});
  Mesh mesh;
  mesh.name = "triangle";
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.normals.assign(3, glm::vec3(0, 0, 1));
  mesh.uvs.resize(3);
  mesh.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.indices = {0, 1, 2};
  scene.meshes.push_back(mesh);
  return scene;
}

// The horizontal square [-half, half]^2 at height y, facing up; u grows with x, v with z.
inline Mesh horizontalSquare(const std::string& name, int material, float half, float y) {
  return quad(name, material,
              {glm::vec3(-half, y, half), glm::vec3(half, y, half), glm::vec3(half, y, -half),
               glm::vec3(-half, y, -half)});
}

// A closed, watertight sphere about the origin with flat (per-triangle) normals pointing inwards:
// `rings` bands of latitude, `segments` of longitude. Vertex positions come from one function of
// (ring, segment), so neighbouring triangles share bit-identical edges and no ray escapes.
inline Mesh inwardSphere(int material, float radius, int rings, int segments) {
  auto at = [&](int ring, int segment) {
    const double theta = M_PI * ring / rings, phi = 2.0 * M_PI * (segment % segments) / segments;
    if (ring == 0) return glm::vec3(0, radius, 0);  // exact poles, shared by a whole band
    if (ring == rings) return glm::vec3(0, -radius, 0);
    return glm::vec3(float(radius * std::sin(theta) * std::cos(phi)),
                     float(radius * std::cos(theta)),
                     float(radius * std::sin(theta) * std::sin(phi)));
  };
  Mesh mesh;
  mesh.name = "sphere";
  mesh.material = material;
  auto triangle = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
    if (glm::dot(normal, a + b + c) > 0.0f) std::swap(b, c), normal = -normal;  // face the centre
    for (const glm::vec3& p : {a, b, c}) {
      mesh.indices.push_back(std::uint32_t(mesh.positions.size()));
      mesh.positions.push_back(p);
      mesh.normals.push_back(normal);
      mesh.uvs.push_back(glm::vec2(0.0f));
    }
  };
  for (int ring = 0; ring < rings; ++ring)
    for (int segment = 0; segment < segments; ++segment) {
      const glm::vec3 a = at(ring, segment), b = at(ring, segment + 1);
      const glm::vec3 c = at(ring + 1, segment), d = at(ring + 1, segment + 1);
      if (ring > 0) triangle(a, b, d);
      if (ring < rings - 1) triangle(a, d, c);
    }
  return mesh;
}

// A camera at `position` looking straight down, image top towards -z.
inline Camera lookingDown(glm::vec3 position, float verticalFov) {
  return {.name = "down", .position = position, .forward = {0, -1, 0}, .up = {0, 0, -1},
          .verticalFov = verticalFov, .nearPlane = 0.01f, .farPlane = 1000.0f};
}

// The unit direction through image position (px, py) in pixels, row 0 at the top, by inverting
// the G-buffer's clip-from-world matrix (independent of the tracer's own ray set-up).
inline glm::dvec3 pixelRay(const Camera& camera, int width, int height, double px, double py) {
  const glm::dmat4 clipFromWorld =
      glm::perspective(double(camera.verticalFov), double(width) / height,
                       double(camera.nearPlane), double(camera.farPlane)) *
      glm::lookAt(glm::dvec3(camera.position), glm::dvec3(camera.position + camera.forward),
                  glm::dvec3(camera.up));
  const glm::dmat4 worldFromClip = glm::inverse(clipFromWorld);
  const double ndcX = 2.0 * px / width - 1.0, ndcY = 1.0 - 2.0 * py / height;
  const glm::dvec4 nearPoint = worldFromClip * glm::dvec4(ndcX, ndcY, -1.0, 1.0);
  const glm::dvec4 farPoint = worldFromClip * glm::dvec4(ndcX, ndcY, 1.0, 1.0);
  return glm::normalize(glm::dvec3(farPoint) / farPoint.w - glm::dvec3(nearPoint) / nearPoint.w);
}

inline const Image& aov(const std::vector<NamedImage>& images, const std::string& name) {
  for (const NamedImage& image : images)
    if (image.name == name) return image.image;
  ADD_FAILURE() << "no AOV named " << name;
  static const Image kNone;
  return kNone;
}

}  // namespace lpvlab::testing

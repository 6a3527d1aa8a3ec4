#pragma once
// Scenes and closed forms of the radiosity tests: a closed box (the furnace), and the two
// configurations whose form factors have closed forms (Howell's catalogue, C-11 and C-14).

#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "framework/radiosity/form_factors.h"
#include "framework/radiosity/patches.h"
#include "framework/scene/scene.h"
#include "reference/test_scenes.h"

namespace lpvlab::test {

inline Material plainMaterial(const std::string& name, glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f)) {
  Material m;
  m.name = name;
  m.baseColor = albedo;
  m.emission = emission;
  return m;
}

// The cube [0, 1]^3, its six faces wound to face inwards, all of one material.
inline Scene closedCube(glm::vec3 albedo, glm::vec3 emission) {
  Scene scene;
  scene.source = "test:closed_cube";
  scene.materials.push_back(plainMaterial("walls", albedo, emission));
  using glm::vec3;
  scene.meshes.push_back(testing::quad("floor", 0, {vec3(0, 0, 0), vec3(0, 0, 1), vec3(1, 0, 1), vec3(1, 0, 0)}));
  scene.meshes.push_back(testing::quad("ceiling", 0, {vec3(0, 1, 0), vec3(1, 1, 0), vec3(1, 1, 1), vec3(0, 1, 1)}));
  scene.meshes.push_back(testing::quad("left", 0, {vec3(0, 0, 0), vec3(0, 1, 0), vec3(0, 1, 1), vec3(0, 0, 1)}));
  scene.meshes.push_back(testing::quad("right", 0, {vec3(1, 0, 0), vec3(1, 0, 1), vec3(1, 1, 1), vec3(1, 1, 0)}));
  scene.meshes.push_back(testing::quad("back", 0, {vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)}));
  scene.meshes.push_back(testing::quad("front", 0, {vec3(0, 0, 1), vec3(0, 1, 1), vec3(1, 1, 1), vec3(1, 0, 1)}));
  return scene;
}

// Two directly opposed a x b rectangles `c` apart: mesh 0 at y = 0 facing up, mesh 1 at y = c
// facing down.
inline Scene parallelRectangles(float a, float b, float c) {
  Scene scene;
  scene.source = "test:parallel_rectangles";
  scene.materials.push_back(plainMaterial("grey", glm::vec3(0.5f)));
  using glm::vec3;
  scene.meshes.push_back(testing::quad("lower", 0, {vec3(0, 0, 0), vec3(0, 0, b), vec3(a, 0, b), vec3(a, 0, 0)}));
  scene.meshes.push_back(testing::quad("upper", 0, {vec3(0, c, 0), vec3(a, c, 0), vec3(a, c, b), vec3(0, c, b)}));
  return scene;
}

// Two rectangles at right angles sharing an edge of length l along x: mesh 0 (l x w) in the
// floor y = 0, z in [0, w], facing up; mesh 1 (l x h) in the wall z = 0, y in [0, h], facing +z.
inline Scene perpendicularRectangles(float l, float w, float h) {
  Scene scene;
  scene.source = "test:perpendicular_rectangles";
  scene.materials.push_back(plainMaterial("grey", glm::vec3(0.5f)));
  using glm::vec3;
  scene.meshes.push_back(testing::quad("floor", 0, {vec3(0, 0, 0), vec3(0, 0, w), vec3(l, 0, w), vec3(l, 0, 0)}));
  scene.meshes.push_back(testing::quad("wall", 0, {vec3(0, 0, 0), vec3(l, 0, 0), vec3(l, h, 0), vec3(0, h, 0)}));
  return scene;
}

// Howell C-11: between directly opposed a x b rectangles c apart.
inline double parallelRectanglesFormFactor(double a, double b, double c) {
  const double x = a / c, y = b / c;
  const double x1 = std::sqrt(1 + x * x), y1 = std::sqrt(1 + y * y);
  return 2.0 / (M_PI * x * y) *
         (std::log(x1 * y1 / std::sqrt(1 + x * x + y * y)) + x * y1 * std::atan(x / y1) +
          y * x1 * std::atan(y / x1) - x * std::atan(x) - y * std::atan(y));
}

// Howell C-14: from the l x w rectangle to the l x h one, at right angles along their common
// edge l.
inline double perpendicularRectanglesFormFactor(double l, double w, double h) {
  const double W = w / l, H = h / l, W2 = W * W, H2 = H * H, R = std::sqrt(W2 + H2);
  const double a = (1 + W2) * (1 + H2) / (1 + W2 + H2);
  const double b = W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2));
  const double c = H2 * (1 + W2 + H2) / ((1 + H2) * (W2 + H2));
  return (W * std::atan(1 / W) + H * std::atan(1 / H) - R * std::atan(1 / R) +
          0.25 * (std::log(a) + W2 * std::log(b) + H2 * std::log(c))) /
         (M_PI * W);
}

// The area-to-area form factor from mesh `from`'s front sides to mesh `to`'s sides (either), from
// the rows: sum over i of A_i sum_j F_ij / A_from.
inline double meshFormFactor(const PatchMesh& mesh, const FormFactorRows& rows, int from, int to) {
  double weighted = 0.0, area = 0.0;
  for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
    if (mesh.patches[p].mesh != from) continue;
    double sum = 0.0;
    for (const FormFactor& f : rows.row(2 * p))
      if (mesh.patches[f.side / 2].mesh == to) sum += f.value;
    weighted += mesh.patches[p].area * sum;
    area += mesh.patches[p].area;
  }
  return weighted / area;
}

}  // namespace lpvlab::test

// glTF node animations (framework/scene/assimp_animations.cpp) on files made to order: the rigid
// world-space motion lpvlab reads must put every vertex where the file's own node transforms put
// it at that time (the parent's transform times the node's interpolated translation, rotation and
// rest scale, times the vertex), and what is not a rigid motion is one clear error.

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "framework/scene/scene_loader.h"
#include "scene/scene_test_support.h"

namespace lpvlab {
namespace {

using test::GltfWriter;
using test::TempDir;

const double kPi = 3.14159265358979323846;

// glTF quaternions are x, y, z, w.
std::vector<float> gltfQuat(const glm::dquat& q) {
  return {float(q.x), float(q.y), float(q.z), float(q.w)};
}
glm::dquat about(const glm::dvec3& axis, double degrees) {
  return glm::angleAxis(degrees * kPi / 180.0, glm::normalize(axis));
}

// A unit cube's corners, with normals (so the loader keeps its vertices, in their order).
test::Primitive cube() {
  test::Primitive p;
  for (int i = 0; i < 8; ++i) {
    p.positions.push_back({i & 1 ? 0.5f : -0.5f, i & 2 ? 0.5f : -0.5f, i & 4 ? 0.5f : -0.5f});
    p.normals.push_back(glm::normalize(p.positions.back()));
  }
  p.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
               2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return p;
}

// The file's own nodes: a carrier (rotated, moved, uniformly scaled by 2) holding the box, which
// the animation "slide" translates (LINEAR, three keys) and turns (STEP, two keys); a lamp the
// animation "spin" turns (LINEAR); a static floor.
struct AnimatedFile {
  glm::dmat4 carrier = glm::translate(glm::dmat4(1.0), {1.0, 2.0, 3.0}) *
                       glm::mat4_cast(about({0, 0, 1}, 30.0)) *
                       glm::scale(glm::dmat4(1.0), glm::dvec3(2.0));
  glm::dvec3 boxScale{0.5, 0.25, 1.0};
  std::vector<double> slideTimes = {0.0, 1.0, 2.0};
  std::vector<glm::dvec3> slideTranslations = {{0.5, 0, 0}, {1.5, 0, 0}, {1.5, 1, 0}};
  std::vector<double> turnTimes = {0.0, 2.0};
  std::vector<glm::dquat> turns = {about({1, 0, 0}, 10.0),
                                   about({0, 1, 0}, 90.0) * about({1, 0, 0}, 10.0)};

  GltfWriter writer;
  AnimatedFile() {
    writer.addMesh(cube());
    writer.json["nodes"] = {{{"name", "carrier"},
                             {"translation", {1, 2, 3}},
                             {"rotation", gltfQuat(about({0, 0, 1}, 30.0))},
                             {"scale", {2, 2, 2}},
                             {"children", {1}}},
                            {{"name", "box"},
                             {"mesh", 0},
                             {"translation", {0.5, 0, 0}},
                             {"rotation", gltfQuat(turns[0])},
                             {"scale", {boxScale.x, boxScale.y, boxScale.z}}},
                            {{"name", "lamp"}, {"mesh", 0}, {"translation", {-3, 0, 0}}},
                            {{"name", "floor"}, {"mesh", 0}, {"translation", {0, -4, 0}}}};
    writer.json["scenes"][0]["nodes"] = {0, 2, 3};
    std::vector<float> translations, rotations, spin;
    for (const glm::dvec3& t : slideTranslations)
      translations.insert(translations.end(), {float(t.x), float(t.y), float(t.z)});
    for (const glm::dquat& q : turns)
      for (float v : gltfQuat(q)) rotations.push_back(v);
    writer.addAnimationChannel("slide", 1, "translation", {0.0f, 1.0f, 2.0f}, translations);
    writer.addAnimationChannel("slide", 1, "rotation", {0.0f, 2.0f}, rotations, "STEP");
    for (double degrees : {0.0, 120.0})
      for (float v : gltfQuat(about({0, 1, 0}, degrees))) spin.push_back(v);
    writer.addAnimationChannel("spin", 2, "rotation", {0.5f, 1.5f}, spin);
  }

  // The box's transform to world at `t` as the file defines it: the carrier's, times the box's
  // translation (linear between keys), rotation (step: the last key at or before t) and scale.
  glm::dmat4 boxAt(double t) const {
    glm::dvec3 translation = slideTranslations.back();
    for (std::size_t k = 0; k + 1 < slideTimes.size(); ++k)
      if (t < slideTimes[k + 1]) {
        const double s = std::max(0.0, (t - slideTimes[k]) / (slideTimes[k + 1] - slideTimes[k]));
        translation = glm::mix(slideTranslations[k], slideTranslations[k + 1], s);
        break;
      }
    const glm::dquat rotation = t < turnTimes[1] ? turns[0] : turns[1];
    return carrier * glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation) *
           glm::scale(glm::dmat4(1.0), boxScale);
  }
};

const NodeAnimation& animationOf(const Scene& scene, const std::string& node) {
  for (const NodeAnimation& a : scene.nodeAnimations)
    if (a.node == node) return a;
  throw std::runtime_error("no animation of node " + node);
}

// NodeAnimation's motion at `t`, its keys interpolated as it says (linear: lerp / slerp).
glm::dvec3 moved(const NodeAnimation& a, const glm::dvec3& p, double t) {
  const auto at = [&](const std::vector<double>& times, auto& values, const std::string& how,
                      auto mix) {
    using Value = std::decay_t<decltype(values[0])>;
    if (t <= times.front()) return Value(values.front());
    for (std::size_t k = 0; k + 1 < times.size(); ++k)
      if (t < times[k + 1])
        return how == "step" ? Value(values[k])
                             : Value(mix(values[k], values[k + 1],
                                         (t - times[k]) / (times[k + 1] - times[k])));
    return Value(values.back());
  };
  const glm::dvec3 translation =
      a.translationTimes.empty()
          ? glm::dvec3(0.0)
          : at(a.translationTimes, a.translations, a.translationInterpolation,
               [](auto x, auto y, double s) { return glm::mix(x, y, s); });
  const glm::dquat rotation =
      a.rotationTimes.empty() ? glm::dquat(1, 0, 0, 0)
                              : at(a.rotationTimes, a.rotations, a.rotationInterpolation,
                                   [](auto x, auto y, double s) { return glm::slerp(x, y, s); });
  return a.pivot + rotation * (p - a.pivot) + translation;
}

TEST(NodeAnimations, AMovedVertexIsWhereTheFilesNodeTransformsPutIt) {
  for (const char* extension : {".gltf", ".glb"}) {
    TempDir dir;
    AnimatedFile file;
    const std::string path = dir.file(std::string("animated") + extension);
    if (std::string(extension) == ".glb")
      file.writer.writeGlb(path);
    else
      file.writer.writeGltf(path);
    const Scene scene = loadScene(path);
    ASSERT_EQ(scene.nodeAnimations.size(), 2u) << extension;
    const NodeAnimation& box = animationOf(scene, "box");
    EXPECT_EQ(box.animation, "slide");
    EXPECT_EQ(box.translationInterpolation, "linear");
    EXPECT_EQ(box.rotationInterpolation, "step") << "read from the file's JSON: " << extension;
    ASSERT_EQ(box.meshes.size(), 1u);
    const Mesh& rest = scene.meshes[std::size_t(box.meshes[0])];
    EXPECT_EQ(rest.name.substr(0, 4), "box/");
    EXPECT_EQ(animationOf(scene, "lamp").animation, "spin");

    const test::Primitive corners = cube();
    for (double t : {-1.0, 0.0, 0.4, 1.0, 1.7, 2.0, 5.0}) {
      const glm::dmat4 world = file.boxAt(std::max(t, 0.0));
      // The loader flattens the cube's vertices in their order, at rest (t = 0).
      for (std::size_t v = 0; v < corners.positions.size(); ++v) {
        const glm::dvec3 expected(world * glm::dvec4(glm::dvec3(corners.positions[v]), 1.0));
        const glm::dvec3 actual = moved(box, glm::dvec3(rest.positions[v]), t);
        EXPECT_NEAR(glm::distance(actual, expected), 0.0, 1e-5)
            << extension << ", t = " << t << " s, vertex " << v;
      }
    }
  }
}

TEST(NodeAnimations, WhatIsNotARigidMotionIsOneErrorNamingTheNode) {
  struct Case {
    const char* what;
    std::function<void(AnimatedFile&)> change;
    const char* phrase;
  };
  const std::vector<Case> cases = {
      {"scaling keys",
       [](AnimatedFile& f) {
         f.writer.addAnimationChannel("slide", 1, "scale", {0.0f, 1.0f}, {0.5f, 0.25f, 1, 1, 1, 1});
       },
       "scaling is animated"},
      {"a cubic spline",
       [](AnimatedFile& f) {
         f.writer.addAnimationChannel("spin", 3, "translation", {0.0f, 1.0f},
                                      {0, 0, 0, 0, -4, 0, 0, 0, 0, 0, 0, 0, 0, -3, 0, 0, 0, 0},
                                      "CUBICSPLINE");
       },
       "CUBICSPLINE"},
      {"an animated parent",
       [](AnimatedFile& f) {
         f.writer.addAnimationChannel("slide", 0, "translation", {0.0f, 1.0f}, {1, 2, 3, 1, 2, 4});
       },
       "ancestor 'carrier' is animated too"},
      {"a parent scaled unevenly",
       [](AnimatedFile& f) {
         f.writer.json["nodes"][0]["scale"] = {1, 2, 3};
       },
       "not a rotation and uniform scale"},
  };
  for (const Case& c : cases) {
    TempDir dir;
    AnimatedFile file;
    c.change(file);
    file.writer.writeGltf(dir.file("bad.gltf"));
    const std::string message = test::errorMessage([&] { loadScene(dir.file("bad.gltf")); });
    EXPECT_NE(message.find("bad.gltf"), std::string::npos) << c.what << ": " << message;
    EXPECT_NE(message.find(c.phrase), std::string::npos) << c.what << ": " << message;
  }
}

}  // namespace
}  // namespace lpvlab

// [animation] read against the built-in Cornell box: what moves, how (rigid meshes, keyed lights,
// the camera path), and one clear error for every kind of bad animation before any frame renders.
#include "framework/animation/animation_file.h"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cmath>

#include "error_support.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {
namespace {

using test::contains;
using test::errorOf;

struct Loaded {
  toml::table root;
  Scene scene;
  Camera camera;
  Animation animation;
};

// Reads `text`'s [animation] against the Cornell box, as loadExperiment does (and checks, as it
// does, that no key went unread).
Loaded load(const std::string& text, const std::vector<NodeAnimation>& nodeAnimations = {}) {
  Loaded l;
  l.root = toml::parse(text);
  l.scene = loadSceneByName("builtin:cornell_box");
  l.scene.nodeAnimations = nodeAnimations;
  l.camera = l.scene.cameras.front();
  Params params(l.root, "anim.toml");
  l.animation = readAnimation(params.table("animation"), l.scene, l.camera, true);
  params.finish();
  return l;
}

const char* kMovingBlock = R"(
[animation]
frames = 61
fps = 30
[[animation.meshes]]
meshes = ["short block"]
[[animation.meshes.keys]]
frame = 0
translation = [0, 0, 0]
rotation_deg = [0, 0, 0]
[[animation.meshes.keys]]
frame = 30
translation = [0.1, 0, -0.05]
rotation_deg = [0, 90, 0]
[[animation.meshes.keys]]
time = 2.0
translation = [0.2, 0, 0]
rotation_deg = [0, 120, 0]
)";

int meshNamed(const Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.meshes.size(); ++i)
    if (scene.meshes[i].name == name) return int(i);
  return -1;
}

TEST(AnimationFile, NoTableIsOneStaticFrame) {
  const Loaded l = load("");
  EXPECT_EQ(l.animation.frames, 1);
  EXPECT_FALSE(l.animation.animated());
}

TEST(AnimationFile, AMovingBlockMovesRigidlyAboutItsCentre) {
  Loaded l = load(kMovingBlock);
  ASSERT_EQ(l.animation.meshes.size(), 1u);
  EXPECT_TRUE(l.animation.movesGeometry());
  EXPECT_FALSE(l.animation.movesCamera());
  const int block = meshNamed(l.scene, "short block");
  const std::vector<glm::vec3> rest = l.scene.meshes[std::size_t(block)].positions;
  const glm::dvec3 pivot = l.animation.meshes[0].pivot;
  for (int frame : {0, 13, 30, 47, 60}) {
    applyAnimation(l.animation, l.animation.frameTime(frame), l.scene, l.camera);
    const Mesh& moved = l.scene.meshes[std::size_t(block)];
    // Rigid: every distance between vertices is kept, and normals stay unit length.
    for (std::size_t i = 0; i < rest.size(); ++i)
      for (std::size_t j = i + 1; j < rest.size(); j += 3)
        EXPECT_NEAR(glm::distance(moved.positions[i], moved.positions[j]),
                    glm::distance(rest[i], rest[j]), 1e-5);
    for (const glm::vec3& n : moved.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
    // The centre of the vertices moves by the translation (the pivot is their bounds' centre,
    // and a rotation about it keeps it).
    glm::dvec3 before(0.0), after(0.0);
    for (std::size_t i = 0; i < rest.size(); ++i)
      before += glm::dvec3(rest[i]), after += glm::dvec3(moved.positions[i]);
    before /= double(rest.size());
    after /= double(rest.size());
    const glm::dvec3 translation =
        l.animation.meshes[0].translation.sample(l.animation.frameTime(frame));
    const glm::dmat3 r =
        glm::mat3_cast(l.animation.meshes[0].rotation.sample(l.animation.frameTime(frame)));
    const glm::dvec3 expected = pivot + translation + r * (before - pivot);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(after[c], expected[c], 1e-5) << "frame " << frame;
  }
  // Frame 30 is a key: a quarter turn about +y, 0.1 m along x and -0.05 along z.
  applyAnimation(l.animation, 1.0, l.scene, l.camera);
  const glm::dvec3 p = glm::dvec3(l.scene.meshes[std::size_t(block)].positions[0]);
  const glm::dvec3 q = glm::dvec3(rest[0]) - pivot;
  const glm::dvec3 expected = pivot + glm::dvec3(0.1, 0, -0.05) + glm::dvec3(q.z, q.y, -q.x);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], expected[c], 1e-5);
  // Other meshes do not move.
  const int tall = meshNamed(l.scene, "tall block");
  EXPECT_EQ(l.scene.meshes[std::size_t(tall)].positions,
            loadSceneByName("builtin:cornell_box").meshes[std::size_t(tall)].positions);
}

TEST(AnimationFile, ACameraPathPassesThroughItsKeysAndSetsPlanesForTheWholePath) {
  Loaded l = load(R"(
[animation]
frames = 90
[animation.camera]
fov_deg = 50
[[animation.camera.keys]]
frame = 0
position = [0.28, 0.27, 0.8]
look_at = [0.28, 0.27, 0]
[[animation.camera.keys]]
frame = 45
position = [0.4, 0.3, 0.7]
look_at = [0.25, 0.2, 0]
fov_deg = 30
[[animation.camera.keys]]
frame = 89
position = [0.1, 0.3, 0.75]
look_at = [0.3, 0.27, 0]
)");
  ASSERT_TRUE(l.animation.camera);
  EXPECT_NEAR(l.camera.verticalFov, glm::radians(50.0f), 1e-6f);
  applyAnimation(l.animation, l.animation.frameTime(45), l.scene, l.camera);
  EXPECT_NEAR(l.camera.position.x, 0.4f, 1e-6f);
  EXPECT_NEAR(l.camera.verticalFov, glm::radians(30.0f), 1e-6f);
  const glm::vec3 toTarget = glm::normalize(glm::vec3(0.25f, 0.2f, 0) - l.camera.position);
  EXPECT_NEAR(glm::dot(toTarget, l.camera.forward), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::dot(l.camera.up, l.camera.forward), 0.0f, 1e-6f);
  EXPECT_GT(l.camera.farPlane, 1.0f);
}

TEST(AnimationFile, KeyedLightsFollowTheirKeysAndIntensityNeverOvershoots) {
  Loaded l = load(R"(
[animation]
frames = 40
[[animation.lights]]
light = "spot"
[[animation.lights.keys]]
frame = 0
intensity = 10
direction = [0, -1, 0]
[[animation.lights.keys]]
frame = 10
intensity = 0
[[animation.lights.keys]]
frame = 20
intensity = 10
direction = [0.5, -1, 0]
)");
  ASSERT_EQ(l.animation.lights.size(), 1u);
  for (int frame = 0; frame < 40; ++frame) {
    applyAnimation(l.animation, l.animation.frameTime(frame), l.scene, l.camera);
    const Light& spot = l.scene.lights[std::size_t(l.animation.lights[0].light)];
    // Linear between keys: a Catmull-Rom through 10, 0, 10 would dip below zero near frame 10.
    EXPECT_GE(spot.intensity, 0.0f) << frame;
    EXPECT_NEAR(glm::length(spot.direction), 1.0f, 1e-6f);
  }
  applyAnimation(l.animation, l.animation.frameTime(5), l.scene, l.camera);
  EXPECT_NEAR(l.scene.lights[0].intensity, 5.0f, 1e-5f);
}

// The scene file's node animations (scene.h NodeAnimation, read from glTF: tests/scene/
// node_animation_test.cpp) played by name: each a rigid motion of its meshes, its keys as the
// file gives them, interpolated as it says; "all" plays every one. Here two made by hand on the
// Cornell box's blocks.
TEST(AnimationFile, TheScenesNodeAnimationsPlayByName) {
  const Scene box = loadSceneByName("builtin:cornell_box");
  NodeAnimation slide;
  slide.animation = "slide";
  slide.node = "short";
  slide.meshes = {meshNamed(box, "short block")};
  slide.pivot = {0.2, 0.0, 0.2};
  slide.translationTimes = {0.0, 1.0};
  slide.translations = {{0, 0, 0}, {0.1, 0, 0}};
  slide.rotationTimes = {0.0, 1.0};
  slide.rotations = {glm::dquat(1, 0, 0, 0), glm::angleAxis(M_PI / 2, glm::dvec3(0, 1, 0))};
  slide.rotationInterpolation = "step";
  NodeAnimation lift = slide;
  lift.animation = "lift";
  lift.meshes = {meshNamed(box, "tall block")};
  lift.rotationTimes.clear();
  lift.rotations.clear();
  lift.translations = {{0, 0, 0}, {0, 0.2, 0}};

  Loaded l =
      load("[animation]\nframes = 3\nfps = 2\nscene_animation = \"slide\"\n", {slide, lift});
  ASSERT_EQ(l.animation.meshes.size(), 1u);
  EXPECT_TRUE(l.animation.movesGeometry());
  const int shortBlock = meshNamed(box, "short block");
  for (double t : {0.0, 0.5, 1.0, 2.0}) {
    Scene scene = l.scene;
    applyAnimation(l.animation, t, scene, l.camera);
    // Linear translation, the rotation held at its first key until the second (step).
    const glm::dvec3 translation(0.1 * std::min(t, 1.0), 0, 0);
    const glm::dquat rotation = t < 1.0 ? slide.rotations[0] : slide.rotations[1];
    for (std::size_t v = 0; v < box.meshes[std::size_t(shortBlock)].positions.size(); ++v) {
      const glm::dvec3 rest(box.meshes[std::size_t(shortBlock)].positions[v]);
      const glm::dvec3 expected = slide.pivot + rotation * (rest - slide.pivot) + translation;
      const glm::dvec3 actual(scene.meshes[std::size_t(shortBlock)].positions[v]);
      EXPECT_NEAR(glm::distance(actual, expected), 0.0, 1e-6) << "t = " << t << ", vertex " << v;
    }
  }
  const Loaded all = load("[animation]\nscene_animation = \"all\"\n", {slide, lift});
  EXPECT_EQ(all.animation.meshes.size(), 2u);

  // Unknown names list the file's; a scene without animations says so; a mesh the scene's
  // animation moves can't also be keyed by hand.
  std::string message =
      errorOf([&] { load("[animation]\nscene_animation = \"walk\"\n", {slide, lift}); });
  EXPECT_TRUE(contains(message, "animation.scene_animation")) << message;
  EXPECT_TRUE(contains(message, "'slide', 'lift'")) << message;
  message = errorOf([&] { load("[animation]\nscene_animation = \"all\"\n"); });
  EXPECT_TRUE(contains(message, "has no node animations")) << message;
  message = errorOf([&] {
    load(std::string("[animation]\nscene_animation = \"slide\"\n") +
             "[[animation.meshes]]\nmeshes = [\"short block\"]\n[[animation.meshes.keys]]\n"
             "frame = 0\ntranslation = [0, 0, 0]\n",
         {slide});
  });
  EXPECT_TRUE(contains(message, "already moved")) << message;
}

TEST(AnimationFile, BadAnimationsAreOneErrorNamingTheKey) {
  const auto error = [](const std::string& text) { return errorOf([&] { load(text); }); };
  EXPECT_TRUE(contains(error("[animation]\nframes = 0\n"),
                       "anim.toml:2: key 'animation.frames': 0 is below the minimum 1"));
  EXPECT_TRUE(contains(error("[animation]\nfps = 0\n"), "key 'animation.fps'"));
  EXPECT_TRUE(contains(error("[[animation.lights]]\nlight = "
                             "\"sun\"\n[[animation.lights.keys]]\nframe = 0\nintensity = 1\n"),
                       "key 'animation.lights[0].light': the scene builtin:cornell_box has no "
                       "light 'sun' (it has: spot)"));
  EXPECT_TRUE(
      contains(error("[[animation.meshes]]\nmeshes = [\"box\"]\n[[animation.meshes.keys]]\nframe = "
                     "0\ntranslation = [0,0,0]\n"),
               "has no mesh 'box'"));
  EXPECT_TRUE(contains(
      error("[[animation.meshes]]\nmeshes = [\"tall block\"]\n[[animation.meshes.keys]]\nframe = "
            "0\ntime = 0\ntranslation = [0,0,0]\n"),
      "give exactly one of time (seconds) and frame"));
  EXPECT_TRUE(
      contains(error("[[animation.meshes]]\nmeshes = [\"tall "
                     "block\"]\n[[animation.meshes.keys]]\nframe = 5\ntranslation = [0,0,0]\n"
                     "[[animation.meshes.keys]]\nframe = 3\ntranslation = [1,0,0]\n"),
               "key 'animation.meshes[0].keys[1].frame': 0.100000 s does not come after the "
               "previous key's 0.166667 s"));
  EXPECT_TRUE(contains(error("[[animation.meshes]]\nmeshes = [\"tall "
                             "block\"]\n[[animation.meshes.keys]]\nframe = 0\nscale = 2\n"),
                       "unknown key 'animation.meshes[0].keys[0].scale'; valid keys here: time, "
                       "frame, translation, rotation_deg"));
  EXPECT_TRUE(contains(error("[[animation.meshes]]\nmeshes = [\"tall "
                             "block\"]\n[[animation.meshes.keys]]\nframe = 0\n"),
                       "no key gives translation or rotation_deg"));
  EXPECT_TRUE(
      contains(error("[[animation.meshes]]\nmeshes = [\"tall "
                     "block\"]\n[[animation.meshes.keys]]\nframe = 0\ntranslation = [0,0,0]\n"
                     "[[animation.meshes]]\nmeshes = [\"tall "
                     "block\"]\n[[animation.meshes.keys]]\nframe = 0\ntranslation = [0,0,0]\n"),
               "mesh 'tall block' is already moved by an earlier [[animation.meshes]]"));
  EXPECT_TRUE(contains(error("[[animation.lights]]\nlight = "
                             "\"spot\"\n[[animation.lights.keys]]\nframe = 0\nintensity = -1\n"),
                       "key 'animation.lights[0].keys[0].intensity': -1 is below the minimum 0"));
  EXPECT_TRUE(contains(error("[animation.camera]\nup = [0, 1, 0]\n"), "no keys"));
  EXPECT_TRUE(contains(
      error("[animation.camera]\n[[animation.camera.keys]]\nframe = 0\nposition = [0, 0, 1]\n"),
      "needs position and look_at"));
  EXPECT_TRUE(
      contains(error("[animation.camera]\ninterpolation = \"cubic\"\n"), "unknown value 'cubic'"));
}

TEST(AnimationFile, AFrameWhoseCameraOrLightDegeneratesIsNamedBeforeRendering) {
  const auto error = [](const std::string& text) { return errorOf([&] { load(text); }); };
  // Linear from z = 1 to z = -1 while looking at the origin: frame 5 (t = 0.5 of the way) puts the
  // camera on its look-at point.
  EXPECT_TRUE(contains(error(R"(
[animation]
frames = 11
fps = 10
[animation.camera]
interpolation = "linear"
[[animation.camera.keys]]
frame = 0
position = [0, 0, 1]
look_at = [0, 0, 0]
[[animation.camera.keys]]
frame = 10
position = [0, 0, -1]
)"),
                       "key 'animation.camera': frame 5: camera path at 0.500000 s: the camera is "
                       "at the point it looks at"));
  // A spot turned from straight down to straight up, linearly: at the midpoint it has no direction.
  EXPECT_TRUE(contains(error(R"(
[animation]
frames = 3
fps = 1
[[animation.lights]]
light = "spot"
interpolation = "linear"
[[animation.lights.keys]]
frame = 0
direction = [0, -1, 0]
[[animation.lights.keys]]
frame = 2
direction = [0, 1, 0]
)"),
                       "key 'animation.lights': frame 1: light 'spot' at 1.000000 s: its direction "
                       "interpolates to zero"));
  // A quantity the light does not have.
  EXPECT_TRUE(contains(error("[[animation.lights]]\nlight = "
                             "\"spot\"\n[[animation.lights.keys]]\nframe = 0\nflux = 3\n"),
                       "unknown key 'animation.lights[0].keys[0].flux'; valid keys here: time, "
                       "frame, position, direction, intensity, color"));
}

}  // namespace
}  // namespace lpvlab

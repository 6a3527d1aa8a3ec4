#include <gtest/gtest.h>

#include "framework/scene/scene_loader.h"
#include "scene/scene_test_support.h"

namespace lpvlab {
namespace {

using test::cachedScene;
using test::sharedScene;

TEST(SceneHash, IsStableAcrossLoads) {
  EXPECT_EQ(sceneHash(loadScene(sharedScene("cornell_box/CornellBox-Original.obj"))),
            sceneHash(loadScene(sharedScene("cornell_box/CornellBox-Original.obj"))));
  EXPECT_EQ(sceneHash(loadScene(sharedScene("sponza/Sponza.gltf"))),
            sceneHash(cachedScene("sponza/Sponza.gltf")));
  EXPECT_EQ(sceneHash(makeCornellBox()), sceneHash(makeCornellBox()));
  EXPECT_EQ(sceneHash(makeCornellBox()).size(), 16u);
}

TEST(SceneHash, DiffersBetweenScenes) {
  EXPECT_NE(sceneHash(makeCornellBox()),
            sceneHash(cachedScene("cornell_box/CornellBox-Original.obj")));
}

// Each kind of content that changes an image changes the hash.
TEST(SceneHash, ChangesWithWhatAffectsAnImage) {
  const Scene original = cachedScene("sponza/Sponza.gltf");
  const std::string hash = sceneHash(original);
  const auto changed = [&](auto&& change) {
    Scene scene = original;
    change(scene);
    return sceneHash(scene);
  };
  EXPECT_NE(hash, changed([](Scene& s) { s.materials[0].baseColor.g += 0.01f; }));
  EXPECT_NE(hash, changed([](Scene& s) { s.materials[0].alphaMode = AlphaMode::Mask; }));
  EXPECT_NE(hash, changed([](Scene& s) { s.materials[0].emission.r = 1.0f; }));
  EXPECT_NE(hash, changed([](Scene& s) { s.textures[0].rgba8[100] ^= 1; }));
  EXPECT_NE(hash, changed([](Scene& s) { s.meshes[0].positions[0].x += 1e-3f; }));
  EXPECT_NE(hash, changed([](Scene& s) { s.meshes[0].material = 1; }));
  // Vertex colours: given (white, which renders as none does, but is other data), then changed.
  const auto coloured = [](Scene& s) { s.meshes[0].colors.assign(s.meshes[0].positions.size(), glm::vec3(1.0f)); };
  EXPECT_NE(hash, changed(coloured));
  EXPECT_NE(changed(coloured), changed([&](Scene& s) { coloured(s), s.meshes[0].colors[0].r = 0.5f; }));
  EXPECT_NE(hash, changed([](Scene& s) { s.cameras[0].verticalFov *= 0.5f; }));
  EXPECT_NE(hash, changed([](Scene& s) { s.lights.push_back(Light{}); }));
}

TEST(SceneHash, IgnoresNamesAndSource) {
  const Scene original = makeCornellBox();
  Scene renamed = original;
  renamed.source = "elsewhere";
  renamed.materials[0].name = "ivory";
  renamed.lights[0].intensity += 0.0f;
  renamed.lights[0].name = "lamp";
  EXPECT_EQ(sceneHash(original), sceneHash(renamed));
  renamed.lights[0].intensity *= 2.0f;
  EXPECT_NE(sceneHash(original), sceneHash(renamed));
}

}  // namespace
}  // namespace lpvlab

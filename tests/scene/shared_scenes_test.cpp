// The shared scenes load completely: triangle counts are computed here from the files
// themselves (OBJ face lines, glTF JSON over the node tree), independently of Assimp.

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/scene_test_support.h"

namespace lpvlab {
namespace {

using test::cachedScene;
using test::sharedScene;

// Every face line "f a b c d ..." with n corners is n - 2 triangles.
std::size_t objTriangles(const std::string& path) {
  std::ifstream in(path);
  std::size_t triangles = 0;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword) || keyword != "f") continue;
    std::size_t corners = 0;
    for (std::string corner; words >> corner;) ++corners;
    triangles += corners - 2;
  }
  return triangles;
}

nlohmann::json readJson(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// Triangles drawn: each node instance of a mesh draws all of its primitives' triangles.
std::size_t gltfDrawnTriangles(const nlohmann::json& gltf) {
  std::function<std::size_t(int)> drawn = [&](int nodeIndex) {
    const nlohmann::json& node = gltf["nodes"][nodeIndex];
    std::size_t triangles = 0;
    if (node.contains("mesh")) {
      for (const nlohmann::json& primitive : gltf["meshes"][node["mesh"].get<int>()]["primitives"]) {
        EXPECT_EQ(primitive.value("mode", 4), 4) << "only TRIANGLES primitives are counted";
        const int accessor = primitive.contains("indices") ? primitive["indices"].get<int>()
                                                           : primitive["attributes"]["POSITION"].get<int>();
        triangles += gltf["accessors"][accessor]["count"].get<std::size_t>() / 3;
      }
    }
    for (const nlohmann::json& child : node.value("children", nlohmann::json::array()))
      triangles += drawn(child.get<int>());
    return triangles;
  };
  std::size_t triangles = 0;
  for (const nlohmann::json& root : gltf["scenes"][gltf.value("scene", 0)]["nodes"])
    triangles += drawn(root.get<int>());
  return triangles;
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What every loaded scene must satisfy, whatever the file.
void expectWellFormed(const Scene& scene) {
  const Bounds bounds = scene.bounds();
  ASSERT_FALSE(bounds.empty());
  EXPECT_TRUE(finite(bounds.min) && finite(bounds.max));
  EXPECT_GT(glm::length(bounds.extent()), 0.0f);
  for (const Mesh& mesh : scene.meshes) {
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << mesh.name;
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size()) << mesh.name;
    ASSERT_EQ(mesh.indices.size() % 3, 0u) << mesh.name;
    ASSERT_GE(mesh.material, 0);
    ASSERT_LT(mesh.material, static_cast<int>(scene.materials.size()));
    for (std::uint32_t index : mesh.indices) ASSERT_LT(index, mesh.positions.size()) << mesh.name;
    for (const glm::vec3& n : mesh.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f) << mesh.name;
  }
  for (const Material& material : scene.materials)
    EXPECT_LT(material.baseColorTexture, static_cast<int>(scene.textures.size())) << material.name;
  for (const TextureImage& texture : scene.textures) {
    EXPECT_GT(texture.width, 0) << texture.path;
    EXPECT_GT(texture.height, 0) << texture.path;
    EXPECT_EQ(texture.rgba8.size(), static_cast<std::size_t>(texture.width) * texture.height * 4);
  }
}

class ObjScene : public testing::TestWithParam<const char*> {};

TEST_P(ObjScene, LoadsEveryFaceAsTriangles) {
  const Scene& scene = cachedScene(GetParam());
  EXPECT_EQ(scene.triangleCount(), objTriangles(sharedScene(GetParam())));
  expectWellFormed(scene);
}

INSTANTIATE_TEST_SUITE_P(Shared, ObjScene,
                         testing::Values("cornell_box/CornellBox-Original.obj",
                                         "cornell_box/CornellBox-Glossy.obj",
                                         "cornell_box/CornellBox-Sphere.obj",
                                         "sibenik/sibenik.obj"));

TEST(SharedScenes, CornellBoxObjHasItsPublishedCountAndEmissiveLight) {
  const Scene& scene = cachedScene("cornell_box/CornellBox-Original.obj");
  EXPECT_EQ(scene.triangleCount(), 36u);  // the scenes README
  bool foundLight = false;
  for (const Material& material : scene.materials) {
    if (material.name == "light") {
      foundLight = true;
      EXPECT_EQ(material.emission, glm::vec3(17, 12, 4));
    }
    if (material.name == "leftWall") {
      EXPECT_EQ(material.baseColor, glm::vec3(0.63f, 0.065f, 0.05f));
    }
  }
  EXPECT_TRUE(foundLight);
}

TEST(SharedScenes, SibenikHasItsPublishedCountAndTextures) {
  const Scene& scene = cachedScene("sibenik/sibenik.obj");
  EXPECT_NEAR(static_cast<double>(scene.triangleCount()), 73.5e3, 0.1e3);  // the scenes README
  EXPECT_FALSE(scene.textures.empty());
}

class GltfScene : public testing::TestWithParam<const char*> {};

TEST_P(GltfScene, DrawsEveryNodeInstance) {
  const Scene& scene = cachedScene(GetParam());
  EXPECT_EQ(scene.triangleCount(), gltfDrawnTriangles(readJson(sharedScene(GetParam()))));
  expectWellFormed(scene);
}

// Cameras: yfov, near and far as in the file; placed at their node's translation (every camera
// node of these files is a root node) looking along the node's rotation of -z.
TEST_P(GltfScene, CamerasMatchTheFile) {
  const Scene& scene = cachedScene(GetParam());
  const nlohmann::json gltf = readJson(sharedScene(GetParam()));
  std::size_t checked = 0;
  for (const nlohmann::json& node : gltf["nodes"]) {
    if (!node.contains("camera")) continue;
    const nlohmann::json& perspective = gltf["cameras"][node["camera"].get<int>()]["perspective"];
    const std::string name = node["name"];
    const auto camera = std::find_if(scene.cameras.begin(), scene.cameras.end(),
                                     [&](const Camera& c) { return c.name == name; });
    ASSERT_NE(camera, scene.cameras.end()) << name;
    EXPECT_NEAR(camera->verticalFov, perspective["yfov"].get<float>(), 1e-6f) << name;
    EXPECT_NEAR(camera->nearPlane, perspective["znear"].get<float>(), 1e-6f) << name;
    EXPECT_NEAR(camera->farPlane, perspective["zfar"].get<float>(), 1e-5f) << name;

    const std::vector<float> t = node["translation"], r = node["rotation"];
    const glm::quat rotation(r[3], r[0], r[1], r[2]);  // glm: w first; glTF: w last
    const glm::vec3 forward = rotation * glm::vec3(0, 0, -1);
    const glm::vec3 up = rotation * glm::vec3(0, 1, 0);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(camera->position[i], t[i], 1e-5f) << name;
      EXPECT_NEAR(camera->forward[i], forward[i], 1e-5f) << name;
      EXPECT_NEAR(camera->up[i], up[i], 1e-4f) << name;
    }
    ++checked;
  }
  EXPECT_EQ(checked, scene.cameras.size());
}

// The first vertex of every primitive of every node instance, read from the .bin and moved by
// the node's translation, rotation and scale here, is where the loader put it. (The node order
// is the file's: these files have only root nodes.)
TEST_P(GltfScene, NodeTransformsPlaceEveryInstance) {
  const std::string path = sharedScene(GetParam());
  const nlohmann::json gltf = readJson(path);
  const std::string bin = test::readFile(
      (std::filesystem::path(path).parent_path() / gltf["buffers"][0]["uri"].get<std::string>()).string());
  const auto firstVec3 = [&](int accessorIndex) {
    const nlohmann::json& accessor = gltf["accessors"][accessorIndex];
    const nlohmann::json& view = gltf["bufferViews"][accessor["bufferView"].get<int>()];
    glm::vec3 v;
    std::memcpy(&v, bin.data() + view.value("byteOffset", 0) + accessor.value("byteOffset", 0), sizeof v);
    return v;
  };

  const Scene& scene = cachedScene(GetParam());
  std::size_t meshIndex = 0;
  for (const nlohmann::json& root : gltf["scenes"][0]["nodes"]) {
    const nlohmann::json& node = gltf["nodes"][root.get<int>()];
    ASSERT_FALSE(node.contains("children") || node.contains("matrix"));
    if (!node.contains("mesh")) continue;
    const std::vector<float> t = node.value("translation", std::vector<float>{0, 0, 0});
    const std::vector<float> r = node.value("rotation", std::vector<float>{0, 0, 0, 1});
    const std::vector<float> s = node.value("scale", std::vector<float>{1, 1, 1});
    const glm::mat4 toWorld = glm::translate(glm::mat4(1.0f), glm::vec3(t[0], t[1], t[2])) *
                              glm::mat4_cast(glm::quat(r[3], r[0], r[1], r[2])) *
                              glm::scale(glm::mat4(1.0f), glm::vec3(s[0], s[1], s[2]));
    const glm::mat3 normalToWorld = glm::inverseTranspose(glm::mat3(toWorld));
    for (const nlohmann::json& primitive : gltf["meshes"][node["mesh"].get<int>()]["primitives"]) {
      ASSERT_LT(meshIndex, scene.meshes.size());
      const Mesh& mesh = scene.meshes[meshIndex++];
      const glm::vec3 position = toWorld * glm::vec4(firstVec3(primitive["attributes"]["POSITION"]), 1.0f);
      const glm::vec3 normal = glm::normalize(normalToWorld * firstVec3(primitive["attributes"]["NORMAL"]));
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(mesh.positions[0][i], position[i], 1e-4f) << mesh.name;
        EXPECT_NEAR(mesh.normals[0][i], normal[i], 1e-4f) << mesh.name;
      }
    }
  }
  EXPECT_EQ(meshIndex, scene.meshes.size());
}

INSTANTIATE_TEST_SUITE_P(Shared, GltfScene,
                         testing::Values("sponza/Sponza.gltf", "breakfast_room/BreakfastRoom.gltf"));

TEST(SharedScenes, SponzaAndBreakfastRoomHaveTheirCameras) {
  EXPECT_EQ(cachedScene("sponza/Sponza.gltf").cameras.size(), 4u);
  EXPECT_EQ(cachedScene("breakfast_room/BreakfastRoom.gltf").cameras.size(), 3u);
  EXPECT_NEAR(static_cast<double>(cachedScene("sponza/Sponza.gltf").triangleCount()), 262e3, 1e3);
}

TEST(SharedScenes, SponzaMaskMaterialsAreMasked) {
  std::set<std::string> masked;
  for (const Material& material : cachedScene("sponza/Sponza.gltf").materials) {
    if (material.alphaMode != AlphaMode::Mask) continue;
    masked.insert(material.name);
    EXPECT_EQ(material.alphaCutoff, 0.5f);  // glTF's default: the file gives none
    EXPECT_GE(material.baseColorTexture, 0) << material.name;
  }
  EXPECT_EQ(masked, (std::set<std::string>{"PotPlant1", "Chain", "Plants"}));
}

// Textures shared by materials are read once: one texture per distinct base colour image.
TEST(SharedScenes, SponzaReadsEachBaseColourImageOnce) {
  const nlohmann::json gltf = readJson(sharedScene("sponza/Sponza.gltf"));
  std::set<int> images;
  for (const nlohmann::json& material : gltf["materials"]) {
    const nlohmann::json pbr = material.value("pbrMetallicRoughness", nlohmann::json::object());
    if (pbr.contains("baseColorTexture"))
      images.insert(gltf["textures"][pbr["baseColorTexture"]["index"].get<int>()]["source"].get<int>());
  }
  const Scene& scene = cachedScene("sponza/Sponza.gltf");
  EXPECT_EQ(scene.textures.size(), images.size());
  std::set<std::string> paths;
  for (const TextureImage& texture : scene.textures) paths.insert(texture.path);
  EXPECT_EQ(paths.size(), scene.textures.size());
}

}  // namespace
}  // namespace lpvlab

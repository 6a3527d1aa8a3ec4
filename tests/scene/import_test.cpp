// Importing features checked on files made to order, where the right answer is known exactly:
// node transforms, instancing, mirroring, normals, texture coordinates, materials, embedded
// textures, KHR_lights_punctual lights and cameras.

#include <array>
#include <cmath>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "framework/scene/assimp_import.h"
#include "framework/scene/scene_loader.h"
#include "scene/scene_test_support.h"

namespace lpvlab {
namespace {

using test::GltfWriter;
using test::TempDir;

constexpr float kPi = 3.14159265358979f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "component " << i;
}

// glTF quaternions are x, y, z, w.
nlohmann::json rotation(const glm::vec3& axis, float radians) {
  const glm::vec3 v = glm::normalize(axis) * std::sin(radians / 2);
  return {v.x, v.y, v.z, std::cos(radians / 2)};
}

Scene load(const GltfWriter& gltf, const TempDir& dir) {
  gltf.writeGltf(dir.file("scene.gltf"));
  return loadScene(dir.file("scene.gltf"));
}

const test::Primitive kTriangle{.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                .normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}};

TEST(Import, FlattensEveryInstanceThroughTheNodeTree) {
  TempDir dir;
  GltfWriter gltf;
  gltf.addMesh(kTriangle);
  // A parent moved by (10, 0, 0) with two children drawing the same mesh.
  gltf.json["nodes"] = {{{"translation", {10, 0, 0}}, {"children", {1, 2}}},
                        {{"mesh", 0}},
                        {{"mesh", 0}, {"translation", {0, 0, 5}}, {"scale", {2, 2, 2}}}};
  gltf.json["scenes"][0]["nodes"] = {0};
  const Scene scene = load(gltf, dir);
  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.triangleCount(), 2u);
  expectNear(scene.meshes[0].positions[1], {11, 0, 0});
  expectNear(scene.meshes[1].positions[1], {12, 0, 5});
  expectNear(scene.meshes[1].normals[0], {0, 0, 1});  // uniform scale: still unit length
}

TEST(Import, NormalsUseTheInverseTransposeAndMirroringKeepsTrianglesCounterClockwise) {
  TempDir dir;
  GltfWriter gltf;
  // A slanted triangle whose normal is (1, 1, 0) / sqrt 2.
  gltf.addMesh({.positions = {{0, 0, 0}, {0, 0, 1}, {1, -1, 0}},
                .normals = std::vector<glm::vec3>(3, glm::normalize(glm::vec3(1, 1, 0)))});
  gltf.json["nodes"] = {{{"mesh", 0}, {"scale", {2, 1, 1}}}, {{"mesh", 0}, {"scale", {-1, 1, 1}}}};
  gltf.json["scenes"][0]["nodes"] = {0, 1};
  const Scene scene = load(gltf, dir);
  ASSERT_EQ(scene.meshes.size(), 2u);
  // Stretching x by 2 tilts the surface: its normal becomes (1/2, 1, 0) normalised.
  expectNear(scene.meshes[0].normals[0], glm::normalize(glm::vec3(0.5f, 1, 0)));
  expectNear(scene.meshes[1].normals[0], glm::normalize(glm::vec3(-1, 1, 0)));
  for (const Mesh& mesh : scene.meshes) {
    const glm::vec3 a = mesh.positions[mesh.indices[0]], b = mesh.positions[mesh.indices[1]],
                    c = mesh.positions[mesh.indices[2]];
    const glm::vec3 geometric = glm::normalize(glm::cross(b - a, c - a));
    expectNear(geometric, mesh.normals[mesh.indices[0]]);
  }
}

// Two triangles sharing an edge in different planes, indexed, without normals: each triangle
// gets its own flat normal at all three corners (Assimp 5.2's aiProcess_GenNormals gets this
// wrong at the shared vertices).
TEST(Import, MissingNormalsBecomeFlatNormalsPerTriangle) {
  TempDir dir;
  GltfWriter gltf;
  gltf.addMesh({.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, .indices = {0, 1, 2, 0, 3, 1}});
  gltf.json["nodes"] = {{{"mesh", 0}}};
  gltf.json["scenes"][0]["nodes"] = {0};
  const Scene scene = load(gltf, dir);
  ASSERT_EQ(scene.triangleCount(), 2u);
  const Mesh& mesh = scene.meshes[0];
  const glm::vec3 expected[] = {{0, 0, 1}, {0, 1, 0}};
  for (int t = 0; t < 2; ++t)
    for (int corner = 0; corner < 3; ++corner)
      expectNear(mesh.normals[mesh.indices[3 * t + corner]], expected[t]);
}

// lpvlab's texture coordinates have glTF's top-left origin, from glTF and OBJ alike.
TEST(Import, TextureCoordinatesHaveATopLeftOrigin) {
  TempDir dir;
  GltfWriter gltf;
  test::Primitive primitive = kTriangle;
  primitive.uvs = {{0.25f, 0.1f}, {1, 0.1f}, {0.25f, 1}};
  gltf.addMesh(primitive);
  gltf.json["nodes"] = {{{"mesh", 0}}};
  gltf.json["scenes"][0]["nodes"] = {0};
  const Scene fromGltf = load(gltf, dir);
  EXPECT_NEAR(fromGltf.meshes[0].uvs[0].x, 0.25f, 1e-6f);
  EXPECT_NEAR(fromGltf.meshes[0].uvs[0].y, 0.1f, 1e-6f);

  // OBJ's vt has a bottom-left origin: v = 0.9 is 0.1 from the top.
  const std::string obj = dir.write(
      "uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25 0.9\nvt 1 0.9\nvt 0.25 0\nf 1/1 2/2 3/3\n");
  const Scene fromObj = loadScene(obj);
  EXPECT_NEAR(fromObj.meshes[0].uvs[0].x, 0.25f, 1e-6f);
  EXPECT_NEAR(fromObj.meshes[0].uvs[0].y, 0.1f, 1e-6f);
}

// A 2 x 1 RGBA PNG: an opaque red texel, then a half-transparent green one.
std::string twoTexelPng(const TempDir& dir) {
  const std::string path = dir.file("texels.png");
  const std::array<std::uint8_t, 8> texels{255, 0, 0, 255, 0, 255, 0, 128};
  auto out = OIIO::ImageOutput::create(path);
  OIIO::ImageSpec spec(2, 1, 4, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // write the texels as they are
  EXPECT_TRUE(out && out->open(path, spec));
  EXPECT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, texels.data()));
  out->close();
  return test::readFile(path);
}

TEST(Import, MaterialsWithEmbeddedTexturesSharedByTwoMaterials) {
  TempDir dir;
  GltfWriter gltf;
  gltf.addImage(twoTexelPng(dir), "image/png");
  gltf.json["textures"] = {{{"source", 0}}};
  gltf.json["materials"] = {
      {{"name", "Leaves"},
       {"alphaMode", "MASK"},
       {"alphaCutoff", 0.3},
       {"emissiveFactor", {0.5, 0.25, 0}},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"baseColorTexture", {{"index", 0}}}}}},
      {{"name", "SameImage"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  test::Primitive first = kTriangle, second = kTriangle;
  first.material = 0;
  second.material = 1;
  gltf.addMesh(first);
  gltf.addMesh(second);
  gltf.json["nodes"] = {{{"mesh", 0}}, {{"mesh", 1}}};
  gltf.json["scenes"][0]["nodes"] = {0, 1};
  gltf.writeGlb(dir.file("scene.glb"));
  const Scene scene = loadScene(dir.file("scene.glb"));

  ASSERT_EQ(scene.textures.size(), 1u);
  const TextureImage& texture = scene.textures[0];
  EXPECT_EQ(texture.width, 2);
  EXPECT_EQ(texture.height, 1);
  EXPECT_EQ(texture.rgba8, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 255, 0, 128}));

  const Material& leaves = scene.materials[scene.meshes[0].material];
  EXPECT_EQ(leaves.name, "Leaves");
  EXPECT_EQ(leaves.baseColor, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_EQ(leaves.baseColorTexture, 0);
  EXPECT_EQ(leaves.alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(leaves.alphaCutoff, 0.3f);
  EXPECT_EQ(leaves.emission, glm::vec3(0.5f, 0.25f, 0.0f));
  const Material& same = scene.materials[scene.meshes[1].material];
  EXPECT_EQ(same.baseColorTexture, 0);
  EXPECT_EQ(same.alphaMode, AlphaMode::Opaque);
  EXPECT_EQ(same.baseColor, glm::vec3(1.0f));
}

// OBJ's map_Kd is read relative to the scene file, with the file's straight alpha kept.
TEST(Import, ObjTexturesAreReadBesideTheSceneFile) {
  TempDir dir;
  std::filesystem::create_directory(dir.file("maps"));
  dir.write("maps/texels.png", twoTexelPng(dir));
  dir.write("scene.mtl", "newmtl Stone\nKd 0.5 0.5 0.5\nKe 1 2 3\nmap_Kd maps/texels.png\n");
  const Scene scene = loadScene(dir.write(
      "scene.obj", "mtllib scene.mtl\nusemtl Stone\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  const Material& stone = scene.materials[scene.meshes[0].material];
  EXPECT_EQ(stone.baseColor, glm::vec3(0.5f));
  EXPECT_EQ(stone.emission, glm::vec3(1, 2, 3));
  ASSERT_EQ(stone.baseColorTexture, 0);
  EXPECT_EQ(scene.textures[0].rgba8, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 255, 0, 128}));
}

// The glossy lobe of the reference's brdf "phong" (Material::specular, shininess, metallic): OBJ's
// Ks and Ns as they are; glTF's metallic-roughness as a dielectric's 0.04, metallicFactor (default
// 1, as glTF's) and m = (2 / alpha^2 - 2) / 4 with alpha = roughness^2. The base colour stays.
TEST(Import, GlossyLobesFromObjAndGltfMaterials) {
  TempDir dir;
  dir.write("scene.mtl", "newmtl Glossy\nKd 0.5 0.4 0.3\nKs 0.3 0.2 0.1\nNs 64\n");
  const Scene obj = loadScene(dir.write(
      "scene.obj", "mtllib scene.mtl\nusemtl Glossy\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  const Material& glossy = obj.materials[obj.meshes[0].material];
  EXPECT_EQ(glossy.baseColor, glm::vec3(0.5f, 0.4f, 0.3f));
  EXPECT_EQ(glossy.specular, glm::vec3(0.3f, 0.2f, 0.1f));
  EXPECT_FLOAT_EQ(glossy.shininess, 64.0f);
  EXPECT_EQ(glossy.metallic, 0.0f);

  GltfWriter gltf;
  gltf.json["materials"] = {
      {{"name", "Plastic"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"metallicFactor", 0.3},
                                 {"roughnessFactor", 0.5}}}},
      {{"name", "Default"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.2, 0.2, 1}}}}}};
  test::Primitive first = kTriangle, second = kTriangle;
  first.material = 0;
  second.material = 1;
  gltf.addMesh(first);
  gltf.addMesh(second);
  gltf.json["nodes"] = {{{"mesh", 0}}, {{"mesh", 1}}};
  gltf.json["scenes"][0]["nodes"] = {0, 1};
  gltf.writeGlb(dir.file("scene.glb"));
  const Scene scene = loadScene(dir.file("scene.glb"));
  const Material& plastic = scene.materials[scene.meshes[0].material];
  EXPECT_EQ(plastic.baseColor, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_EQ(plastic.specular, glm::vec3(0.04f));
  EXPECT_FLOAT_EQ(plastic.metallic, 0.3f);
  EXPECT_NEAR(plastic.shininess, (2.0 / (0.25 * 0.25) - 2.0) / 4.0, 1e-3);  // 7.5
  const Material& fallback = scene.materials[scene.meshes[1].material];
  EXPECT_FLOAT_EQ(fallback.metallic, 1.0f);   // glTF's default metallicFactor
  EXPECT_FLOAT_EQ(fallback.shininess, 0.0f);  // roughness 1
}

TEST(Import, PunctualLightsArePlacedByTheirNodes) {
  TempDir dir;
  GltfWriter gltf;
  gltf.addMesh(kTriangle);
  gltf.json["extensionsUsed"] = {"KHR_lights_punctual"};
  gltf.json["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "spot"}, {"color", {1, 0.5, 0.25}}, {"intensity", 8},
       {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.6}}}},
      {{"type", "point"}, {"color", {0.5, 0.5, 1}}, {"intensity", 3}},
      {{"type", "directional"}, {"intensity", 2}}};
  const auto light = [](int index) { return nlohmann::json{{"KHR_lights_punctual", {{"light", index}}}}; };
  gltf.json["nodes"] = {
      {{"mesh", 0}},
      {{"name", "lamp post"}, {"translation", {10, 0, 0}}, {"children", {2}}},
      // Rotating -z by -90 degrees about x points it down.
      {{"name", "Spot"}, {"translation", {0, 5, 0}}, {"rotation", rotation({1, 0, 0}, -kPi / 2)},
       {"extensions", light(0)}},
      {{"name", "Bulb"}, {"translation", {1, 2, 3}}, {"extensions", light(1)}},
      {{"name", "Sun"}, {"rotation", rotation({0, 1, 0}, kPi / 2)}, {"extensions", light(2)}}};
  gltf.json["scenes"][0]["nodes"] = {0, 1, 3, 4};
  const Scene scene = load(gltf, dir);
  ASSERT_EQ(scene.lights.size(), 3u);

  const Light& spot = scene.lights[0];
  EXPECT_EQ(spot.name, "Spot");  // Assimp names lights after their nodes
  EXPECT_EQ(spot.type, LightType::Spot);
  expectNear(spot.position, {10, 5, 0});
  expectNear(spot.direction, {0, -1, 0});
  expectNear(spot.color, {1, 0.5f, 0.25f});
  EXPECT_FLOAT_EQ(spot.intensity, 8.0f);
  EXPECT_FLOAT_EQ(spot.innerConeAngle, 0.3f);  // glTF's half-angles
  EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.6f);

  const Light& bulb = scene.lights[1];
  EXPECT_EQ(bulb.type, LightType::Point);
  expectNear(bulb.position, {1, 2, 3});
  expectNear(bulb.color * bulb.intensity, glm::vec3(0.5f, 0.5f, 1) * 3.0f);

  const Light& sun = scene.lights[2];
  EXPECT_EQ(sun.type, LightType::Directional);
  expectNear(sun.direction, {-1, 0, 0});  // -z turned 90 degrees about y
  expectNear(sun.color * sun.intensity, glm::vec3(2.0f));
}

TEST(Import, CamerasArePlacedByTheirNodesOnce) {
  TempDir dir;
  GltfWriter gltf;
  gltf.addMesh(kTriangle);
  gltf.json["cameras"] = {
      {{"type", "perspective"},
       {"perspective", {{"aspectRatio", 2.0}, {"yfov", 0.5}, {"znear", 0.1}, {"zfar", 30}}}},
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.05}}}}};
  gltf.json["nodes"] = {
      {{"mesh", 0}},
      {{"name", "Root camera"}, {"camera", 0}, {"translation", {1, 2, 3}}},
      {{"name", "rig"}, {"translation", {1, 0, 0}}, {"rotation", rotation({0, 1, 0}, kPi / 2)},
       {"children", {3}}},
      {{"name", "Rig camera"}, {"camera", 1}, {"translation", {0, 0, 2}}, {"scale", {0.5, 0.5, 0.5}}}};
  gltf.json["scenes"][0]["nodes"] = {0, 1, 2};
  const Scene scene = load(gltf, dir);
  ASSERT_EQ(scene.cameras.size(), 2u);

  const Camera& root = scene.cameras[0];
  EXPECT_EQ(root.name, "Root camera");
  expectNear(root.position, {1, 2, 3});  // not twice the translation
  expectNear(root.forward, {0, 0, -1});
  expectNear(root.up, {0, 1, 0});
  EXPECT_FLOAT_EQ(root.verticalFov, 0.5f);  // yfov, whatever the aspect ratio
  EXPECT_FLOAT_EQ(root.nearPlane, 0.1f);
  EXPECT_FLOAT_EQ(root.farPlane, 30.0f);

  const Camera& rig = scene.cameras[1];
  expectNear(rig.position, {3, 0, 0});  // (0, 0, 2) turned about y, then moved by (1, 0, 0)
  expectNear(rig.forward, {-1, 0, 0});
  expectNear(rig.up, {0, 1, 0});
  EXPECT_FLOAT_EQ(rig.verticalFov, 0.7f);  // no aspect ratio
}

TEST(Import, OrthographicCamerasAreRefused) {
  TempDir dir;
  GltfWriter gltf;
  gltf.addMesh(kTriangle);
  gltf.json["cameras"] = {{{"type", "orthographic"},
                           {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}};
  gltf.json["nodes"] = {{{"mesh", 0}}, {{"name", "Plan view"}, {"camera", 0}}};
  gltf.json["scenes"][0]["nodes"] = {0, 1};
  const std::string message = test::errorMessage([&] { load(gltf, dir); });
  EXPECT_NE(message.find("scene.gltf"), std::string::npos) << message;
  EXPECT_NE(message.find("camera 'Plan view' is orthographic"), std::string::npos) << message;
}

// glTF and OBJ can't describe area lights, but other importers give them to Assimp: the
// conversion refuses them.
TEST(Import, AreaLightsAreRefused) {
  aiLight area;
  area.mName = "Panel";
  area.mType = aiLightSource_AREA;
  const std::string message =
      test::errorMessage([&] { convertLight(area, glm::mat4(1.0f), "room.gltf"); });
  EXPECT_NE(message.find("room.gltf"), std::string::npos) << message;
  EXPECT_NE(message.find("light 'Panel' is an area light"), std::string::npos) << message;

  aiLight ambient;
  ambient.mName = "Fill";
  ambient.mType = aiLightSource_AMBIENT;
  const std::string other =
      test::errorMessage([&] { convertLight(ambient, glm::mat4(1.0f), "room.gltf"); });
  EXPECT_NE(other.find("light 'Fill' has a type lpvlab can't use"), std::string::npos) << other;
}

}  // namespace
}  // namespace lpvlab

// Every way a scene file can be unusable gives an lpvlab::Error naming the file and the problem.

#include <gtest/gtest.h>

#include "framework/scene/scene_loader.h"
#include "scene/scene_test_support.h"

namespace lpvlab {
namespace {

using test::errorMessage;
using test::GltfWriter;
using test::TempDir;

// The message names the file and says what is wrong.
void expectError(const std::string& path, const std::vector<std::string>& phrases) {
  const std::string message = errorMessage([&] { loadScene(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
  for (const std::string& phrase : phrases)
    EXPECT_NE(message.find(phrase), std::string::npos) << "'" << phrase << "' not in: " << message;
}

const std::string kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

// One triangle, its positions in an external .bin.
GltfWriter triangleGltf() {
  GltfWriter gltf;
  gltf.addMesh({.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
  gltf.json["nodes"].push_back({{"mesh", 0}});
  gltf.json["scenes"][0]["nodes"].push_back(0);
  return gltf;
}

TEST(BadSceneFiles, MissingFile) {
  TempDir dir;
  expectError(dir.file("absent.gltf"), {"no such file"});
}

TEST(BadSceneFiles, Directory) {
  TempDir dir;
  std::filesystem::create_directory(dir.file("folder.obj"));
  expectError(dir.file("folder.obj"), {"is a directory"});
}

TEST(BadSceneFiles, UnsupportedExtension) {
  TempDir dir;
  expectError(dir.write("scene.fbx", kTriangleObj), {"unsupported scene format", ".fbx"});
  expectError(dir.write("scene", kTriangleObj), {"unsupported scene format", "no file extension"});
}

TEST(BadSceneFiles, MalformedGltfJson) {
  TempDir dir;
  const std::string path = dir.write("broken.gltf", R"({"asset": {"version": "2.0"}, "scenes": [)");
  expectError(path, {"malformed", "invalid JSON"});
}

TEST(BadSceneFiles, TruncatedBuffer) {
  TempDir dir;
  const std::string path = dir.file("truncated.gltf");
  triangleGltf().writeGltf(path);
  const std::string bin = dir.file("truncated.bin");
  const std::string bytes = test::readFile(bin);
  dir.write("truncated.bin", bytes.substr(0, bytes.size() / 2));
  expectError(path, {"malformed", "Assimp"});
}

TEST(BadSceneFiles, ObjWithoutFaces) {
  TempDir dir;
  expectError(dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), {"no triangles"});
}

TEST(BadSceneFiles, GltfWithOnlyPoints) {
  TempDir dir;
  GltfWriter gltf = triangleGltf();
  gltf.json["meshes"][0]["primitives"][0]["mode"] = 0;  // POINTS
  gltf.writeGltf(dir.file("points.gltf"));
  expectError(dir.file("points.gltf"), {"no triangles"});
}

TEST(BadSceneFiles, NonFiniteVertices) {
  TempDir dir;
  expectError(dir.write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"),
              {"non-finite vertex position"});
  expectError(dir.write("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 inf\nf 1//1 2//1 3//1\n"),
              {"non-finite vertex normal"});
}

TEST(BadSceneFiles, MissingTextureNamesTextureAndMaterial) {
  TempDir dir;
  GltfWriter gltf = triangleGltf();
  gltf.json["images"] = {{{"uri", "missing.png"}}};
  gltf.json["textures"] = {{{"source", 0}}};
  gltf.json["materials"] = {
      {{"name", "Painted"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  gltf.json["meshes"][0]["primitives"][0]["material"] = 0;
  gltf.writeGltf(dir.file("untextured.gltf"));
  expectError(dir.file("untextured.gltf"),
              {"material 'Painted'", "cannot read base colour texture", "missing.png"});
}

TEST(BadSceneFiles, UnreadableTexture) {
  TempDir dir;
  dir.write("scene.mtl", "newmtl Stone\nKd 1 1 1\nmap_Kd notanimage.png\n");
  dir.write("notanimage.png", "this is text");
  const std::string path = dir.write("scene.obj", "mtllib scene.mtl\nusemtl Stone\n" + kTriangleObj);
  expectError(path, {"material 'Stone'", "notanimage.png"});
}

TEST(BadSceneFiles, UnknownBuiltinScene) {
  const std::string message = errorMessage([] { loadSceneByName("builtin:teapot"); });
  EXPECT_NE(message.find("builtin:teapot"), std::string::npos) << message;
  EXPECT_NE(message.find("no such built-in scene"), std::string::npos) << message;
}

}  // namespace
}  // namespace lpvlab

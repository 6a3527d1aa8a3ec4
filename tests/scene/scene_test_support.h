#pragma once
// Helpers for the scene tests: the shared scenes, temporary folders, error messages, and a
// small glTF writer for files made to order.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "framework/scene/scene.h"

namespace lpvlab::test {

// A file under the shared scenes folder, e.g. sharedScene("sponza/Sponza.gltf").
std::string sharedScene(const std::string& relative);

// Each shared scene is loaded once per test binary (Sponza and Sibenik take a while).
const Scene& cachedScene(const std::string& relative);

// A fresh folder, removed with its contents at the end of the test.
class TempDir {
public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& contents) const;

private:
  std::filesystem::path path_;
};

// The message of the lpvlab::Error `action` throws; "" (and a test failure) when it throws none.
std::string errorMessage(const std::function<void()>& action);

// Reads a whole file (text or binary).
std::string readFile(const std::string& path);

// Triangle, normal and uv data of one glTF mesh primitive; empty arrays are left out.
struct Primitive {
  std::vector<glm::vec3> positions{};
  std::vector<std::uint16_t> indices{};
  std::vector<glm::vec3> normals{};
  std::vector<glm::vec2> uvs{};
  int material = -1;
};

// Builds glTF 2.0 files with one binary buffer: .gltf with an external .bin, or .glb.
class GltfWriter {
public:
  GltfWriter();
  nlohmann::json json;  // add nodes, materials, cameras, extensions... directly
  int addMesh(const Primitive& primitive);                       // index into "meshes"
  int addImage(const std::string& bytes, const std::string& mimeType);  // embedded in the buffer
  // A channel of animation `animation` (created on first use, by name): `node`'s `path`
  // ("translation", "rotation" (x, y, z, w) or "scale") keyed at `times` (seconds) with `values`
  // (3 or 4 floats per key; 3 times that for "CUBICSPLINE": in-tangent, value, out-tangent).
  void addAnimationChannel(const std::string& animation, int node, const std::string& path,
                           const std::vector<float>& times, const std::vector<float>& values,
                           const std::string& interpolation = "LINEAR");
  void writeGltf(const std::string& path) const;  // and <stem>.bin beside it
  void writeGlb(const std::string& path) const;

private:
  int addView(const void* data, std::size_t size);
  int addAccessor(const void* data, std::size_t count, int componentType, const char* type,
                  std::size_t elementSize);
  std::string bin_;
};

}  // namespace lpvlab::test

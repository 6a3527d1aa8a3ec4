#include "scene/scene_test_support.h"

#include <algorithm>
#include <atomic>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "framework/core/error.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab::test {

std::string sharedScene(const std::string& relative) {
  return std::string(LPVLAB_SHARED_DIR) + "/scenes/" + relative;
}

const Scene& cachedScene(const std::string& relative) {
  static std::map<std::string, Scene> scenes;
  const auto found = scenes.find(relative);
  if (found != scenes.end()) return found->second;
  return scenes.emplace(relative, loadScene(sharedScene(relative))).first->second;
}

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("lpvlab_scene_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::string TempDir::write(const std::string& name, const std::string& contents) const {
  const std::string path = file(name);
  std::ofstream(path, std::ios::binary) << contents;
  return path;
}

std::string errorMessage(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an lpvlab::Error";
  return "";
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream contents;
  contents << in.rdbuf();
  return contents.str();
}

GltfWriter::GltfWriter() {
  json = {{"asset", {{"version", "2.0"}}},
          {"scene", 0},
          {"scenes", {{{"nodes", nlohmann::json::array()}}}},
          {"nodes", nlohmann::json::array()},
          {"meshes", nlohmann::json::array()},
          {"accessors", nlohmann::json::array()},
          {"bufferViews", nlohmann::json::array()}};
}

int GltfWriter::addView(const void* data, std::size_t size) {
  bin_.resize((bin_.size() + 3) / 4 * 4, '\0');  // accessors must be 4-byte aligned
  json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", size}});
  bin_.append(static_cast<const char*>(data), size);
  return static_cast<int>(json["bufferViews"].size()) - 1;
}

int GltfWriter::addAccessor(const void* data, std::size_t count, int componentType,
                            const char* type, std::size_t elementSize) {
  const int view = addView(data, count * elementSize);
  json["accessors"].push_back(
      {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}});
  return static_cast<int>(json["accessors"].size()) - 1;
}

int GltfWriter::addMesh(const Primitive& p) {
  constexpr int kFloat = 5126, kUnsignedShort = 5123;
  nlohmann::json primitive;
  const int position =
      addAccessor(p.positions.data(), p.positions.size(), kFloat, "VEC3", sizeof(glm::vec3));
  glm::vec3 min(1e30f), max(-1e30f);
  for (const glm::vec3& v : p.positions) {
    min = glm::min(min, v);
    max = glm::max(max, v);
  }
  json["accessors"][position]["min"] = {min.x, min.y, min.z};  // required for POSITION
  json["accessors"][position]["max"] = {max.x, max.y, max.z};
  primitive["attributes"]["POSITION"] = position;
  if (!p.normals.empty())
    primitive["attributes"]["NORMAL"] =
        addAccessor(p.normals.data(), p.normals.size(), kFloat, "VEC3", sizeof(glm::vec3));
  if (!p.uvs.empty())
    primitive["attributes"]["TEXCOORD_0"] =
        addAccessor(p.uvs.data(), p.uvs.size(), kFloat, "VEC2", sizeof(glm::vec2));
  if (!p.indices.empty())
    primitive["indices"] = addAccessor(p.indices.data(), p.indices.size(), kUnsignedShort,
                                       "SCALAR", sizeof(std::uint16_t));
  if (p.material >= 0) primitive["material"] = p.material;
  json["meshes"].push_back({{"primitives", {primitive}}});
  return static_cast<int>(json["meshes"].size()) - 1;
}

int GltfWriter::addImage(const std::string& bytes, const std::string& mimeType) {
  const int view = addView(bytes.data(), bytes.size());
  json["images"].push_back({{"bufferView", view}, {"mimeType", mimeType}});
  return static_cast<int>(json["images"].size()) - 1;
}

void GltfWriter::addAnimationChannel(const std::string& animation, int node,
                                     const std::string& path, const std::vector<float>& times,
                                     const std::vector<float>& values,
                                     const std::string& interpolation) {
  constexpr int kFloat = 5126;
  if (!json.contains("animations")) json["animations"] = nlohmann::json::array();
  nlohmann::json* clip = nullptr;
  for (nlohmann::json& a : json["animations"])
    if (a["name"] == animation) clip = &a;
  if (!clip) {
    json["animations"].push_back({{"name", animation},
                                  {"channels", nlohmann::json::array()},
                                  {"samplers", nlohmann::json::array()}});
    clip = &json["animations"].back();
  }
  const int input = addAccessor(times.data(), times.size(), kFloat, "SCALAR", sizeof(float));
  json["accessors"][input]["min"] = {*std::min_element(times.begin(), times.end())};  // required
  json["accessors"][input]["max"] = {*std::max_element(times.begin(), times.end())};
  const std::size_t width = path == "rotation" ? 4 : 3;
  const int output = addAccessor(values.data(), values.size() / width, kFloat,
                                 width == 4 ? "VEC4" : "VEC3", width * sizeof(float));
  (*clip)["samplers"].push_back(
      {{"input", input}, {"output", output}, {"interpolation", interpolation}});
  (*clip)["channels"].push_back({{"sampler", (*clip)["samplers"].size() - 1},
                                 {"target", {{"node", node}, {"path", path}}}});
}

void GltfWriter::writeGltf(const std::string& path) const {
  const std::filesystem::path file(path);
  const std::string binName = file.stem().string() + ".bin";
  std::ofstream((file.parent_path() / binName).string(), std::ios::binary) << bin_;
  nlohmann::json out = json;
  out["buffers"] = {{{"byteLength", bin_.size()}, {"uri", binName}}};
  std::ofstream(path) << out.dump();
}

void GltfWriter::writeGlb(const std::string& path) const {
  nlohmann::json out = json;
  out["buffers"] = {{{"byteLength", bin_.size()}}};
  std::string text = out.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');  // chunks are 4-byte aligned
  std::string bin = bin_;
  bin.resize((bin.size() + 3) / 4 * 4, '\0');

  std::string glb;
  const auto u32 = [&](std::uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  u32(0x46546C67);  // "glTF"
  u32(2);
  u32(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
  u32(static_cast<std::uint32_t>(text.size()));
  u32(0x4E4F534A);  // "JSON"
  glb += text;
  u32(static_cast<std::uint32_t>(bin.size()));
  u32(0x004E4942);  // "BIN\0"
  glb += bin;
  std::ofstream(path, std::ios::binary) << glb;
}

}  // namespace lpvlab::test

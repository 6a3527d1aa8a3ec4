#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/scene/assimp_import.h"

namespace lpvlab {

glm::mat4 nodeToWorld(const aiNode& node) {
  glm::mat4 toWorld = toGlm(node.mTransformation);
  for (const aiNode* parent = node.mParent; parent; parent = parent->mParent)
    toWorld = toGlm(parent->mTransformation) * toWorld;
  return toWorld;
}

namespace {

// Assimp reports a .gltf whose JSON does not parse only as "No suitable reader found"; the JSON
// parser's own message says where the file is broken.
std::string describeImportFailure(const std::string& path, const std::string& assimpError) {
  std::string what = "malformed or unreadable scene file (Assimp: " + assimpError + ")";
  if (lowercaseExtension(path) == ".gltf") {
    std::ifstream in(path);
    try {
      [[maybe_unused]] const nlohmann::json json = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
      what += "; invalid JSON: " + std::string(e.what());
    }
  }
  return what;
}

bool finite(const aiVector3D& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Checked once per unique mesh, before any transform, so the message names the source data.
void requireFiniteVertices(const aiMesh& mesh, const std::string& path) {
  const auto check = [&](const aiVector3D* values, const char* what) {
    for (unsigned i = 0; i < mesh.mNumVertices; ++i)
      if (!finite(values[i]))
        throwAt(path, "mesh '" + std::string(mesh.mName.C_Str()) + "': non-finite vertex " + what +
                          " (NaN or Inf) at vertex " + std::to_string(i));
  };
  check(mesh.mVertices, "position");
  if (mesh.HasNormals()) check(mesh.mNormals, "normal");
  if (mesh.HasTextureCoords(0)) check(mesh.mTextureCoords[0], "texture coordinate");
}

using Triangle = std::array<std::uint32_t, 3>;

// aiProcess_Triangulate leaves point and line primitives as 1- and 2-index faces: they are no
// surface, so only the triangles are kept. A mirroring transform (negative determinant) turns
// counter-clockwise triangles clockwise; swapping two corners keeps them counter-clockwise.
std::vector<Triangle> triangles(const aiMesh& mesh, bool mirrored) {
  std::vector<Triangle> result;
  result.reserve(mesh.mNumFaces);
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;
    if (mirrored)
      result.push_back({face.mIndices[0], face.mIndices[2], face.mIndices[1]});
    else
      result.push_back({face.mIndices[0], face.mIndices[1], face.mIndices[2]});
  }
  return result;
}

// A zero normal can't be made unit length; such a mesh gets flat normals like one without any.
bool hasUsableNormals(const aiMesh& mesh) {
  if (!mesh.HasNormals()) return false;
  for (unsigned i = 0; i < mesh.mNumVertices; ++i)
    if (mesh.mNormals[i].SquareLength() == 0.0f) return false;
  return true;
}

// One drawn instance of a mesh, in world space. TextureImage coordinates: Assimp gives OpenGL's
// bottom-left origin (it flips glTF's v and keeps OBJ's); lpvlab's is top-left, like TextureImage.
Mesh flattenInstance(const aiMesh& in, const glm::mat4& toWorld, const std::string& name) {
  const glm::mat3 linear(toWorld);
  const std::vector<Triangle> tris = triangles(in, glm::determinant(linear) < 0.0f);
  const auto position = [&](std::uint32_t i) {
    const aiVector3D& p = in.mVertices[i];
    return glm::vec3(toWorld * glm::vec4(p.x, p.y, p.z, 1.0f));
  };
  const auto uv = [&](std::uint32_t i) {
    if (!in.HasTextureCoords(0)) return glm::vec2(0.0f);
    const aiVector3D& t = in.mTextureCoords[0][i];
    return glm::vec2(t.x, 1.0f - t.y);
  };

  Mesh out;
  out.name = name;
  out.material = static_cast<int>(in.mMaterialIndex);
  if (hasUsableNormals(in)) {
    const glm::mat3 normalToWorld = glm::inverseTranspose(linear);
    for (std::uint32_t i = 0; i < in.mNumVertices; ++i) {
      const aiVector3D& n = in.mNormals[i];
      out.positions.push_back(position(i));
      out.normals.push_back(glm::normalize(normalToWorld * glm::vec3(n.x, n.y, n.z)));
      out.uvs.push_back(uv(i));
    }
    for (const Triangle& t : tris) out.indices.insert(out.indices.end(), t.begin(), t.end());
    return out;
  }
  // Flat normals: every triangle gets its own three vertices. (aiProcess_GenNormals is not used:
  // in Assimp 5.2 it writes each face's normal into the vertices it shares with other faces, so
  // an indexed mesh gets the last face's normal at every shared vertex.)
  for (const Triangle& t : tris) {
    const glm::vec3 a = position(t[0]), b = position(t[1]), c = position(t[2]);
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    // A zero-area triangle covers nothing: any unit normal will do.
    const glm::vec3 normal = length > 0.0f ? n / length : glm::vec3(0, 1, 0);
    for (std::uint32_t corner = 0; corner < 3; ++corner) {
      out.indices.push_back(static_cast<std::uint32_t>(out.positions.size()));
      out.positions.push_back(corner == 0 ? a : corner == 1 ? b : c);
      out.normals.push_back(normal);
      out.uvs.push_back(uv(t[corner]));
    }
  }
  return out;
}

// Instanced meshes are flattened: every node that references a mesh gets its own copy.
// `placed`: the meshes each node placed (its own and its descendants').
void flattenNode(const aiScene& scene, const aiNode& node, const glm::mat4& parentToWorld,
                 std::vector<Mesh>& meshes, NodeMeshes& placed) {
  const glm::mat4 toWorld = parentToWorld * toGlm(node.mTransformation);
  const int first = int(meshes.size());
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[k]];
    const std::string name = std::string(node.mName.C_Str()) + "/" + mesh.mName.C_Str();
    meshes.push_back(flattenInstance(mesh, toWorld, name));
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    flattenNode(scene, *node.mChildren[c], toWorld, meshes, placed);
  placed[&node] = {first, int(meshes.size())};
}

// Assimp names a light or camera after the node that places it.
const aiNode& placingNode(const aiScene& scene, const aiString& name, const std::string& path,
                          const char* what) {
  const aiNode* node = scene.mRootNode->FindNode(name);
  if (!node) throwAt(path, std::string(what) + " '" + name.C_Str() + "' is not placed by any node");
  return *node;
}

}  // namespace

Scene importWithAssimp(const std::string& path) {
  Assimp::Importer importer;
  // No aiProcess_PreTransformVertices: flattenNode applies the node transforms itself, keeping
  // every instance. No aiProcess_GenNormals: see flattenInstance.
  const aiScene* imported = importer.ReadFile(path, aiProcess_Triangulate);
  if (!imported || !imported->mRootNode)
    throwAt(path, describeImportFailure(path, importer.GetErrorString()));
  const aiScene& ai = *imported;

  Scene scene;
  scene.source = path;
  for (unsigned m = 0; m < ai.mNumMeshes; ++m) requireFiniteVertices(*ai.mMeshes[m], path);
  scene.materials = convertMaterials(ai, path, scene.textures);
  NodeMeshes placed;
  flattenNode(ai, *ai.mRootNode, glm::mat4(1.0f), scene.meshes, placed);
  scene.nodeAnimations = convertNodeAnimations(ai, placed, path);
  for (unsigned l = 0; l < ai.mNumLights; ++l) {
    const aiLight& light = *ai.mLights[l];
    const aiNode& node = placingNode(ai, light.mName, path, "light");
    scene.lights.push_back(convertLight(light, nodeToWorld(node), path));
  }
  for (unsigned c = 0; c < ai.mNumCameras; ++c) {
    const aiCamera& camera = *ai.mCameras[c];
    const aiNode& node = placingNode(ai, camera.mName, path, "camera");
    scene.cameras.push_back(convertCamera(camera, nodeToWorld(node), path));
  }
  return scene;
}

}  // namespace lpvlab

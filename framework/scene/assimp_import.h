#pragma once
// Internal to the scene module (and its tests): turning what Assimp 5.2 imports from glTF and
// OBJ files into lpvlab's Scene. Split by job: assimp_loader.cpp walks the node tree and flattens
// meshes, assimp_materials.cpp converts materials and their textures, assimp_lights_cameras.cpp
// converts lights and cameras.

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <assimp/matrix4x4.h>
#include <assimp/scene.h>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "framework/scene/scene.h"

namespace lpvlab {

// Assimp matrices are row-major, glm's are column-major.
inline glm::mat4 toGlm(const aiMatrix4x4& m) { return glm::transpose(glm::make_mat4(&m.a1)); }

// The meshes each node places, its own and its descendants': [first, last) of Scene::meshes
// (flattening walks the tree depth first, so they are consecutive).
using NodeMeshes = std::map<const aiNode*, std::pair<int, int>>;

// The extension of `path`, lower-case, with its dot (".gltf"); empty when there is none.
std::string lowercaseExtension(const std::string& path);

// The transform from a node's space to world space (the product of it and all its ancestors).
glm::mat4 nodeToWorld(const aiNode& node);

// Reads `path` through Assimp into a Scene (without the "no triangles" check, which the caller
// makes). `path` names the file in every error message.
Scene importWithAssimp(const std::string& path);

// The scene's materials in Assimp's order (so aiMesh::mMaterialIndex indexes them), with their
// base colour textures read once per file into `textures`.
std::vector<Material> convertMaterials(const aiScene& scene, const std::string& path,
                                       std::vector<TextureImage>& textures);

// A light placed by its node's transform. Throws an Error naming `path` and the light for a
// type lpvlab cannot use (area, ambient, undefined).
Light convertLight(const aiLight& light, const glm::mat4& toWorld, const std::string& path);

// A perspective camera placed by its node's transform. Throws an Error naming `path` and the
// camera for an orthographic camera.
Camera convertCamera(const aiCamera& camera, const glm::mat4& toWorld, const std::string& path);

// The file's node animations (scene.h NodeAnimation), one per animated node and animation, from
// Assimp's channels; the interpolation of a glTF file's samplers is read from its JSON (Assimp 5.2
// does not pass it on). Throws an Error naming `path`, the animation and the node for what is not
// a rigid motion lpvlab can play: a scaling key other than the node's rest scale, a node under a
// non-uniformly scaled or animated parent, a CUBICSPLINE sampler.
std::vector<NodeAnimation> convertNodeAnimations(const aiScene& scene, const NodeMeshes& meshes,
                                                 const std::string& path);

}  // namespace lpvlab

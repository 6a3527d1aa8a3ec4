// A scene file's node animations (glTF animations, read through Assimp 5.2) as rigid motions of
// the meshes under each animated node, in world space (scene.h NodeAnimation).
//
// Assimp gives, per animation and animated node, keys of the node's local translation T, rotation
// R and scaling S, in ticks (seconds * mTicksPerSecond; 1000 for glTF). The node's transform at
// time t is P T(t) R(t) S(t), P its parent's transform to world space, and at rest (the node's
// mTransformation) P T0 R0 S0. With S(t) = S0, a world point p of its meshes as loaded goes to
//   P (T(t) + R(t) R0^-1 (P^-1 p - T0)).
// For a parent transform whose linear part is a uniform scale s times a rotation Q that is
//   pivot + Q R(t) R0^-1 Q^-1 (p - pivot) + s Q (T(t) - T0),   pivot = P T0 (the node's origin),
// NodeAnimation's form, with keys Q R_k R0^-1 Q^-1 and s Q (T_k - T0): fixed linear maps of the
// file's keys, so lerp and slerp between the mapped keys are the file's own interpolation.
// What is not such a motion is refused: scaling keys other than S0 (not rigid), a parent that
// scales unevenly or is animated itself in the same animation (its motion would compose with
// the child's).

#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <tuple>

#include "framework/core/error.h"
#include "framework/scene/assimp_import.h"

namespace lpvlab {

namespace {

// (animation index, node name, "translation" | "rotation" | "scale") -> glTF sampler
// interpolation ("LINEAR", "STEP", "CUBICSPLINE").
using SamplerInterpolations = std::map<std::tuple<int, std::string, std::string>, std::string>;

// The JSON of a .gltf file, or of a .glb file's first chunk; null for other files or what does
// not parse (Assimp has read the file already, and reports its own errors).
nlohmann::json gltfJson(const std::string& path) {
  const std::string extension = lowercaseExtension(path);
  if (extension != ".gltf" && extension != ".glb") return nullptr;
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (extension == ".glb") {
    // Header: magic, version, length (12 bytes); then the JSON chunk: length, type "JSON", data.
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || bytes.compare(16, 4, "JSON") != 0)
      return nullptr;
    const std::uint32_t length =
        std::uint32_t(std::uint8_t(bytes[12])) | std::uint32_t(std::uint8_t(bytes[13])) << 8 |
        std::uint32_t(std::uint8_t(bytes[14])) << 16 | std::uint32_t(std::uint8_t(bytes[15])) << 24;
    if (length > bytes.size() - 20) return nullptr;
    bytes = bytes.substr(20, length);
  }
  nlohmann::json json = nlohmann::json::parse(bytes, nullptr, /*allow_exceptions=*/false);
  return json.is_discarded() ? nlohmann::json(nullptr) : json;
}

SamplerInterpolations samplerInterpolations(const nlohmann::json& gltf) {
  SamplerInterpolations out;
  if (!gltf.is_object()) return out;
  const nlohmann::json nodes = gltf.value("nodes", nlohmann::json::array());
  const nlohmann::json animations = gltf.value("animations", nlohmann::json::array());
  if (!nodes.is_array() || !animations.is_array()) return out;
  for (std::size_t a = 0; a < animations.size(); ++a) {
    const nlohmann::json& animation = animations[a];
    if (!animation.is_object()) continue;
    const nlohmann::json channels = animation.value("channels", nlohmann::json::array());
    const nlohmann::json samplers = animation.value("samplers", nlohmann::json::array());
    if (!channels.is_array() || !samplers.is_array()) continue;
    for (const nlohmann::json& channel : channels) {
      if (!channel.is_object() || !channel.contains("target")) continue;
      const nlohmann::json& target = channel["target"];
      const nlohmann::json sampler = channel.value("sampler", nlohmann::json());
      const nlohmann::json node =
          target.is_object() ? target.value("node", nlohmann::json()) : nlohmann::json();
      if (!sampler.is_number_unsigned() || !node.is_number_unsigned()) continue;
      const std::size_t s = sampler.get<std::size_t>(), n = node.get<std::size_t>();
      if (s >= samplers.size() || n >= nodes.size() || !samplers[s].is_object() ||
          !nodes[n].is_object())
        continue;
      const nlohmann::json name = nodes[n].value("name", nlohmann::json());
      const nlohmann::json path = target.value("path", nlohmann::json());
      const nlohmann::json interpolation =
          samplers[s].value("interpolation", nlohmann::json("LINEAR"));
      if (name.is_string() && path.is_string() && interpolation.is_string())
        out[{int(a), name.get<std::string>(), path.get<std::string>()}] =
            interpolation.get<std::string>();
    }
  }
  return out;
}

glm::dvec3 toGlm(const aiVector3D& v) { return {v.x, v.y, v.z}; }
glm::dquat toGlm(const aiQuaternion& q) { return glm::normalize(glm::dquat(q.w, q.x, q.y, q.z)); }

// A channel's sampler interpolation as lpvlab plays it ("step", "linear"); a CUBICSPLINE is
// refused. `where` names the animation and node.
std::string playedInterpolation(const SamplerInterpolations& interpolations,
                                const std::tuple<int, std::string, std::string>& channel,
                                const std::string& where) {
  const auto found = interpolations.find(channel);
  const std::string name = found == interpolations.end() ? "LINEAR" : found->second;
  if (name == "STEP") return "step";
  if (name == "LINEAR") return "linear";
  throw Error(where + ": " + std::get<2>(channel) + " sampler is " + name +
              " (Assimp 5.2 reads only a CUBICSPLINE's values, not its tangents; lpvlab "
              "plays LINEAR and STEP samplers)");
}

// An animated node's parent transform: uniform scale s times rotation Q, or refused (the
// node's motion would not be rigid in world space).
struct RigidParent {
  glm::dmat4 transform;   // node to world of the parent
  glm::dmat3 linear;      // its linear part, s Q
  glm::dquat rotation;    // Q
};

RigidParent rigidParent(const aiNode& node, const std::string& where) {
  RigidParent parent;
  parent.transform = node.mParent ? glm::dmat4(nodeToWorld(*node.mParent)) : glm::dmat4(1.0);
  parent.linear = glm::dmat3(parent.transform);
  const double s = std::cbrt(glm::determinant(parent.linear));
  const glm::dmat3 q = parent.linear / s;
  const glm::dmat3 gram = glm::transpose(q) * q;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!(std::abs(gram[i][j] - (i == j ? 1.0 : 0.0)) < 1e-4))
        throw Error(where +
                    ": its parent's transform is not a rotation and uniform scale "
                    "(the node's motion would not be rigid in world space)");
  parent.rotation = glm::quat_cast(q);
  return parent;
}

// lpvlab moves meshes rigidly: a scaling key away from the rest scale `s0` is refused.
void refuseAnimatedScaling(const aiNodeAnim& channel, const glm::dvec3& s0, double ticksPerSecond,
                           const std::string& where) {
  for (unsigned k = 0; k < channel.mNumScalingKeys; ++k) {
    const glm::dvec3 scaling = toGlm(channel.mScalingKeys[k].mValue);
    const double tolerance = 1e-5 * std::max({std::abs(s0.x), std::abs(s0.y), std::abs(s0.z), 1e-3});
    if (glm::any(glm::greaterThan(glm::abs(scaling - s0), glm::dvec3(tolerance))))
      throw Error(where + ": its scaling is animated (at " +
                  std::to_string(channel.mScalingKeys[k].mTime / ticksPerSecond) +
                  " s); lpvlab moves meshes rigidly");
  }
}

}  // namespace

std::vector<NodeAnimation> convertNodeAnimations(const aiScene& scene, const NodeMeshes& meshes,
                                                 const std::string& path) {
  std::vector<NodeAnimation> out;
  if (scene.mNumAnimations == 0) return out;
  const SamplerInterpolations interpolations = samplerInterpolations(gltfJson(path));
  for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
    const aiAnimation& animation = *scene.mAnimations[a];
    const std::string animationName =
        animation.mName.length > 0 ? animation.mName.C_Str() : "animation " + std::to_string(a);
    const double ticksPerSecond =
        animation.mTicksPerSecond > 0.0 ? animation.mTicksPerSecond : 25.0;
    std::set<const aiNode*> animated;
    for (unsigned c = 0; c < animation.mNumChannels; ++c)
      if (const aiNode* node = scene.mRootNode->FindNode(animation.mChannels[c]->mNodeName))
        animated.insert(node);

    for (unsigned c = 0; c < animation.mNumChannels; ++c) {
      const aiNodeAnim& channel = *animation.mChannels[c];
      const std::string nodeName = channel.mNodeName.C_Str();
      const std::string where =
          path + ": animation '" + animationName + "', node '" + nodeName + "'";
      const aiNode* node = scene.mRootNode->FindNode(channel.mNodeName);
      if (!node) throw Error(where + ": no such node");
      for (const aiNode* up = node->mParent; up; up = up->mParent)
        if (animated.count(up))
          throw Error(where + ": its ancestor '" + up->mName.C_Str() +
                      "' is animated too (nested node animations are not supported)");
      const auto interpolationOf = [&](const char* gltfPath) {
        return playedInterpolation(interpolations, {int(a), nodeName, gltfPath}, where);
      };

      const RigidParent parent = rigidParent(*node, where);
      aiVector3D restScaling, restPosition;
      aiQuaternion restRotation;
      node->mTransformation.Decompose(restScaling, restRotation, restPosition);
      const glm::dvec3 t0 = toGlm(restPosition);
      const glm::dquat r0 = toGlm(restRotation);
      refuseAnimatedScaling(channel, toGlm(restScaling), ticksPerSecond, where);

      NodeAnimation motion;
      motion.animation = animationName;
      motion.node = nodeName;
      const auto placed = meshes.find(node);
      if (placed != meshes.end())
        for (int m = placed->second.first; m < placed->second.second; ++m)
          motion.meshes.push_back(m);
      motion.pivot = glm::dvec3(parent.transform * glm::dvec4(t0, 1.0));
      for (unsigned k = 0; k < channel.mNumPositionKeys; ++k) {
        motion.translationTimes.push_back(channel.mPositionKeys[k].mTime / ticksPerSecond);
        motion.translations.push_back(parent.linear * (toGlm(channel.mPositionKeys[k].mValue) - t0));
      }
      for (unsigned k = 0; k < channel.mNumRotationKeys; ++k) {
        motion.rotationTimes.push_back(channel.mRotationKeys[k].mTime / ticksPerSecond);
        motion.rotations.push_back(
            glm::normalize(parent.rotation * toGlm(channel.mRotationKeys[k].mValue) *
                           glm::inverse(r0) * glm::inverse(parent.rotation)));
      }
      if (channel.mNumPositionKeys > 0)
        motion.translationInterpolation = interpolationOf("translation");
      if (channel.mNumRotationKeys > 0) motion.rotationInterpolation = interpolationOf("rotation");
      if (channel.mNumScalingKeys > 1) interpolationOf("scale");  // a CUBICSPLINE is refused too
      out.push_back(std::move(motion));
    }
  }
  return out;
}

}  // namespace lpvlab

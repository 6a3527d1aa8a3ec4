// The hash covers what can change an image and nothing else: names and Scene::source are left
// out (the same content moved to another folder or renamed keeps its cached references), and
// textures count by their pixels, not their paths. Every value goes in field by field; arrays of
// glm vectors are hashed as the tightly packed floats they are.

#include <cstdint>

#include "framework/core/hash.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {
namespace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::vec2) == 2 * sizeof(float),
              "glm vectors must be packed floats for array hashing");

// Lengths go in first, so that two different splits of the same bytes hash differently.
template <class T>
void hashArray(Hasher& h, const std::vector<T>& values) {
  h.value(static_cast<std::uint64_t>(values.size()));
  h.bytes(values.data(), values.size() * sizeof(T));
}

void hashVec3(Hasher& h, const glm::vec3& v) { h.value(v.x).value(v.y).value(v.z); }

}  // namespace

std::string sceneHash(const Scene& scene) {
  Hasher h;
  h.text("lpvlab scene hash 2");  // changes when what is hashed changes

  h.value(static_cast<std::uint64_t>(scene.meshes.size()));
  for (const Mesh& mesh : scene.meshes) {
    hashArray(h, mesh.positions);
    hashArray(h, mesh.normals);
    hashArray(h, mesh.uvs);
    hashArray(h, mesh.colors);
    hashArray(h, mesh.indices);
    h.value(static_cast<std::int32_t>(mesh.material));
  }

  h.value(static_cast<std::uint64_t>(scene.materials.size()));
  for (const Material& material : scene.materials) {
    hashVec3(h, material.baseColor);
    h.value(static_cast<std::int32_t>(material.baseColorTexture));
    h.value(static_cast<std::int32_t>(material.alphaMode));
    h.value(material.alphaCutoff);
    hashVec3(h, material.emission);
    // Only glossy materials add their lobe, so the hash of a Lambertian scene is what it was.
    if (glm::any(glm::greaterThan(material.specular, glm::vec3(0.0f))) || material.metallic > 0.0f) {
      hashVec3(h, material.specular);
      h.value(material.shininess).value(material.metallic);
    }
  }

  h.value(static_cast<std::uint64_t>(scene.textures.size()));
  for (const TextureImage& texture : scene.textures) {
    h.value(static_cast<std::int32_t>(texture.width)).value(static_cast<std::int32_t>(texture.height));
    hashArray(h, texture.rgba8);
  }

  h.value(static_cast<std::uint64_t>(scene.lights.size()));
  for (const Light& light : scene.lights) {
    h.value(static_cast<std::int32_t>(light.type));
    hashVec3(h, light.position);
    hashVec3(h, light.direction);
    hashVec3(h, light.color);
    h.value(light.intensity).value(light.innerConeAngle).value(light.outerConeAngle);
  }

  h.value(static_cast<std::uint64_t>(scene.cameras.size()));
  for (const Camera& camera : scene.cameras) {
    hashVec3(h, camera.position);
    hashVec3(h, camera.forward);
    hashVec3(h, camera.up);
    h.value(camera.verticalFov).value(camera.nearPlane).value(camera.farPlane);
  }
  return h.hex();
}

}  // namespace lpvlab

#include <algorithm>
#include <filesystem>
#include <map>

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>

#include "framework/core/error.h"
#include "framework/scene/assimp_import.h"
#include "framework/scene/texture_loader.h"

namespace lpvlab {
namespace {

// Textures shared by several materials (common in Sponza) are read once: materials refer to
// them by the reference string Assimp gives ("*0" for a texture embedded in a .glb, otherwise a
// path relative to the scene file).
class TextureCache {
public:
  TextureCache(const aiScene& scene, const std::string& scenePath, std::vector<TextureImage>& textures)
      : scene_(scene), scenePath_(scenePath), textures_(textures) {}

  int index(const std::string& reference, const std::string& material) {
    const auto found = indices_.find(reference);
    if (found != indices_.end()) return found->second;
    try {
      textures_.push_back(read(reference));
    } catch (const Error& e) {
      throwAt(scenePath_, "material '" + material + "': cannot read base colour texture '" +
                              reference + "': " + e.what());
    }
    const int index = static_cast<int>(textures_.size()) - 1;
    indices_.emplace(reference, index);
    return index;
  }

private:
  TextureImage read(const std::string& reference) const {
    if (const aiTexture* embedded = scene_.GetEmbeddedTexture(reference.c_str())) {
      // glTF's embedded images are always compressed files (PNG, JPEG): mHeight == 0 says so and
      // mWidth is their size in bytes.
      const std::string name = scenePath_ + ":" + reference;
      if (embedded->mHeight != 0) throwAt(name, "uncompressed embedded textures are not supported");
      return decodeTexture(embedded->pcData, embedded->mWidth, embedded->achFormatHint, name);
    }
    // MTL files written on Windows use backslashes.
    std::string relative = reference;
    std::replace(relative.begin(), relative.end(), '\\', '/');
    const std::filesystem::path file = std::filesystem::path(scenePath_).parent_path() / relative;
    return readTextureFile(file.lexically_normal().string());
  }

  const aiScene& scene_;
  const std::string& scenePath_;
  std::vector<TextureImage>& textures_;
  std::map<std::string, int> indices_;
};

glm::vec3 rgb(const aiColor4D& c) { return {c.r, c.g, c.b}; }

Material convertMaterial(const aiMaterial& in, TextureCache& textures) {
  Material out;
  out.name = in.GetName().C_Str();

  // glTF's baseColorFactor is AI_MATKEY_BASE_COLOR; OBJ's Kd is only the diffuse colour. Clamped
  // to [0,1]: a Lambertian surface can't reflect more light than it receives.
  aiColor4D colour;
  if (in.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS ||
      in.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS)
    out.baseColor = glm::clamp(rgb(colour), 0.0f, 1.0f);

  // glTF's baseColorTexture is both BASE_COLOR and DIFFUSE; OBJ's map_Kd is DIFFUSE.
  aiString texture;
  if (in.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS ||
      in.GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS)
    out.baseColorTexture = textures.index(texture.C_Str(), out.name);

  // glTF only. BLEND is drawn opaque: lpvlab has no translucency. The cutoff is compared with
  // the texture's alpha alone (baseColorFactor's alpha is not kept).
  aiString alphaMode;
  if (in.Get(AI_MATKEY_GLTF_ALPHAMODE, alphaMode) == AI_SUCCESS &&
      std::string(alphaMode.C_Str()) == "MASK") {
    out.alphaMode = AlphaMode::Mask;
    in.Get(AI_MATKEY_GLTF_ALPHACUTOFF, out.alphaCutoff);
  }

  // OBJ's Ke, glTF's emissiveFactor.
  if (in.Get(AI_MATKEY_COLOR_EMISSIVE, colour) == AI_SUCCESS) out.emission = rgb(colour);
  return out;
}

}  // namespace

std::vector<Material> convertMaterials(const aiScene& scene, const std::string& path,
                                       std::vector<TextureImage>& textures) {
  TextureCache cache(scene, path, textures);
  std::vector<Material> materials;
  for (unsigned m = 0; m < scene.mNumMaterials; ++m)
    materials.push_back(convertMaterial(*scene.mMaterials[m], cache));
  return materials;
}

}  // namespace lpvlab

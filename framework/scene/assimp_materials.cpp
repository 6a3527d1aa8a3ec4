#include <algorithm>
#include <cmath>
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

// The glossy lobe (Material::specular, shininess, metallic). glTF's metallic-roughness: a
// dielectric's reflectance at normal incidence, 0.04, and metallicFactor as it is (its default is
// 1, as glTF's; phongAt mixes the lobe towards the albedo by it); GGX's alpha = roughness^2 has
// the Blinn-Phong exponent 2 / alpha^2 - 2 (Walter et al. 2007), and a Phong lobe about the
// reflected direction is about 4 times wider than a Blinn-Phong lobe about the half vector, so
// m = (2 / alpha^2 - 2) / 4 (0 for roughness 1, capped at 10^4 for 0). The textures of
// metallic-roughness are not read (no shipped scene has one). OBJ: Ks and Ns as they are (MTL's
// Ns is a Phong exponent), not metallic.
void readGlossyLobe(const aiMaterial& in, Material& out) {
  float metallic = 0.0f, roughness = 1.0f;
  const bool gltf = in.Get(AI_MATKEY_METALLIC_FACTOR, metallic) == AI_SUCCESS;
  if (gltf) {
    in.Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness);
    metallic = std::clamp(metallic, 0.0f, 1.0f);
    const double alpha = std::max(double(std::clamp(roughness, 0.0f, 1.0f)) * roughness, 1e-4);
    out.specular = glm::vec3(0.04f);
    out.metallic = metallic;
    out.shininess = float(std::min(1e4, (2.0 / (alpha * alpha) - 2.0) / 4.0));
    return;
  }
  aiColor4D colour;
  if (in.Get(AI_MATKEY_COLOR_SPECULAR, colour) == AI_SUCCESS)
    out.specular = glm::clamp(rgb(colour), 0.0f, 1.0f);
  float shininess = 0.0f;
  if (in.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && std::isfinite(shininess))
    out.shininess = std::clamp(shininess, 0.0f, 1e4f);
}

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
  readGlossyLobe(in, out);
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

#pragma once
// Material lookups at a surface point, as the LPV pipeline's raster passes do them
// (shaders/raster/material.glsl): albedo = base colour factor * base colour texture, where the
// texture is sRGB-encoded (decoded to linear per texel, before filtering, like a GL sRGB
// texture), filtered bilinearly with repeat wrapping; alpha is linear and, for Mask materials,
// cuts the surface out where it is below the cutoff. Emission is the material's constant
// radiance, emitted from both sides.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "framework/reference/phong_brdf.h"
#include "framework/scene/scene.h"

namespace lpvlab {

// One material prepared for per-hit lookups: untextured materials never touch a texture.
struct SurfaceMaterial {
  glm::vec3 baseColor{0.0f};              // linear albedo factor
  const TextureImage* texture = nullptr;  // base colour texture; null: none
  float alphaCutoff = -1.0f;              // Mask with a texture: cut out below this; < 0: never
  glm::vec3 emission{0.0f};               // W/(m^2 sr), both sides
  bool emissive = false;                  // any emission channel > 0
  glm::vec3 specular{0.0f};               // the lobe of brdf "phong" (Material's; phongAt)
  float shininess = 0.0f;
  float metallic = 0.0f;
};

// The scene's materials, with texture pointers into scene.textures (which must outlive them).
// Throws an Error naming the material for a texture index out of range, a texture whose pixel
// count doesn't match its size, or a non-finite or negative colour or emission.
std::vector<SurfaceMaterial> prepareMaterials(const Scene& scene);

// sRGB-encoded 8-bit value -> linear [0, 1], from a 256-entry table (the exact sRGB curve).
float srgbToLinear(std::uint8_t encoded);

// Bilinear lookup (texel centres at (i + 0.5) / size, repeat wrapping, uv (0, 0) the top-left
// corner): linear RGB (sRGB-decoded) and linear alpha.
glm::vec4 sampleTexture(const TextureImage& texture, glm::vec2 uv);
// The alpha channel alone (what alpha masks read), bilinear like sampleTexture.
float sampleAlpha(const TextureImage& texture, glm::vec2 uv);

inline glm::vec3 albedoAt(const SurfaceMaterial& material, glm::vec2 uv) {
  if (!material.texture) return material.baseColor;
  return material.baseColor * glm::vec3(sampleTexture(*material.texture, uv));
}

// Whether a material has a lobe for brdf "phong" to render.
inline bool glossyMaterial(const SurfaceMaterial& material) {
  return material.metallic > 0.0f || glm::any(glm::greaterThan(material.specular, glm::vec3(0.0f)));
}

// Its BRDF at a point of albedo `albedo` (base colour x texture x vertex colour): the lobe's
// reflectance mix(specular, albedo, metallic), the diffuse albedo (1 - metallic) albedo, limited
// to 1 - rho_s per channel so that no direction reflects more than it receives.
inline PhongBrdf phongAt(const SurfaceMaterial& material, const glm::vec3& albedo) {
  PhongBrdf brdf;
  brdf.specular = glm::mix(material.specular, albedo, material.metallic);
  brdf.diffuse = glm::min(albedo * (1.0f - material.metallic), glm::vec3(1.0f) - brdf.specular);
  brdf.exponent = material.shininess;
  return brdf;
}

// True where an alpha mask removes the surface.
inline bool cutOut(const SurfaceMaterial& material, glm::vec2 uv) {
  return material.alphaCutoff >= 0.0f && sampleAlpha(*material.texture, uv) < material.alphaCutoff;
}

}  // namespace lpvlab

#include "framework/reference/material_sampling.h"

#include <array>
#include <cmath>
#include <string>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

std::array<float, 256> makeSrgbTable() {
  std::array<float, 256> table{};
  for (int i = 0; i < 256; ++i) {
    const double c = i / 255.0;
    table[i] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
  }
  return table;
}

const std::array<float, 256> kSrgbToLinear = makeSrgbTable();

// The four texels around uv and their bilinear weights.
struct BilinearTaps {
  std::size_t texel[4];  // offsets of the texels' first byte in rgba8
  float weight[4];
};

// Wraps a texture coordinate into [0, 1); NaN and values that round to 1 become 0.
float wrapUnit(float t) {
  t -= std::floor(t);
  return t >= 0.0f && t < 1.0f ? t : 0.0f;
}

BilinearTaps bilinearTaps(const TextureImage& texture, glm::vec2 uv) {
  const int w = texture.width, h = texture.height;
  // Continuous texel coordinates with texel centres at integers; in [-0.5, size - 0.5).
  const float x = wrapUnit(uv.x) * float(w) - 0.5f;
  const float y = wrapUnit(uv.y) * float(h) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  const int x0 = (int(fx) + w) % w, x1 = (x0 + 1) % w;
  const int y0 = (int(fy) + h) % h, y1 = (y0 + 1) % h;
  auto at = [&](int col, int row) { return (std::size_t(row) * w + col) * 4; };
  return {{at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1)},
          {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty}};
}

void requireColour(const glm::vec3& c, const std::string& where, const char* what) {
  for (int i = 0; i < 3; ++i) {
    requireFinite(c[i], where, what);
    if (c[i] < 0.0f) throwAt(where, std::string(what) + " is negative");
  }
}

}  // namespace

float srgbToLinear(std::uint8_t encoded) { return kSrgbToLinear[encoded]; }

glm::vec4 sampleTexture(const TextureImage& texture, glm::vec2 uv) {
  const BilinearTaps taps = bilinearTaps(texture, uv);
  const std::uint8_t* rgba = texture.rgba8.data();
  glm::vec4 sum(0.0f);
  for (int i = 0; i < 4; ++i) {
    const std::uint8_t* texel = rgba + taps.texel[i];
    sum += taps.weight[i] * glm::vec4(kSrgbToLinear[texel[0]], kSrgbToLinear[texel[1]],
                                      kSrgbToLinear[texel[2]], texel[3] * (1.0f / 255.0f));
  }
  return sum;
}

float sampleAlpha(const TextureImage& texture, glm::vec2 uv) {
  const BilinearTaps taps = bilinearTaps(texture, uv);
  float sum = 0.0f;
  for (int i = 0; i < 4; ++i) sum += taps.weight[i] * texture.rgba8[taps.texel[i] + 3];
  return sum * (1.0f / 255.0f);
}

std::vector<SurfaceMaterial> prepareMaterials(const Scene& scene) {
  std::vector<SurfaceMaterial> out;
  out.reserve(scene.materials.size());
  for (const Material& material : scene.materials) {
    const std::string where = "material '" + material.name + "'";
    requireColour(material.baseColor, where, "base colour");
    requireColour(material.emission, where, "emission");
    requireColour(material.specular, where, "specular colour");
    requireFinite(material.shininess, where, "shininess");
    requireFinite(material.metallic, where, "metallic");
    if (material.shininess < 0.0f) throwAt(where, "shininess (the Phong exponent) is negative");
    if (material.metallic < 0.0f || material.metallic > 1.0f) throwAt(where, "metallic is outside [0, 1]");
    SurfaceMaterial prepared;
    prepared.baseColor = material.baseColor;
    prepared.emission = material.emission;
    prepared.specular = material.specular;
    prepared.shininess = material.shininess;
    prepared.metallic = material.metallic;
    prepared.emissive = material.emits();
    if (material.baseColorTexture >= 0) {
      if (std::size_t(material.baseColorTexture) >= scene.textures.size())
        throwAt(where, "base colour texture " + std::to_string(material.baseColorTexture) +
                           " does not exist (the scene has " +
                           std::to_string(scene.textures.size()) + ")");
      const TextureImage& texture = scene.textures[material.baseColorTexture];
      if (texture.width < 1 || texture.height < 1 ||
          texture.rgba8.size() != std::size_t(texture.width) * texture.height * 4)
        throwAt(where, "texture '" + texture.path + "' has no pixels or the wrong pixel count");
      prepared.texture = &texture;
      // Without a texture alpha is 1 everywhere (as in the raster passes): nothing to cut out.
      if (material.alphaMode == AlphaMode::Mask) prepared.alphaCutoff = material.alphaCutoff;
    }
    out.push_back(prepared);
  }
  return out;
}

}  // namespace lpvlab

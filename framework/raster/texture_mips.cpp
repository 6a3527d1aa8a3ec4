#include "framework/raster/texture_mips.h"

#include <algorithm>
#include <cmath>

#include "framework/reference/material_sampling.h"

namespace lpvlab {

std::uint8_t linearToSrgb(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  const float encoded = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return std::uint8_t(std::lround(encoded * 255.0f));
}

namespace {

// Level k + 1 from level k: each texel the bilinear mean of `above` at its centre, in linear space.
TextureImage halve(const TextureImage& above) {
  TextureImage below;
  below.path = above.path;
  below.width = std::max(1, above.width / 2);
  below.height = std::max(1, above.height / 2);
  below.rgba8.resize(std::size_t(below.width) * below.height * 4);
  for (int y = 0; y < below.height; ++y)
    for (int x = 0; x < below.width; ++x) {
      const glm::vec2 uv((x + 0.5f) / float(below.width), (y + 0.5f) / float(below.height));
      const glm::vec4 mean = sampleTexture(above, uv);
      std::uint8_t* texel = &below.rgba8[(std::size_t(y) * below.width + x) * 4];
      for (int c = 0; c < 3; ++c) texel[c] = linearToSrgb(mean[c]);
      texel[3] = std::uint8_t(std::lround(std::clamp(mean.a, 0.0f, 1.0f) * 255.0f));
    }
  return below;
}

}  // namespace

MipChain::MipChain(const TextureImage& level0) : level0_(&level0) {
  const TextureImage* above = &level0;
  while (above->width > 1 || above->height > 1) {
    levels_.push_back(halve(*above));
    above = &levels_.back();
  }
}

float MipChain::lodOf(glm::vec2 dUvDx, glm::vec2 dUvDy) const {
  const glm::vec2 size(level0_->width, level0_->height);
  const float rho = std::max(glm::length(dUvDx * size), glm::length(dUvDy * size));
  return rho > 0.0f && std::isfinite(rho) ? std::log2(rho) : 0.0f;
}

namespace {

// GL's LINEAR_MIPMAP_LINEAR: `bilinear` (a lookup in one level) in the two levels around `lod`,
// blended by its fraction; level 0 alone when magnified (lod <= 0, or NaN).
template <class Value, class Bilinear>
Value trilinear(float lod, int levels, Bilinear&& bilinear) {
  if (!(lod > 0.0f)) return bilinear(0);
  const int lower = int(std::floor(std::min(lod, float(levels - 1))));
  const float blend = std::min(lod, float(levels - 1)) - float(lower);
  const Value a = bilinear(lower);
  if (blend == 0.0f || lower == levels - 1) return a;
  return a + blend * (bilinear(lower + 1) - a);
}

}  // namespace

glm::vec4 MipChain::sample(glm::vec2 uv, float lod) const {
  return trilinear<glm::vec4>(lod, levels(), [&](int k) { return sampleTexture(level(k), uv); });
}

float MipChain::sampleAlpha(glm::vec2 uv, float lod) const {
  return trilinear<float>(lod, levels(), [&](int k) { return lpvlab::sampleAlpha(level(k), uv); });
}

std::size_t MipChain::bytes() const {
  std::size_t total = 0;
  for (const TextureImage& level : levels_) total += level.rgba8.size();
  return total;
}

}  // namespace lpvlab

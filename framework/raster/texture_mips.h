#pragma once
// A texture's mip chain and trilinear lookups, as the GL raster passes sample base colour
// textures (scene_gpu.cpp: sRGB8_ALPHA8, glGenerateTextureMipmap, LINEAR_MIPMAP_LINEAR, repeat):
//   - level k + 1 is level k halved (each side max(1, floor(n / 2))), each texel the bilinear
//     mean of level k at its centre (for even sizes the 2 x 2 box mean), in linear space, then
//     sRGB-encoded to 8 bits again, as Mesa generates an sRGB texture's mipmaps;
//   - the level of detail is OpenGL 4.6's (8.14.1) without anisotropy: lambda = log2(rho),
//     rho = the longer of d(u W, v H)/dx and d(u W, v H)/dy, the texture coordinates' change from
//     one pixel to the next in texels of level 0; lambda <= 0 samples level 0 bilinearly, above it
//     the two nearest levels are sampled bilinearly and blended by lambda's fraction.
// GL implementations may approximate rho (the specification allows it, and llvmpipe takes it
// per 2 x 2 quad), so minified textures can differ from GL's in the last bits of a blend, never by
// a level.

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "framework/scene/scene.h"

namespace lpvlab {

class MipChain {
public:
  // `level0` must outlive the chain (it is not copied).
  explicit MipChain(const TextureImage& level0);

  // The linear colour and alpha at uv, at level of detail `lod` (lodOf).
  glm::vec4 sample(glm::vec2 uv, float lod) const;
  // Its alpha alone (what alpha masks test), without decoding the colour.
  float sampleAlpha(glm::vec2 uv, float lod) const;
  // lambda for texture-coordinate derivatives along the image's x and y (per pixel).
  float lodOf(glm::vec2 dUvDx, glm::vec2 dUvDy) const;
  int levels() const { return int(levels_.size()) + 1; }
  // Bytes of the levels it made (level 0 is the scene's).
  std::size_t bytes() const;

private:
  const TextureImage& level(int k) const { return k == 0 ? *level0_ : levels_[std::size_t(k - 1)]; }

  const TextureImage* level0_;
  std::vector<TextureImage> levels_;  // levels 1, 2, ... down to 1 x 1
};

// The sRGB encoding of a linear value in [0, 1], rounded to 8 bits (the inverse of srgbToLinear,
// material_sampling.h).
std::uint8_t linearToSrgb(float linear);

}  // namespace lpvlab

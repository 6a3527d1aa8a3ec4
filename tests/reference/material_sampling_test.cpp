// Texture lookups as a GL sRGB texture with bilinear filtering and repeat wrapping does them.

#include <cmath>

#include <gtest/gtest.h>

#include "framework/reference/material_sampling.h"

namespace lpvlab {
namespace {

double srgbCurve(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// 2 x 2 texels, top row first: red, green / blue, white (alpha 0, 85, 170, 255).
TextureImage checker() {
  return {.path = "test:checker", .width = 2, .height = 2,
          .rgba8 = {255, 0, 0, 0, 0, 255, 0, 85, 0, 0, 255, 170, 255, 255, 255, 255}};
}

TEST(MaterialSampling, SrgbTableIsTheSrgbCurve) {
  for (int i = 0; i < 256; ++i)
    ASSERT_NEAR(srgbToLinear(std::uint8_t(i)), srgbCurve(i / 255.0), 1e-7);
  EXPECT_EQ(srgbToLinear(0), 0.0f);
  EXPECT_EQ(srgbToLinear(255), 1.0f);
}

TEST(MaterialSampling, TexelCentresReturnTheirTexel) {
  const TextureImage texture = checker();
  // uv (0, 0) is the top-left corner: texel (0, 0) (red) is centred at (0.25, 0.25).
  EXPECT_EQ(sampleTexture(texture, {0.25f, 0.25f}), glm::vec4(1, 0, 0, 0));
  EXPECT_EQ(sampleTexture(texture, {0.75f, 0.25f}), glm::vec4(0, 1, 0, 85 / 255.0f));
  EXPECT_EQ(sampleTexture(texture, {0.25f, 0.75f}), glm::vec4(0, 0, 1, 170 / 255.0f));
  EXPECT_EQ(sampleAlpha(texture, {0.75f, 0.75f}), 1.0f);
}

TEST(MaterialSampling, FiltersBilinearlyInLinearSpaceAndWraps) {
  const TextureImage texture = checker();
  // Midway between the four centres: the average of the decoded texels.
  const glm::vec4 centre = sampleTexture(texture, {0.5f, 0.5f});
  EXPECT_NEAR(centre.r, 0.5, 1e-6);
  EXPECT_NEAR(centre.g, 0.5, 1e-6);
  EXPECT_NEAR(centre.b, 0.5, 1e-6);
  EXPECT_NEAR(centre.a, 0.5, 1e-6);
  // Corners of the texture are midway between the texels across the wrapped edges too.
  const glm::vec4 corner = sampleTexture(texture, {0.0f, 0.0f});
  EXPECT_NEAR(corner.r, centre.r, 1e-6);
  EXPECT_NEAR(corner.a, centre.a, 1e-6);
  // Repeat: whole numbers added to uv change nothing.
  const glm::vec4 shifted = sampleTexture(texture, {0.3f + 3.0f, 0.6f - 2.0f});
  const glm::vec4 base = sampleTexture(texture, {0.3f, 0.6f});
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(shifted[c], base[c], 1e-5);
  EXPECT_NEAR(sampleAlpha(texture, {0.3f, 0.6f}), base.a, 1e-6);
}

TEST(MaterialSampling, MasksCutOutBelowTheCutoffOnlyWithATexture) {
  Scene scene;
  scene.textures = {checker()};
  scene.materials = {{.name = "masked", .baseColor = glm::vec3(0.5f), .baseColorTexture = 0,
                      .alphaMode = AlphaMode::Mask, .alphaCutoff = 0.5f},
                     {.name = "untextured mask", .alphaMode = AlphaMode::Mask},
                     {.name = "opaque", .baseColorTexture = 0}};
  const std::vector<SurfaceMaterial> materials = prepareMaterials(scene);
  EXPECT_TRUE(cutOut(materials[0], {0.25f, 0.25f}));   // alpha 0
  EXPECT_FALSE(cutOut(materials[0], {0.75f, 0.75f}));  // alpha 1
  EXPECT_FALSE(cutOut(materials[1], {0.25f, 0.25f}));  // no texture: alpha is 1
  EXPECT_FALSE(cutOut(materials[2], {0.25f, 0.25f}));  // opaque ignores alpha
  EXPECT_EQ(albedoAt(materials[0], {0.75f, 0.75f}), glm::vec3(0.5f));  // factor * white
}

}  // namespace
}  // namespace lpvlab

// Alpha masks cut surfaces out for every ray: a textured square hangs over a lit plane, its left
// half cut out by the texture's alpha, under a tilted directional light. Seen from above, each
// pixel shows one of: the square (kept by the intersection filter), the plane through the cut-out
// half (hit rejected by the intersection filter), the plane lit through the cut-out half (rejected
// by the occlusion filter) or the plane in the kept half's shadow. Pixels wholly of one kind have
// a noise-free direct radiance, computed here from an independent model of the scene: the
// square's albedo also checks the sRGB decoding of the texture.

#include <cmath>

#include <gtest/gtest.h>

#include "framework/reference/path_tracer.h"
#include "instruction_sets.h"
#include "test_scenes.h"

namespace lpvlab {
namespace {

constexpr int kSize = 48;
constexpr std::uint8_t kTexelSrgb = 188;
constexpr float kPlaneAlbedo = 0.5f;
constexpr float kIrradiance = 2.0f;
const glm::vec3 kLightDirection = glm::normalize(glm::vec3(0.0f, -1.0f, 0.6f));
const Camera kCamera = testing::lookingDown({0.2f, 3.5f, 1.0f}, glm::radians(80.0f));

// The texture's alpha along u (4 texels: 0, 0, 255, 255; bilinear, wrapping) and whether the
// mask keeps the square there (cutoff 0.5). The square spans x in [-1, 1] with u = (x + 1) / 2.
bool keptAt(double x) {
  const double alphas[4] = {0.0, 0.0, 1.0, 1.0};
  const double t = (x + 1.0) / 2.0 * 4.0 - 0.5;  // texel coordinate, centres at integers
  const int i = int(std::floor(t));
  const double f = t - i;
  const double alpha = (1 - f) * alphas[(i + 4) % 4] + f * alphas[(i + 5) % 4];
  return alpha >= 0.5;
}

bool insideSquare(const glm::dvec3& p) { return std::abs(p.x) < 1.0 && std::abs(p.z) < 1.0; }

// What the camera sees through an image position, and how the light reaches it.
enum class Seen { kSquare, kPlaneThroughHole, kPlane };
enum class Light { kOpen, kThroughHole, kBlocked };
struct Finding {
  Seen seen;
  Light light;
  bool operator==(const Finding&) const = default;
};

Finding findingAt(double px, double py) {
  const glm::dvec3 origin(kCamera.position);
  const glm::dvec3 d = testing::pixelRay(kCamera, kSize, kSize, px, py);
  const glm::dvec3 atSquare = origin + d * ((1.0 - origin.y) / d.y);
  // Nothing is above the square: it is always lit.
  if (insideSquare(atSquare) && keptAt(atSquare.x)) return {Seen::kSquare, Light::kOpen};
  const Seen seen = insideSquare(atSquare) ? Seen::kPlaneThroughHole : Seen::kPlane;
  const glm::dvec3 atPlane = origin + d * (-origin.y / d.y);
  // From the plane towards the light, up to the square's height.
  const glm::dvec3 towardsLight = -glm::dvec3(kLightDirection);
  const glm::dvec3 crossing = atPlane + towardsLight * (1.0 / towardsLight.y);
  if (!insideSquare(crossing)) return {seen, Light::kOpen};
  return {seen, keptAt(crossing.x) ? Light::kBlocked : Light::kThroughHole};
}

// The filters see packets of each instruction set's own width (16, 8 or 4 rays, or single rays).
class AlphaMask : public testing::PerInstructionSet {};

TEST_P(AlphaMask, CutOutPartsPassCameraAndShadowRays) {
  Scene scene;
  scene.source = "test:alpha mask";
  TextureImage texture{.path = "test:half cut out", .width = 4, .height = 1};
  for (std::uint8_t alpha : {0, 0, 255, 255})
    texture.rgba8.insert(texture.rgba8.end(), {kTexelSrgb, kTexelSrgb, kTexelSrgb, alpha});
  scene.textures = {texture};
  scene.materials = {{.name = "plane", .baseColor = glm::vec3(kPlaneAlbedo)},
                     {.name = "leaf", .baseColor = glm::vec3(1.0f), .baseColorTexture = 0,
                      .alphaMode = AlphaMode::Mask, .alphaCutoff = 0.5f}};
  scene.meshes = {testing::horizontalSquare("plane", 0, 50.0f, 0.0f),
                  testing::horizontalSquare("leaf", 1, 1.0f, 1.0f)};
  scene.lights = {{.name = "sun", .type = LightType::Directional, .direction = kLightDirection,
                   .intensity = kIrradiance}};
  PathTracer tracer(scene, kCamera, kSize, kSize, tracerSettings());
  Accumulator acc(kSize, kSize);
  tracer.render(acc, 4, 2);
  const std::vector<NamedImage> images = acc.images();
  const Image& direct = testing::aov(images, "direct");

  const double srgb = kTexelSrgb / 255.0;
  const double squareAlbedo = std::pow((srgb + 0.055) / 1.055, 2.4);
  const double irradiance = kIrradiance * -kLightDirection.y;
  int square = 0, planeThroughHole = 0, litThroughHole = 0, blocked = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Finding finding = findingAt(x, y);
      if (!(findingAt(x + 1, y) == finding && findingAt(x, y + 1) == finding &&
            findingAt(x + 1, y + 1) == finding))
        continue;  // straddles an edge: its expectation depends on where
      square += finding.seen == Seen::kSquare;
      planeThroughHole += finding.seen == Seen::kPlaneThroughHole;
      litThroughHole += finding.light == Light::kThroughHole;
      blocked += finding.light == Light::kBlocked;
      const double albedo = finding.seen == Seen::kSquare ? squareAlbedo : kPlaneAlbedo;
      const double expected =
          finding.light == Light::kBlocked ? 0.0 : albedo / M_PI * irradiance;
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(direct.at(x, y, c), expected, 1e-5 * expected)
            << "pixel (" << x << ", " << y << "): seen " << int(finding.seen) << ", light "
            << int(finding.light);
    }
  EXPECT_GE(square, 2);
  EXPECT_GE(planeThroughHole, 2);
  EXPECT_GE(litThroughHole, 2);
  EXPECT_GE(blocked, 2);
}

LPVLAB_PER_INSTRUCTION_SET(AlphaMask);

}  // namespace
}  // namespace lpvlab

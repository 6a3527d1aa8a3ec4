// Direct light on a large diffuse plane seen from straight above, against closed forms:
//   point/spot light:  L = a / pi * I falloff cos(theta) / r^2     (falloff: shared::spotFalloff)
//   directional light: L = a / pi * E cos(theta)
//   area light (a uniformly emitting quad): L = a / pi * E, E from Lambert's polygon formula
//   constant sky:      L = a * L_sky    (E = pi L_sky over the open hemisphere)
// A pixel's expectation is the average over its area (the tracer's box filter), computed here by
// a 16 x 16 midpoint rule over camera rays from the inverted G-buffer matrices, and each pixel is
// z-tested with the variance the tracer reports. A plane cannot light itself, so indirect is 0.

#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "framework/math/shared.h"
#include "framework/reference/path_tracer.h"
#include "framework/reference/statistical_compare.h"
#include "instruction_sets.h"
#include "test_scenes.h"

namespace lpvlab {
namespace {

using testing::aov;

constexpr int kSize = 32;
constexpr float kPlaneAlbedo = 0.6f;
constexpr float kCameraHeight = 2.0f;

Scene planeScene() {
  Scene scene;
  scene.source = "test:plane";
  scene.materials = {{.name = "plane", .baseColor = glm::vec3(kPlaneAlbedo)}};
  scene.meshes = {testing::horizontalSquare("plane", 0, 200.0f, 0.0f)};
  return scene;
}

const Camera kCamera = testing::lookingDown({0.0f, kCameraHeight, 0.0f}, glm::radians(60.0f));

// Pixel averages of `radiance` at the point of the plane (y = 0) seen through each position.
Image expectedImage(const std::function<glm::dvec3(const glm::dvec3&)>& radiance) {
  constexpr int kSub = 16;
  Image image(kSize, kSize, 3);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      glm::dvec3 sum(0.0);
      for (int j = 0; j < kSub; ++j)
        for (int i = 0; i < kSub; ++i) {
          const glm::dvec3 d = testing::pixelRay(kCamera, kSize, kSize, x + (i + 0.5) / kSub,
                                                 y + (j + 0.5) / kSub);
          const glm::dvec3 origin(kCamera.position);
          sum += radiance(origin + d * (-origin.y / d.y));
        }
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = float(sum[c] / (kSub * kSub));
    }
  return image;
}

std::vector<NamedImage> render(const Scene& scene, int samples, TracerSettings settings,
                               glm::vec3 sky = glm::vec3(0.0f)) {
  settings.skyRadiance = sky;
  PathTracer tracer(scene, kCamera, kSize, kSize, settings);
  Accumulator acc(kSize, kSize);
  tracer.render(acc, samples, 2);
  return acc.images();
}

// Pixel channels whose variance is infinite are not tested; `tests` is how many are.
void expectDirectMatches(const Image& direct, const Image& variance, const Image& expected,
                         int tests) {
  const ComparisonResult result = compareToExact(direct, variance, expected);
  EXPECT_EQ(result.tests, tests);
  EXPECT_LE(result.rejected, 1) << "max |z| " << result.maxAbsZ << ", threshold "
                                << result.threshold;
  EXPECT_LT(std::abs(result.meanZ), 0.2);
}

void expectDirectMatches(const std::vector<NamedImage>& images, const Image& expected) {
  expectDirectMatches(aov(images, "direct"), aov(images, "direct_variance"), expected,
                      kSize * kSize * 3);
}

void expectNoIndirect(const std::vector<NamedImage>& images) {
  for (const char* name : {"indirect", "indirect1"})
    for (float value : aov(images, name).pixels) ASSERT_EQ(value, 0.0f) << name;
}

double planeBrdf() { return kPlaneAlbedo / M_PI; }

// Every closed form on every instruction set.
class DirectLight : public testing::PerInstructionSet {};

TEST_P(DirectLight, PointLightOverAPlaneIsICosOverRSquared) {
  Scene scene = planeScene();
  const Light light{.name = "point", .type = LightType::Point, .position = {0.3f, 1.0f, -0.4f},
                    .color = {1.0f, 0.5f, 0.25f}, .intensity = 5.0f};
  scene.lights = {light};
  const std::vector<NamedImage> images = render(scene, 64, tracerSettings());
  expectDirectMatches(images, expectedImage([&](const glm::dvec3& p) {
    const glm::dvec3 toLight = glm::dvec3(light.position) - p;
    const double r2 = glm::dot(toLight, toLight);
    const double cosine = toLight.y / std::sqrt(r2);
    return planeBrdf() * glm::dvec3(light.color) * double(light.intensity) * cosine / r2;
  }));
  expectNoIndirect(images);
}

TEST_P(DirectLight, SpotLightFollowsTheSharedConeFalloff) {
  Scene scene = planeScene();
  const Light light{.name = "spot", .type = LightType::Spot, .position = {-0.2f, 1.0f, 0.1f},
                    .direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.0f)),
                    .intensity = 8.0f, .innerConeAngle = glm::radians(15.0f),
                    .outerConeAngle = glm::radians(30.0f)};
  scene.lights = {light};
  const std::vector<NamedImage> images = render(scene, 64, tracerSettings());
  auto falloffAt = [&](const glm::dvec3& p) {
    const glm::dvec3 fromLight = glm::normalize(p - glm::dvec3(light.position));
    return shared::spotFalloff(glm::dot(glm::dvec3(light.direction), fromLight),
                               std::cos(double(light.innerConeAngle)),
                               std::cos(double(light.outerConeAngle)));
  };
  const Image expected = expectedImage([&](const glm::dvec3& p) {
    const glm::dvec3 toLight = glm::dvec3(light.position) - p;
    const double r = glm::length(toLight);
    return glm::dvec3(planeBrdf() * light.intensity * falloffAt(p) * (toLight.y / r) / (r * r));
  });
  // Pixels the cone's outer edge crosses are left out: there the light falls on a sliver of the
  // pixel that few of its samples find, and the sample variance of such a skewed distribution
  // badly underestimates the true one. Inside and outside the cone every pixel is tested.
  const Image coneCoverage = expectedImage(
      [&](const glm::dvec3& p) { return glm::dvec3(falloffAt(p) > 0.0 ? 1.0 : 0.0); });
  Image variance = aov(images, "direct_variance");
  int dark = 0, edge = 0;
  for (std::size_t i = 0; i < variance.pixels.size(); ++i) {
    dark += coneCoverage.pixels[i] == 0.0f;
    if (coneCoverage.pixels[i] > 0.0f && coneCoverage.pixels[i] < 1.0f) {
      variance.pixels[i] = INFINITY;
      ++edge;
    }
  }
  expectDirectMatches(aov(images, "direct"), variance, expected, kSize * kSize * 3 - edge);
  EXPECT_GT(dark, 0);  // the test covers the outside of the cone too
  expectNoIndirect(images);
}

TEST_P(DirectLight, DirectionalLightIsIrradianceTimesCosine) {
  Scene scene = planeScene();
  const glm::vec3 direction = glm::normalize(glm::vec3(0.5f, -1.0f, 0.2f));
  scene.lights = {{.name = "sun", .type = LightType::Directional, .direction = direction,
                   .color = {1.0f, 0.9f, 0.8f}, .intensity = 3.0f}};
  const std::vector<NamedImage> images = render(scene, 4, tracerSettings());
  expectDirectMatches(images, expectedImage([&](const glm::dvec3&) {
    return planeBrdf() * 3.0 * glm::dvec3(1.0, 0.9, 0.8) * double(-direction.y);
  }));
  expectNoIndirect(images);
}

// Irradiance at p (normal +y) from a uniform Lambertian polygon of radiance 1: Lambert's formula,
// E = 1/2 sum over edges of (angle the edge subtends) * (n . unit normal of the edge's plane).
double polygonIrradiance(const glm::dvec3& p, const std::vector<glm::dvec3>& polygon) {
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec3 a = glm::normalize(polygon[i] - p);
    const glm::dvec3 b = glm::normalize(polygon[(i + 1) % polygon.size()] - p);
    const glm::dvec3 edgePlane = glm::normalize(glm::cross(a, b));
    sum += std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0)) * edgePlane.y;
  }
  return 0.5 * std::abs(sum);
}

TEST_P(DirectLight, EmissiveQuadMatchesLambertsPolygonFormula) {
  Scene scene = planeScene();
  const glm::vec3 emission(4.0f, 2.0f, 1.0f);
  // Black, so nothing bounces off it; emits on both sides (the camera sees its back).
  scene.materials.push_back({.name = "lamp", .baseColor = glm::vec3(0.0f), .emission = emission});
  const std::array<glm::vec3, 4> corners = {
      glm::vec3(-0.3f, 1.0f, -0.2f), glm::vec3(-0.3f, 1.0f, 0.3f), glm::vec3(0.2f, 1.0f, 0.3f),
      glm::vec3(0.2f, 1.0f, -0.2f)};
  scene.meshes.push_back(testing::quad("lamp", 1, corners));
  const std::vector<glm::dvec3> polygon(corners.begin(), corners.end());
  const std::vector<NamedImage> images = render(scene, 64, tracerSettings());

  // Pixels the lamp covers wholly or not at all (its corners' rays agree); partly covered ones
  // are skipped, as their expectation needs the lamp's silhouette.
  auto seesLamp = [&](double px, double py) {
    const glm::dvec3 d = testing::pixelRay(kCamera, kSize, kSize, px, py);
    const glm::dvec3 hit = glm::dvec3(kCamera.position) + d * ((1.0 - kCameraHeight) / d.y);
    return hit.x > -0.3 && hit.x < 0.2 && hit.z > -0.2 && hit.z < 0.3;
  };
  const Image expectedPlane = expectedImage([&](const glm::dvec3& p) {
    return planeBrdf() * glm::dvec3(emission) * polygonIrradiance(p, polygon);
  });
  Image estimate(kSize, kSize, 3), variance(kSize, kSize, 3), expected(kSize, kSize, 3);
  const Image& direct = aov(images, "direct");
  const Image& directVariance = aov(images, "direct_variance");
  int lampPixels = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool lamp = seesLamp(x, y);
      const bool whole = seesLamp(x + 1, y) == lamp && seesLamp(x, y + 1) == lamp &&
                         seesLamp(x + 1, y + 1) == lamp;
      for (int c = 0; c < 3; ++c) {
        estimate.at(x, y, c) = direct.at(x, y, c);
        variance.at(x, y, c) = whole ? directVariance.at(x, y, c) : INFINITY;  // untested
        expected.at(x, y, c) = lamp ? emission[c] : expectedPlane.at(x, y, c);
      }
      lampPixels += whole && lamp;
    }
  EXPECT_GT(lampPixels, 4);
  const ComparisonResult result = compareToExact(estimate, variance, expected);
  EXPECT_GT(result.pixels, kSize * kSize * 3 / 4);
  EXPECT_LE(result.rejected, 1) << "max |z| " << result.maxAbsZ << ", threshold "
                                << result.threshold;
  EXPECT_LT(std::abs(result.meanZ), 0.2);
  expectNoIndirect(images);
}

TEST_P(DirectLight, ConstantSkyOverAPlaneReflectsAlbedoTimesSky) {
  const glm::vec3 sky(1.0f, 2.0f, 3.0f);
  const std::vector<NamedImage> images = render(planeScene(), 16, tracerSettings(), sky);
  expectDirectMatches(images, expectedImage([&](const glm::dvec3&) {
    return double(kPlaneAlbedo) * glm::dvec3(sky);
  }));
  expectNoIndirect(images);
}

TEST_P(DirectLight, BackgroundIsZeroInEveryAov) {
  // Looking up from the plane into the sky: no camera ray hits anything.
  Scene scene = planeScene();
  const Camera up{.name = "up", .position = {0, 1, 0}, .forward = {0, 1, 0}, .up = {0, 0, 1}};
  TracerSettings settings = tracerSettings();
  settings.skyRadiance = glm::vec3(1.0f);
  PathTracer tracer(scene, up, 8, 8, settings);
  Accumulator acc(8, 8);
  tracer.render(acc, 4, 1);
  for (const NamedImage& image : acc.images())
    if (image.name.find("_variance") == std::string::npos) {
      for (float value : image.image.pixels) ASSERT_EQ(value, 0.0f) << image.name;
    }
}

LPVLAB_PER_INSTRUCTION_SET(DirectLight);

}  // namespace
}  // namespace lpvlab

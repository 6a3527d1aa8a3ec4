// The reference's glossy BRDF (framework/reference/phong_brdf.h) and the path tracer with
// [reference] brdf = "phong":
//   - reciprocity: f(wi, wo) = f(wo, wi) for random pairs;
//   - the sampler draws what pdf() says: over the hemisphere, integral pdf + P(sample below the
//     horizon) = 1, and the mean of f cos / pdf over samples is the directional albedo by
//     quadrature (a wrong density biases it);
//   - energy: with rho_d + rho_s = 1 the directional albedo is at most 1 at every angle, and 1 at
//     normal incidence;
//   - the white furnace: a plane under a uniform sky of radiance L reflects L a(theta_o) towards
//     every pixel, path traced against the quadrature per pixel (a statistical test);
//   - direct light from a point light in closed form, f(l, v) I cos / d^2, per pixel;
//   - a material without a lobe renders bit for bit as with the Lambertian reference.

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "framework/reference/path_tracer.h"
#include "framework/reference/phong_brdf.h"
#include "framework/reference/statistical_compare.h"
#include "test_scenes.h"

namespace lpvlab {
namespace {

using testing::aov;

// Under the sanitizers (-O0) the quadratures and the path tracing run 10 to 50 times slower: the
// same checks on fewer exponents, angles, samples and pixels (each check as strict per value).
#ifdef LPVLAB_SANITIZED
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

const glm::vec3 kUp(0.0f, 0.0f, 1.0f);

glm::vec3 directionAt(double theta, double phi) {
  return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                   float(std::cos(theta)));
}

// integral over the hemisphere of g(w) dw by the midpoint rule in (cos theta, phi): equal areas.
// Fine in cos theta, where a sharp lobe about the normal varies fastest (4000 rings keep m = 200's
// error below 1e-4).
constexpr int kRings = kSanitized ? 1500 : 4000, kSegments = kSanitized ? 500 : 1000;  // m <= 50 there

template <class F>
double hemisphere(F g, int rings = kRings, int segments = kSegments) {
  double sum = 0.0;
  for (int i = 0; i < rings; ++i) {
    const double mu = (i + 0.5) / rings, theta = std::acos(mu);
    for (int j = 0; j < segments; ++j) sum += g(directionAt(theta, 2.0 * M_PI * (j + 0.5) / segments));
  }
  return sum * 2.0 * M_PI / (double(rings) * segments);
}

// The directional albedo of the red channel, integral f cos, by quadrature.
double albedo(const PhongBrdf& brdf, const glm::vec3& wo, int rings = kRings, int segments = kSegments) {
  return hemisphere([&](const glm::vec3& wi) { return double(brdf.evaluate(kUp, wo, wi).r) * wi.z; },
                    rings, segments);
}

PhongBrdf brdf(float diffuse, float specular, float exponent) {
  return {.diffuse = glm::vec3(diffuse), .specular = glm::vec3(specular), .exponent = exponent};
}

TEST(PhongBrdf, IsReciprocal) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const PhongBrdf b = brdf(0.3f, 0.6f, 12.0f);
  for (int k = 0; k < 1000; ++k) {
    const glm::vec3 wi = directionAt(std::acos(u(random)), 2 * M_PI * u(random));
    const glm::vec3 wo = directionAt(std::acos(u(random)), 2 * M_PI * u(random));
    const glm::vec3 a = b.evaluate(kUp, wo, wi), c = b.evaluate(kUp, wi, wo);
    ASSERT_NEAR(a.r, c.r, 1e-5f * std::max(1.0f, a.r));
  }
}

TEST(PhongBrdf, SamplesTheDensityItReports) {
  const std::vector<float> exponents = kSanitized ? std::vector<float>{1.0f, 20.0f}
                                                  : std::vector<float>{0.0f, 1.0f, 20.0f, 200.0f};
  for (const float exponent : exponents)
    for (const double thetaO : {0.0, 0.7, 1.3}) {
      const PhongBrdf b = brdf(0.4f, 0.5f, exponent);
      const glm::vec3 wo = directionAt(thetaO, 0.3);
      const double integral = hemisphere([&](const glm::vec3& wi) { return double(b.pdf(kUp, wo, wi)); });
      std::mt19937 random(11);
      std::uniform_real_distribution<float> u(0.0f, 1.0f);
      constexpr int kSamples = kSanitized ? 100000 : 400000;
      int below = 0;
      double sum = 0.0, squares = 0.0;
      for (int k = 0; k < kSamples; ++k) {
        glm::vec3 wi;
        double weight = 0.0;
        if (b.sample(kUp, wo, u(random), u(random), u(random), wi))
          weight = double(b.evaluate(kUp, wo, wi).r) * wi.z / b.pdf(kUp, wo, wi);
        else
          ++below;
        sum += weight;
        squares += weight * weight;
      }
      const double mean = sum / kSamples;
      const double error = std::sqrt((squares / kSamples - mean * mean) / kSamples);
      const double expected = albedo(b, wo);
      std::cout << "m " << exponent << ", theta_o " << thetaO << ": integral of pdf " << integral
                << " + below the horizon " << double(below) / kSamples << "; albedo sampled " << mean
                << " +- " << error << ", quadrature " << expected << "\n";
      EXPECT_NEAR(integral + double(below) / kSamples, 1.0, 4e-3);
      EXPECT_LT(std::abs(mean - expected), 4.0 * error + 2e-4);
    }
}

TEST(PhongBrdf, ReflectsNoMoreThanItReceives) {
  const std::vector<float> exponents = kSanitized ? std::vector<float>{1.0f, 50.0f}
                                                  : std::vector<float>{0.0f, 1.0f, 5.0f, 50.0f, 200.0f};
  const std::vector<double> angles = kSanitized ? std::vector<double>{0.0, 0.9, 1.5}
                                                : std::vector<double>{0.0, 0.3, 0.6, 0.9, 1.2, 1.5};
  for (const float exponent : exponents) {
    const PhongBrdf b = brdf(0.25f, 0.75f, exponent);
    double largest = 0.0;
    for (const double thetaO : angles) {
      const double a = albedo(b, directionAt(thetaO, 0.0));
      largest = std::max(largest, a);
      if (thetaO == 0.0) EXPECT_NEAR(a, 1.0, 2e-3) << "m " << exponent;
    }
    EXPECT_LT(largest, 1.0 + 2e-3) << "m " << exponent;
  }
}

// A 20 m square facing up under a sky of radiance 1, seen obliquely: every pixel's direct light is
// L a(theta_o) (the plane sees only sky; nothing else reflects). The expected value is taken at
// the pixel centre's ray, which moves a(theta_o) by far less than the noise over a pixel.
TEST(PhongBrdf, WhiteFurnaceUnderAUniformSky) {
  constexpr int kSize = kSanitized ? 12 : 24, kSamples = 512;
  Scene scene;
  scene.source = "test:glossy plane";
  scene.materials = {{.name = "glossy", .baseColor = glm::vec3(0.3f), .specular = glm::vec3(0.7f),
                      .shininess = 15.0f}};
  scene.meshes = {testing::horizontalSquare("plane", 0, 10.0f, 0.0f)};
  Camera camera;
  camera.name = "oblique";
  camera.position = glm::vec3(0.0f, 1.0f, 2.0f);
  orientCamera(camera, glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(0, 1, 0));
  camera.verticalFov = 0.6f;  // the image's top row still meets the plane, 6 m away
  camera.nearPlane = 0.01f;
  camera.farPlane = 100.0f;
  TracerSettings settings;
  settings.skyRadiance = glm::vec3(1.0f);
  settings.glossy = true;
  const PathTracer tracer(scene, camera, kSize, kSize, settings);
  Accumulator acc(kSize, kSize);
  tracer.render(acc, kSamples, 0);
  const std::vector<NamedImage> images = acc.images();

  const PhongBrdf b = brdf(0.3f, 0.7f, 15.0f);
  Image exact = aov(images, "direct");
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::vec3 wo = -glm::vec3(testing::pixelRay(camera, kSize, kSize, x + 0.5, y + 0.5));
      // The plane's frame turned to the quadrature's (normal +z).
      const glm::vec3 local(wo.x, -wo.z, wo.y);
      const float a = float(albedo(b, local, 400, 400));
      for (int c = 0; c < 3; ++c) exact.pixels[(std::size_t(y) * kSize + x) * 3 + c] = a;
    }
  const ComparisonResult z = compareToExact(aov(images, "direct"), aov(images, "direct_variance"), exact);
  std::cout << z.tests << " values tested, " << z.rejected << " rejected (max |z| " << z.maxAbsZ
            << ", mean z " << z.meanZ << ")\n";
  EXPECT_GT(z.tests, 3 * kSize * kSize - 10);
  EXPECT_EQ(z.rejected, 0);
  EXPECT_LT(std::abs(z.meanZ), kSanitized ? 0.4 : 0.2);
  for (float v : aov(images, "indirect").pixels) ASSERT_EQ(v, 0.0f);
}

// The closed form of direct light: a glossy plane lit by a point light reflects, towards the eye,
// L = f(l, v) I cos(theta_l) / d^2 at each point. The pixel's expectation is that averaged over
// its area (16 x 16 points), against the path tracer's mean with its variance.
TEST(PhongBrdf, DirectLightFromAPointLightIsTheClosedForm) {
  constexpr int kSize = 24, kSamples = 256, kSub = 16;
  const PhongBrdf b{.diffuse = glm::vec3(0.2f, 0.3f, 0.4f), .specular = glm::vec3(0.6f, 0.5f, 0.4f),
                    .exponent = 8.0f};
  Scene scene;
  scene.source = "test:glossy plane, point light";
  scene.materials = {{.name = "glossy", .baseColor = b.diffuse, .specular = b.specular, .shininess = 8.0f}};
  scene.meshes = {testing::horizontalSquare("plane", 0, 10.0f, 0.0f)};
  Light light;
  light.name = "bulb";
  light.type = LightType::Point;
  light.position = glm::vec3(0.3f, 0.8f, -0.6f);
  light.intensity = 2.0f;
  scene.lights.push_back(light);
  Camera camera;
  camera.name = "oblique";
  camera.position = glm::vec3(0.0f, 1.0f, 1.5f);
  orientCamera(camera, glm::vec3(0.0f, 0.0f, -0.5f), glm::vec3(0, 1, 0));
  camera.verticalFov = 0.7f;
  camera.nearPlane = 0.01f;
  camera.farPlane = 100.0f;
  TracerSettings settings;
  settings.glossy = true;
  const PathTracer tracer(scene, camera, kSize, kSize, settings);
  Accumulator acc(kSize, kSize);
  tracer.render(acc, kSamples, 0);
  const std::vector<NamedImage> images = acc.images();

  const glm::vec3 n(0.0f, 1.0f, 0.0f);
  Image exact = aov(images, "direct");
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      glm::dvec3 sum(0.0);
      for (int i = 0; i < kSub; ++i)
        for (int j = 0; j < kSub; ++j) {
          const glm::dvec3 ray = testing::pixelRay(camera, kSize, kSize, x + (i + 0.5) / kSub, y + (j + 0.5) / kSub);
          const double t = -double(camera.position.y) / ray.y;  // the plane y = 0
          const glm::vec3 p = glm::vec3(glm::dvec3(camera.position) + t * ray);
          const glm::vec3 toLight = light.position - p;
          const float d2 = glm::dot(toLight, toLight);
          const glm::vec3 l = toLight / std::sqrt(d2), v = -glm::vec3(ray);
          sum += glm::dvec3(b.evaluate(n, v, l) * (light.intensity * l.y / d2));
        }
      for (int c = 0; c < 3; ++c)
        exact.pixels[(std::size_t(y) * kSize + x) * 3 + c] = float(sum[c] / (kSub * kSub));
    }
  const ComparisonResult z = compareToExact(aov(images, "direct"), aov(images, "direct_variance"), exact);
  std::cout << z.tests << " values tested, " << z.rejected << " rejected (max |z| " << z.maxAbsZ
            << ", mean z " << z.meanZ << ")\n";
  EXPECT_GT(z.tests, 1000);
  EXPECT_EQ(z.rejected, 0);
}

// Without a lobe (specular 0, not metallic) brdf "phong" runs the Lambertian code: the same image.
TEST(PhongBrdf, LambertianMaterialsRenderAsWithTheLambertianReference) {
  const Scene scene = testing::colouredTriangle();
  Camera camera = testing::lookingDown(glm::vec3(0.3f, 0.3f, 2.0f), 0.8f);
  camera.forward = glm::vec3(0, 0, -1);
  camera.up = glm::vec3(0, 1, 0);
  TracerSettings settings;
  settings.skyRadiance = glm::vec3(0.5f);
  std::vector<NamedImage> images[2];
  for (const bool glossy : {false, true}) {
    settings.glossy = glossy;
    const PathTracer tracer(scene, camera, 16, 16, settings);
    Accumulator acc(16, 16);
    tracer.render(acc, 16, 0);
    images[glossy] = acc.images();
  }
  EXPECT_EQ(aov(images[0], "combined").pixels, aov(images[1], "combined").pixels);
}

}  // namespace
}  // namespace lpvlab

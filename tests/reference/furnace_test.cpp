// The furnace: inside a closed surface of uniform albedo rho and uniform emitted radiance Le, the
// radiance is the same everywhere, L = Le + (rho / pi) * (pi L), so L = Le / (1 - rho) whatever
// the shape. By scattering count: uniform radiance R reflects as rho R, so the light with exactly
// k scatterings is rho^k Le, and with the tracer's AOVs (integrator.h):
//   direct    = Le + rho Le                  (k = 0: emission seen; k = 1: emission lit once)
//   indirect1 = rho^2 Le                     (k = 2)
//   indirect  = rho^2 Le / (1 - rho)         (k >= 2)
//   combined  = Le / (1 - rho)
// Every pixel is tested against these with its reported variance; the emission is reached by both
// next-event estimation and BRDF sampling, so this checks their MIS weights sum to one, and the
// roulette (rho up to 0.7 needs many bounces) for bias. rho is the material's base colour times
// the sphere's vertex colours (Mesh::colors), so the tracer must multiply them in at every
// scattering, and into the albedo AOV.

#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "framework/reference/path_tracer.h"
#include "framework/reference/statistical_compare.h"
#include "instruction_sets.h"
#include "test_scenes.h"

namespace lpvlab {
namespace {

using testing::aov;

#ifdef LPVLAB_SANITIZED
// Under the sanitizers (-O0) each of the 10 tests renders its set's furnace again in a process
// of its own (40 s at 32^2): a quarter of the pixels there, the same samples per pixel, so each
// pixel's test is as strict and the image-wide ones still pool 256 pixels.
constexpr int kSize = 16;
#else
constexpr int kSize = 32;
#endif
constexpr int kSamples = 256;

struct FurnaceImages {
  glm::vec3 rho, emission;
  std::vector<NamedImage> images;
};

FurnaceImages renderFurnace(const std::string& isa) {
  const glm::vec3 baseColor(0.6f, 0.625f, 0.875f), vertexColor(0.5f, 0.8f, 0.8f);
  FurnaceImages furnace{.rho = baseColor * vertexColor, .emission = {1.0f, 2.0f, 0.5f}};  // (0.3, 0.5, 0.7)
  Scene scene;
  scene.source = "test:furnace";
  scene.materials = {{.name = "furnace", .baseColor = baseColor, .emission = furnace.emission}};
  scene.meshes = {testing::inwardSphere(0, 1.0f, 24, 48)};
  scene.meshes[0].colors.assign(scene.meshes[0].positions.size(), vertexColor);
  const Camera camera{.name = "centre", .position = glm::vec3(0.0f), .forward = {0, 0, -1},
                      .up = {0, 1, 0}, .verticalFov = float(M_PI / 2), .nearPlane = 0.01f,
                      .farPlane = 10.0f};
  TracerSettings settings;
  settings.engine.isa = isa;
  settings.maxBounces = 200;  // 0.7^200: the cap removes nothing measurable
  PathTracer tracer(scene, camera, kSize, kSize, settings);
  Accumulator acc(kSize, kSize);
  tracer.render(acc, kSamples, 2);
  furnace.images = acc.images();
  return furnace;
}

// Rendered once per instruction set, for all the tests of that set.
const FurnaceImages& furnace(const std::string& isa) {
  static std::map<std::string, FurnaceImages> rendered;
  auto found = rendered.find(isa);
  if (found == rendered.end()) found = rendered.emplace(isa, renderFurnace(isa)).first;
  return found->second;
}

Image uniform(const glm::vec3& value) {
  Image image(kSize, kSize, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = value[int(i % 3)];
  return image;
}

// Per-pixel z-tests (Sidak, family-wise alpha 0.01) and a test of the image-wide mean per channel,
// whose standard error sqrt(sum of the pixels' variances) / pixels comes from the same variances.
void expectMatches(const FurnaceImages& furnace, const std::string& name, const glm::vec3& expected) {
  const Image& estimate = aov(furnace.images, name);
  const Image& variance = aov(furnace.images, name + "_variance");
  const ComparisonResult result = compareToExact(estimate, variance, uniform(expected));
  EXPECT_EQ(result.tests, kSize * kSize * 3) << name;
  EXPECT_LE(result.rejected, 1) << name << ": max |z| " << result.maxAbsZ << " over threshold "
                                << result.threshold;
  // Skewed per-sample values bias z slightly (sample mean and sample variance correlate), so the
  // mean z is only required to be a small fraction of one standard error.
  EXPECT_LT(std::abs(result.meanZ), 0.2) << name;

  const double pooledThreshold = twoSidedCriticalZ(0.001 / 3);
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0, varianceSum = 0.0;
    for (int p = 0; p < kSize * kSize; ++p) {
      sum += estimate.pixels[p * 3 + c];
      varianceSum += variance.pixels[p * 3 + c];
    }
    const double pixels = kSize * kSize;
    const double z = (sum / pixels - expected[c]) / (std::sqrt(varianceSum) / pixels);
    EXPECT_LT(std::abs(z), pooledThreshold)
        << name << " channel " << c << ": image mean " << sum / pixels << ", expected "
        << expected[c];
  }
}

class Furnace : public testing::PerInstructionSet {};

TEST_P(Furnace, CombinedIsEmissionOverOneMinusAlbedo) {
  const FurnaceImages& f = furnace(isa());
  expectMatches(f, "combined", f.emission / (1.0f - f.rho));
}

TEST_P(Furnace, DirectIsEmissionPlusOneScattering) {
  const FurnaceImages& f = furnace(isa());
  expectMatches(f, "direct", f.emission * (1.0f + f.rho));
}

TEST_P(Furnace, IndirectIsEverythingFromTwoScatteringsOn) {
  const FurnaceImages& f = furnace(isa());
  expectMatches(f, "indirect", f.emission * f.rho * f.rho / (1.0f - f.rho));
}

TEST_P(Furnace, Indirect1IsExactlyTwoScatterings) {
  const FurnaceImages& f = furnace(isa());
  expectMatches(f, "indirect1", f.emission * f.rho * f.rho);
}

TEST_P(Furnace, FirstHitAovsSeeTheSphereEverywhere) {
  const FurnaceImages& f = furnace(isa());
  const Image& albedo = aov(f.images, "albedo");
  const Image& depth = aov(f.images, "depth");
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(albedo.at(x, y, c), f.rho[c], 1e-6);
      ASSERT_GT(depth.at(x, y, 0), 0.5f);  // the sphere is 1 m away, the corners further out
      ASSERT_LE(depth.at(x, y, 0), 1.0f);
    }
}

LPVLAB_PER_INSTRUCTION_SET(Furnace);

}  // namespace
}  // namespace lpvlab

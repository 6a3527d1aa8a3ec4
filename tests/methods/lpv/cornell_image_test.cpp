// The built-in Cornell box rendered end to end (128x128, default grid and iterations), checked
// through its AOVs: the G-buffer against a ray cast of the scene's triangles, and the light
// against what the scene implies (the spot can't reach the ceiling, the red wall tints the floor
// next to it). Pixels are picked by their AOVs (normal, depth -> world position), never by
// hard-coded positions.

#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <toml++/toml.h>

#include "framework/core/parameters.h"
#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "framework/pipeline/raster_passes.h"
#include "framework/pipeline/scene_gpu.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

struct Render {
  int width = 0, height = 0;
  Camera camera;
  Scene scene;
  std::map<std::string, Image> aovs;
  const Image& operator[](const std::string& name) const { return aovs.at(name); }
};

// One frame of the default experiment at 128x128, rendered once for all tests here.
const Render& cornellRender() {
  static const Render render = [] {
    test::glTestContext();
    Experiment e = loadExperiment(
        "", {"output.width=128", "output.height=128", "timing.warmup=0", "timing.repeats=1"});
    Render r;
    r.width = e.settings.width;
    r.height = e.settings.height;
    r.camera = e.camera;
    r.scene = e.scene;
    ShaderCompiler shaders;
    Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
    pipeline.renderFrame();
    for (NamedImage& aov : pipeline.readOutputs()) r.aovs[aov.name] = std::move(aov.image);
    return r;
  }();
  return render;
}

glm::dvec3 rgb(const Image& image, int x, int y) {
  return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)};
}

void forEachPixel(const Render& r, const std::function<void(int, int)>& f) {
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) f(x, y);
}

bool covered(const Render& r, int x, int y) { return r["depth"].at(x, y, 0) > 0.0f; }

// World position of a covered pixel from its view depth and the camera.
glm::dvec3 worldPosition(const Render& r, int x, int y) {
  return glm::dvec3(r.camera.position) +
         double(r["depth"].at(x, y, 0)) * test::cameraRay(r.camera, r.width, r.height, x, y);
}

TEST(CornellImage, AovsAreWellFormed) {
  const Render& r = cornellRender();
  for (const char* name : {"direct", "indirect", "combined", "albedo", "normal", "depth"}) {
    ASSERT_TRUE(r.aovs.count(name)) << name;
    const Image& image = r[name];
    ASSERT_EQ(image.width, r.width) << name;
    ASSERT_EQ(image.height, r.height) << name;
    ASSERT_EQ(image.channels, std::string(name) == "depth" ? 1 : 3) << name;
    for (float v : image.pixels) ASSERT_TRUE(std::isfinite(v)) << name;
  }
  int coveredCount = 0, uncoveredCount = 0;
  forEachPixel(r, [&](int x, int y) {
    const glm::dvec3 albedo = rgb(r["albedo"], x, y), normal = rgb(r["normal"], x, y);
    const glm::dvec3 direct = rgb(r["direct"], x, y), indirect = rgb(r["indirect"], x, y);
    const glm::dvec3 combined = rgb(r["combined"], x, y);
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(albedo[c], 0.0);
      EXPECT_LE(albedo[c], 1.0);
      EXPECT_GE(direct[c], 0.0);
      EXPECT_GE(indirect[c], 0.0);
      EXPECT_NEAR(combined[c], direct[c] + indirect[c], 1e-6 * (1.0 + combined[c]));
    }
    if (covered(r, x, y)) {
      ++coveredCount;
      EXPECT_NEAR(glm::length(normal), 1.0, 1e-4) << "pixel " << x << "," << y;
    } else {
      ++uncoveredCount;
      EXPECT_EQ(r["depth"].at(x, y, 0), 0.0f) << "depth is 0 exactly where nothing was hit";
      EXPECT_EQ(normal, glm::dvec3(0.0)) << "pixel " << x << "," << y;
      EXPECT_EQ(albedo, glm::dvec3(0.0)) << "pixel " << x << "," << y;
      EXPECT_EQ(combined, glm::dvec3(0.0)) << "pixel " << x << "," << y;
    }
  });
  // The box's open front fills most of the view; the rows above and below it see nothing.
  EXPECT_GT(coveredCount, r.width * r.height * 3 / 4);
  EXPECT_GT(uncoveredCount, 0);
}

// The G-buffer against the ground truth: a ray through each pixel centre against the triangles.
TEST(CornellImage, GBufferMatchesARayCastOfTheScene) {
  const Render& r = cornellRender();
  const test::SceneRaycaster raycaster(r.scene);
  int mismatched = 0, compared = 0;
  forEachPixel(r, [&](int x, int y) {
    const glm::dvec3 ray = test::cameraRay(r.camera, r.width, r.height, x, y);
    const auto hit = raycaster.cast(glm::dvec3(r.camera.position), ray);
    ++compared;
    const bool gpuCovered = covered(r, x, y);
    if (bool(hit) != gpuCovered) {
      ++mismatched;  // a ray grazing a triangle edge or a crack between the measured walls
      return;
    }
    if (!hit) return;
    const glm::dvec3 facing = glm::dot(hit->normal, ray) < 0.0 ? hit->normal : -hit->normal;
    const bool same = std::abs(r["depth"].at(x, y, 0) - hit->t) <= 1e-3 * hit->t &&
                      glm::length(rgb(r["normal"], x, y) - facing) <= 1e-3 &&
                      glm::length(rgb(r["albedo"], x, y) -
                                  glm::dvec3(raycaster.material(*hit).baseColor)) <= 1e-6;
    if (!same) ++mismatched;  // an edge between two surfaces
  });
  std::cout << "[ cornell ] G-buffer vs ray cast: " << mismatched << " of " << compared
            << " pixels differ\n";
  EXPECT_LE(mismatched, compared / 500);
}

TEST(CornellImage, CeilingGetsOnlyIndirectLight) {
  const Render& r = cornellRender();
  int ceiling = 0;
  glm::dvec3 indirectSum(0.0);
  forEachPixel(r, [&](int x, int y) {
    if (!covered(r, x, y) || r["normal"].at(x, y, 1) >= -0.9f) return;  // faces down: the ceiling
    ++ceiling;
    EXPECT_NEAR(worldPosition(r, x, y).y, 0.5488, 0.005) << "pixel " << x << "," << y;
    EXPECT_EQ(rgb(r["direct"], x, y), glm::dvec3(0.0))
        << "the spot's cone stays below the horizontal; pixel " << x << "," << y;
    indirectSum += rgb(r["indirect"], x, y);
  });
  ASSERT_GT(ceiling, 100) << "the ceiling is in view";
  const glm::dvec3 mean = indirectSum / double(ceiling);
  std::cout << "[ cornell ] " << ceiling << " ceiling pixels, mean indirect (" << mean.x << ", "
            << mean.y << ", " << mean.z << ")\n";
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(std::isfinite(mean[c]));
    EXPECT_GT(mean[c], 0.0) << "channel " << c;
  }
}

TEST(CornellImage, FloorNextToEachWallTakesItsColour) {
  const Render& r = cornellRender();
  // The floor spans x in [0, 0.5528] m: the red wall is at its high end (left in the image,
  // the camera looks along +z with +x to its left), the green wall at x = 0.
  const double floorWidth = 0.5528;
  glm::dvec3 nearRed(0.0), nearGreen(0.0);
  int redCount = 0, greenCount = 0, upward = 0;
  int leftColumnsNearRed = 0;
  forEachPixel(r, [&](int x, int y) {
    if (!covered(r, x, y) || r["normal"].at(x, y, 1) <= 0.9f) return;  // faces up
    ++upward;
    const glm::dvec3 p = worldPosition(r, x, y);
    // Up-facing surfaces are the floor (y = 0) and the block tops (0.165 and 0.33 m).
    const double distance = std::min({std::abs(p.y), std::abs(p.y - 0.165), std::abs(p.y - 0.33)});
    EXPECT_LT(distance, 0.005) << "pixel " << x << "," << y << " at height " << p.y;
    if (std::abs(p.y) > 0.005) return;  // a block top
    if (p.x > 0.75 * floorWidth) {
      ++redCount, nearRed += rgb(r["indirect"], x, y);
      leftColumnsNearRed += x < r.width / 2;
    }
    if (p.x < 0.25 * floorWidth) ++greenCount, nearGreen += rgb(r["indirect"], x, y);
  });
  ASSERT_GT(redCount, 50);
  ASSERT_GT(greenCount, 50);
  EXPECT_EQ(leftColumnsNearRed, redCount) << "the red wall's side is the image's left half";
  const double redRG = nearRed.x / nearRed.y, greenRG = nearGreen.x / nearGreen.y;
  const double redGR = nearRed.y / nearRed.x, greenGR = nearGreen.y / nearGreen.x;
  std::cout << "[ cornell ] floor indirect R/G next to the red wall " << redRG
            << ", next to the green wall " << greenRG << "; G/R " << redGR << " and " << greenGR
            << " (" << redCount << " and " << greenCount << " pixels)\n";
  EXPECT_GT(redRG, greenRG);
  EXPECT_GT(greenGR, redGR);
}

// The rendering strategy alone, on the box's G-buffer, reading a hand-made grid whose light
// has a closed-form irradiance. Cell c holds, per channel,
//   a(x) * cosLobe(+y) + (gamma, 0, 0, 0),   a(x) = alpha + beta * x (x: the cell centre's world x)
// (light travelling up, brighter to the left, plus an isotropic part). Trilinear interpolation of
// a field linear in position is exact between cell centres, so a surface at p with normal n
// reflects exactly
//   albedo / pi / cellSize^2 * max(0, a(p.x) <cosLobe(+y), cosLobe(-n)> + gamma z0),
// with <cosLobe(u), cosLobe(v)> = z0^2 + z1^2 u.v = pi/4 + pi/3 u.v and z0 = sqrt(pi)/2:
// surfaces facing down (the ceiling) get the most, those facing up (the floor) only gamma's part.
TEST(CornellImage, TrilinearRenderingReproducesAnAnalyticField) {
  test::glTestContext();
  Experiment e = loadExperiment("", {"output.width=128", "output.height=128"});
  const int w = e.settings.width, h = e.settings.height;
  const GridGeometry& geometry = e.settings.grid;
  ShaderCompiler shaders;
  const SceneGpu scene(e.scene);
  GBufferPass gbufferPass(shaders, w, h);
  gbufferPass.render(scene, e.camera);

  toml::table table;
  Params params(table, "rendering test", "rendering");
  std::unique_ptr<RenderingStrategy> rendering =
      Registry<RenderingStrategy>::instance().create(params, "trilinear");
  params.finish();
  Requirements requirements;
  rendering->prepare({.shaders = shaders, .grid = geometry, .requirements = requirements});
  LightGrid grid(geometry, requirements.shOrder);

  const double alpha[3] = {1.0e-4, 0.7e-4, 0.4e-4};  // W/sr, per channel
  const double beta[3] = {2.0e-4, 1.0e-4, 0.5e-4};   // W/sr per metre
  const double gamma[3] = {0.3e-4, 0.2e-4, 0.1e-4};  // W/sr
  const int cellCount = geometry.cellCount();
  std::vector<float> coefficients(std::size_t(3) * 4 * cellCount);
  for (int z = 0; z < geometry.resolution.z; ++z)
    for (int y = 0; y < geometry.resolution.y; ++y)
      for (int x = 0; x < geometry.resolution.x; ++x) {
        const int cell = shared::cellIndex({x, y, z}, geometry.resolution);
        const double centreX = geometry.origin.x + (x + 0.5) * geometry.cellSize;
        for (int channel = 0; channel < 3; ++channel) {
          const glm::dvec4 c = (alpha[channel] + beta[channel] * centreX) *
                                   shared::shCosineLobe({0, 1, 0}) +
                               glm::dvec4(gamma[channel], 0, 0, 0);
          for (int k = 0; k < 4; ++k)
            coefficients[shared::coefficientIndex(channel, k, 4, cell, cellCount)] = float(c[k]);
        }
      }
  grid.accumulated.upload(coefficients.data(), coefficients.size() * sizeof(float));

  DualImage indirect(w, h, "indirect (test)");
  const LightMaps noLightMaps;
  Frame frame{.gbuffer = gbufferPass.gbuffer(), .lightMaps = noLightMaps, .lightGrid = grid, .indirect = indirect};
  rendering->render(frame);
  std::vector<float> out(std::size_t(w) * h * 4), position(out.size()), normal(out.size()),
      albedo(out.size());
  const GBuffer& g = gbufferPass.gbuffer();
  auto read = [&](const gl::Texture& texture, std::vector<float>& into) {
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(into.size() * sizeof(float)),
                      into.data());
  };
  read(indirect.texture(), out);
  read(g.position, position);
  read(g.normal, normal);
  read(g.albedo, albedo);
  checkGl("rendering test");

  const double cs2 = double(geometry.cellSize) * geometry.cellSize;
  const double z0 = 0.5 * std::sqrt(M_PI);
  double largest = 0.0, worst = 0.0;
  int coveredPixels = 0, ceilingPixels = 0, floorPixels = 0;
  double ceilingMean = 0.0, floorMean = 0.0;
  for (std::size_t i = 0; i < std::size_t(w) * h; ++i) {
    if (position[4 * i + 3] == 0.0f) {
      for (int c = 0; c < 3; ++c) EXPECT_EQ(out[4 * i + c], 0.0f);
      continue;
    }
    ++coveredPixels;
    const glm::dvec3 p(position[4 * i], position[4 * i + 1], position[4 * i + 2]);
    const glm::dvec3 n(normal[4 * i], normal[4 * i + 1], normal[4 * i + 2]);
    for (int c = 0; c < 3; ++c) {
      const double a = alpha[c] + beta[c] * p.x;
      const double e = std::max(0.0, a * (M_PI / 4.0 - M_PI / 3.0 * n.y) + gamma[c] * z0);
      const double expected = albedo[4 * i + c] / M_PI * e / cs2;
      largest = std::max(largest, expected);
      worst = std::max(worst, std::abs(out[4 * i + c] - expected));
    }
    if (n.y < -0.9) ++ceilingPixels, ceilingMean += out[4 * i];
    if (n.y > 0.9) ++floorPixels, floorMean += out[4 * i];
  }
  ASSERT_GT(coveredPixels, w * h / 2);
  ASSERT_GT(ceilingPixels, 0);
  ASSERT_GT(floorPixels, 0);
  EXPECT_LE(worst, 1e-4 * largest) << "largest difference from the closed form";
  // The field's light goes up: what faces down is lit far more than what faces up.
  EXPECT_GT(ceilingMean / ceilingPixels, 3.0 * floorMean / floorPixels);
}

}  // namespace
}  // namespace lpvlab

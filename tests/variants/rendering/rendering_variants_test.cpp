// The rendering kernel shaders/rendering/trilinear.comp with its options (strategies "trilinear"
// with leak_damping, and "glossy") on hand-made G-buffers (one row of pixels with chosen
// positions, normals and albedos) and hand-made grids, against:
//   - the shared mathematics checked on its own: the Phong lobe's SH coefficients by numerical
//     integration, the trilinear weights' slope by finite differences of the interpolant;
//   - closed forms: a grid whose intensity is the same in every cell is never damped; a step in
//     the light across a thin wall is damped by exp(-k (b - a) / E) exactly where it grows
//     towards the surface; glossy on a constant isotropic intensity I adds specular_albedo I / s^2
//     whatever the direction, exponent, step or SH order;
//   - the double-precision C++ of the same shared GLSL, sampled and marched the way the kernel
//     does, on random grids;
//   - finite, non-negative output at extreme parameters.

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "error_support.h"
#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"
#include "framework/scene/scene.h"
#include "pipeline_test_support.h"
#include "rendering_rig.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/rendering/trilinear_weights.glsl"
#include "shaders/rendering/leak_damping.glsl"
#include "shaders/rendering/phong_lobe.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using glm::dvec3;
using test::HandGrid;
using test::SurfacePixel;
using test::renderPixels;

// --- The kernel in double precision, from the same shared functions ----------------------------

struct LobeSample {
  dvec3 value{0.0}, slope{0.0};
};

LobeSample sampleLobe(const HandGrid& grid, dvec3 g, const std::vector<double>& lobe, dvec3 d) {
  const dvec3 centred = g - 0.5;
  const dvec3 base = glm::floor(centred);
  const dvec3 f = centred - base;
  LobeSample s;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    const glm::ivec3 c = glm::clamp(glm::ivec3(base) + o, glm::ivec3(0), grid.geometry.resolution - 1);
    dvec3 v(0.0);
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < grid.coefficients(); ++k) v[channel] += grid.at(c, channel, k) * lobe[k];
    s.value += shared::trilinearWeight(o, f) * v;
    s.slope += shared::trilinearWeightSlope(o, f, d) * v;
  }
  return s;
}

struct Options {
  double normalOffset = 0.0, leakDamping = 0.0;
  double specularAlbedo = 0.0, exponent = 32.0, step = 1.0;
  int samples = 0;
};

dvec3 cpuRender(const HandGrid& grid, const SurfacePixel& px, const Options& o, dvec3 camera) {
  const double s = grid.geometry.cellSize;
  const dvec3 origin(grid.geometry.origin);
  const dvec3 p = px.position + px.normal * (o.normalOffset * s);
  const int n = grid.coefficients();
  std::vector<double> lobe(n);
  for (int k = 0; k < n; ++k) lobe[k] = shared::shCosineLobeAt(k, -px.normal);
  const LobeSample diffuse = sampleLobe(grid, shared::gridFromWorld(p, origin, s), lobe, px.normal);
  dvec3 e = diffuse.value;
  if (o.leakDamping > 0.0)
    e *= shared::leakDampingFactor(e.x + e.y + e.z, diffuse.slope.x + diffuse.slope.y + diffuse.slope.z,
                                   o.leakDamping);
  dvec3 radiance = px.albedo / M_PI * glm::max(e, dvec3(0.0)) / (s * s);
  if (o.specularAlbedo > 0.0) {
    const dvec3 v = glm::normalize(camera - px.position);
    const dvec3 r = glm::reflect(-v, px.normal);
    for (int k = 0; k < n; ++k) lobe[k] = shared::shPhongLobeAt(k, -r, o.exponent);
    const dvec3 start = shared::gridFromWorld(p, origin, s);
    dvec3 sum(0.0);
    int inside = 0;
    for (int j = 0; j < o.samples; ++j) {
      const dvec3 g = start + r * ((j + 0.5) * o.step);
      if (j > 0 && (glm::any(glm::lessThan(g, dvec3(0.0))) ||
                    glm::any(glm::greaterThan(g, dvec3(grid.geometry.resolution)))))
        break;
      sum += sampleLobe(grid, g, lobe, r).value;
      ++inside;
    }
    if (inside > 0) radiance += o.specularAlbedo * glm::max(sum / double(inside), dvec3(0.0)) / (s * s);
  }
  return radiance;
}

// A grid of 8 x 4 x 4 cells of 0.25 m away from the world origin, so that the world-to-grid
// mapping is exercised.
GridGeometry testGeometry(glm::ivec3 resolution = {8, 4, 4}) {
  return GridGeometry{glm::vec3(-1.0f, 0.5f, 2.0f), 0.25f, resolution};
}

dvec3 worldAt(const GridGeometry& g, dvec3 gridPosition) {
  return dvec3(g.origin) + gridPosition * double(g.cellSize);
}

const dvec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

double largestComponent(const std::vector<dvec3>& values) {
  double m = 0.0;
  for (const dvec3& v : values) m = std::max({m, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  return m;
}

// --- The shared mathematics ----------------------------------------------------------------------

// <c, P> for P the normalised Phong lobe: its coefficients against a quadrature of
// (m + 1) / (2 pi) max(0, w . a)^m Y_i(w) in coordinates about a (t = cos theta, phi).
TEST(RenderingMath, PhongLobeMatchesNumericalIntegration) {
  const dvec3 axes[3] = {glm::normalize(dvec3(0.3, -0.5, 0.8)), {0, 0, 1},
                         glm::normalize(dvec3(-1, 2, 0.5))};
  for (double m : {1.0, 4.0, 32.0, 300.0})
    for (const dvec3& a : axes) {
      const dvec3 u = glm::normalize(glm::cross(a, std::abs(a.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
      const dvec3 v = glm::cross(a, u);
      const int nt = 20000, nphi = 16;  // phi: exact for bands <= 3 with 16 equal steps
      std::vector<double> integral(16, 0.0);
      for (int it = 0; it < nt; ++it) {
        const double t = (it + 0.5) / nt;
        const double weight = (m + 1.0) / (2.0 * M_PI) * std::pow(t, m) * (1.0 / nt) * (2.0 * M_PI / nphi);
        for (int ip = 0; ip < nphi; ++ip) {
          const double phi = 2.0 * M_PI * (ip + 0.5) / nphi;
          const dvec3 w = t * a + std::sqrt(1.0 - t * t) * (std::cos(phi) * u + std::sin(phi) * v);
          for (int i = 0; i < 16; ++i) integral[i] += weight * shared::shBasisAt(i, w);
        }
      }
      for (int i = 0; i < 16; ++i)
        EXPECT_NEAR(shared::shPhongLobeAt(i, a, m), integral[i], 2e-4)
            << "coefficient " << i << ", exponent " << m;
    }
  // m = 1 is the clamped cosine divided by pi.
  for (int i = 0; i < 16; ++i)
    EXPECT_NEAR(shared::shPhongLobeAt(i, axes[0], 1.0), shared::shCosineLobeAt(i, axes[0]) / M_PI, 1e-12);
}

TEST(RenderingMath, TrilinearSlopeIsTheInterpolantsDerivative) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    double values[8];
    for (double& v : values) v = uniform(rng) * 2.0 - 1.0;
    const dvec3 f(0.05 + 0.9 * uniform(rng), 0.05 + 0.9 * uniform(rng), 0.05 + 0.9 * uniform(rng));
    const dvec3 d = glm::normalize(dvec3(uniform(rng) - 0.5, uniform(rng) - 0.5, uniform(rng) - 0.5));
    auto interpolant = [&](dvec3 at) {
      double sum = 0.0, weights = 0.0;
      for (int corner = 0; corner < 8; ++corner) {
        const glm::ivec3 o(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        sum += shared::trilinearWeight(o, at) * values[corner];
        weights += shared::trilinearWeight(o, at);
      }
      EXPECT_NEAR(weights, 1.0, 1e-12);
      return sum;
    };
    double slope = 0.0;
    for (int corner = 0; corner < 8; ++corner)
      slope += shared::trilinearWeightSlope({corner & 1, (corner >> 1) & 1, (corner >> 2) & 1}, f, d) *
               values[corner];
    const double h = 1e-5;
    EXPECT_NEAR(slope, (interpolant(f + h * d) - interpolant(f - h * d)) / (2.0 * h), 1e-7);
  }
}

// --- The kernel against closed forms -------------------------------------------------------------

// Pixels at random places inside the grid (away from its edge), facing every axis and random
// directions, with random albedo.
std::vector<SurfacePixel> randomPixels(const GridGeometry& g, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<SurfacePixel> pixels;
  for (int i = 0; i < count; ++i) {
    const dvec3 gp = dvec3(0.6) + dvec3(uniform(rng), uniform(rng), uniform(rng)) *
                                       (dvec3(g.resolution) - 1.2);
    const dvec3 n = i < 6 ? kAxes[i]
                          : glm::normalize(dvec3(uniform(rng) - 0.5, uniform(rng) - 0.5, uniform(rng) - 0.5));
    pixels.push_back({worldAt(g, gp), n, dvec3(0.2 + 0.8 * uniform(rng), 0.5 * uniform(rng), uniform(rng))});
  }
  return pixels;
}

// The same intensity in every cell (anisotropic: a lobe plus an isotropic part): the irradiance
// has no slope in any direction, so damping, however strong, changes nothing.
TEST(RenderingVariants, LeakDampingLeavesAUniformFieldAlone) {
  const GridGeometry g = testGeometry();
  HandGrid grid(g, 1);
  const glm::dvec4 lobe = shared::shCosineLobe(glm::normalize(dvec3(0.2, 1.0, -0.4)));
  grid.fill([&](glm::ivec3, int ch, std::vector<double>& c) {
    const glm::dvec4 v = (1.0 + ch) * 1e-3 * lobe + glm::dvec4(0.5e-3, 0, 0, 0);
    c = {v.x, v.y, v.z, v.w};
  });
  const std::vector<SurfacePixel> pixels = randomPixels(g, 40, 1);
  toml::table damped;
  damped.insert("leak_damping", 16.0);
  const std::vector<dvec3> plain = renderPixels("trilinear", {}, grid, pixels, {0, 0, 0});
  const std::vector<dvec3> out = renderPixels("trilinear", damped, grid, pixels, {0, 0, 0});
  const double s2 = double(g.cellSize) * g.cellSize;
  const double largest = largestComponent(plain);
  ASSERT_GT(largest, 0.0);
  for (std::size_t i = 0; i < pixels.size(); ++i)
    for (int ch = 0; ch < 3; ++ch) {
      const glm::dvec4 c = (1.0 + ch) * 1e-3 * lobe + glm::dvec4(0.5e-3, 0, 0, 0);
      const double e = glm::dot(c, shared::shCosineLobe(-pixels[i].normal));
      const double expected = pixels[i].albedo[ch] / M_PI * std::max(0.0, e) / s2;
      EXPECT_NEAR(out[i][ch], expected, 1e-5 * largest) << "pixel " << i;
      EXPECT_NEAR(out[i][ch], plain[i][ch], 1e-5 * largest) << "pixel " << i;
    }
}

// A thin wall between the cell centres x = 3.5 and 4.5: the cells behind it (x >= 4) hold light
// b L, those in front a L with a < b (what leaked through), L = cosLobe(+x) + an isotropic part:
// light travelling along +x, into surfaces whose normal is -x. A surface in front of the wall at
// grid x = 3.5 + f, normal -x, reads E = ((1 - f) a + f b) K with K = <L, cosLobe(+x)>, whose
// slope per cell along the normal is -(b - a) K: growth towards the surface g = (b - a) / ((1 -
// f) a + f b), damping exp(-k g). Surfaces facing +x see the light grow away from them (no
// damping), and those facing y or z see no slope at all.
TEST(RenderingVariants, LeakDampingLowersLightGrowingThroughAWallAsPredicted) {
  const GridGeometry g = testGeometry();
  const double a = 0.2e-3, b = 1.0e-3, k = 1.5;
  const glm::dvec4 light = shared::shCosineLobe({1, 0, 0}) + glm::dvec4(0.3, 0, 0, 0);
  const double tint[3] = {1.0, 0.6, 0.3};
  HandGrid grid(g, 1);
  grid.fill([&](glm::ivec3 cell, int ch, std::vector<double>& c) {
    const glm::dvec4 v = (cell.x >= 4 ? b : a) * tint[ch] * light;
    c = {v.x, v.y, v.z, v.w};
  });
  std::vector<SurfacePixel> pixels;
  std::vector<double> fractions;
  for (double f : {0.05, 0.3, 0.5, 0.8, 0.97})
    for (const dvec3& n : kAxes) {
      pixels.push_back({worldAt(g, {3.5 + f, 1.7, 2.2}), n, {0.8, 0.7, 0.9}});
      fractions.push_back(f);
    }
  toml::table damped;
  damped.insert("leak_damping", k);
  const std::vector<dvec3> out = renderPixels("trilinear", damped, grid, pixels, {0, 0, 0});
  const double s2 = double(g.cellSize) * g.cellSize;
  const double largest = largestComponent(out);
  ASSERT_GT(largest, 0.0);
  int dampedPixels = 0;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const dvec3 n = pixels[i].normal;
    const double f = fractions[i];
    const double level = (1.0 - f) * a + f * b;
    const double damping = n.x < -0.5 ? std::exp(-k * (b - a) / level) : 1.0;
    dampedPixels += damping < 1.0;
    for (int ch = 0; ch < 3; ++ch) {
      const double e = level * tint[ch] * glm::dot(light, shared::shCosineLobe(-n));
      const double expected = pixels[i].albedo[ch] / M_PI * std::max(0.0, e * damping) / s2;
      EXPECT_NEAR(out[i][ch], expected, 1e-5 * largest)
          << "pixel " << i << " normal (" << n.x << ", " << n.y << ", " << n.z << "), f " << f;
    }
  }
  EXPECT_EQ(dampedPixels, 5);
}

// Constant isotropic intensity I per channel: every lobe-weighted read is I, so glossy adds
// specular_albedo I / s^2 to the Lambertian albedo I / s^2 (E = pi I), for any view, exponent,
// step, march length and SH order.
TEST(RenderingVariants, GlossyOnAConstantIsotropicGridAddsSpecularAlbedoTimesRadiance) {
  const GridGeometry g = testGeometry();
  const double intensity[3] = {2e-3, 1e-3, 0.5e-3};  // W/sr
  const double specular = 0.35;
  const std::vector<SurfacePixel> pixels = randomPixels(g, 24, 2);
  const dvec3 cameras[2] = {worldAt(g, {4.0, 2.0, -6.0}), worldAt(g, {-3.0, 9.0, 2.0})};
  const double s2 = double(g.cellSize) * g.cellSize;
  for (int order = 1; order <= 3; ++order) {
    HandGrid grid(g, order);
    grid.fill([&](glm::ivec3, int ch, std::vector<double>& c) {
      c[0] = intensity[ch] * 2.0 * std::sqrt(M_PI);  // I integrated against Y00
    });
    for (double exponent : {1.0, 40.0, 10000.0})
      for (double step : {0.3, 1.0, 2.5}) {
        toml::table table{{"specular_albedo", specular}, {"exponent", exponent},
                          {"step", step}, {"max_distance", 6.0}};
        const dvec3& camera = cameras[order % 2];
        const std::vector<dvec3> out = renderPixels("glossy", table, grid, pixels, glm::vec3(camera));
        for (std::size_t i = 0; i < pixels.size(); ++i)
          for (int ch = 0; ch < 3; ++ch) {
            const double expected = (pixels[i].albedo[ch] + specular) * intensity[ch] / s2;
            EXPECT_NEAR(out[i][ch], expected, 2e-5 * expected)
                << "order " << order << ", exponent " << exponent << ", step " << step << ", pixel " << i;
          }
      }
  }
}

// Random grids (light of every direction, varying from cell to cell): the kernel is the
// double-precision C++ above, which calls the same shared functions, within float rounding;
// and glossy with specular_albedo = 0 is trilinear, bit for bit.
TEST(RenderingVariants, KernelMatchesDoublePrecisionReferenceOnRandomGrids) {
  const GridGeometry g = testGeometry({7, 5, 6});
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int order = 1; order <= 3; ++order) {
    HandGrid grid(g, order);
    // c0 dominant, so the irradiance read stays well away from 0 and the damping factor, which
    // divides by it, is well conditioned.
    grid.fill([&](glm::ivec3, int, std::vector<double>& c) {
      c[0] = 1e-3 * (1.5 + 0.5 * uniform(rng));
      for (std::size_t kk = 1; kk < c.size(); ++kk) c[kk] = 0.15e-3 * uniform(rng);
    });
    const std::vector<SurfacePixel> pixels = randomPixels(g, 48, 3 + order);
    const dvec3 camera = worldAt(g, {3.0, 2.0, -5.0});
    Options o;
    o.normalOffset = 0.4;
    o.leakDamping = 2.0;
    o.specularAlbedo = 0.5;
    o.exponent = 12.0;
    o.step = 0.7;
    o.samples = 10;  // round(7 / 0.7)
    toml::table table{{"normal_offset", o.normalOffset}, {"leak_damping", o.leakDamping},
                      {"specular_albedo", o.specularAlbedo}, {"exponent", o.exponent},
                      {"step", o.step}, {"max_distance", 7.0}};
    const std::vector<dvec3> out = renderPixels("glossy", table, grid, pixels, glm::vec3(camera));
    std::vector<dvec3> expected;
    for (const SurfacePixel& p : pixels) expected.push_back(cpuRender(grid, p, o, camera));
    const double largest = largestComponent(expected);
    ASSERT_GT(largest, 0.0);
    for (std::size_t i = 0; i < pixels.size(); ++i)
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(out[i][ch], expected[i][ch], 2e-5 * largest) << "order " << order << ", pixel " << i;

    toml::table diffuseOnly{{"normal_offset", o.normalOffset}, {"leak_damping", o.leakDamping}};
    toml::table glossyOff = diffuseOnly;
    glossyOff.insert("exponent", 50.0);
    const std::vector<dvec3> trilinear = renderPixels("trilinear", diffuseOnly, grid, pixels, glm::vec3(camera));
    const std::vector<dvec3> off = renderPixels("glossy", glossyOff, grid, pixels, glm::vec3(camera));
    EXPECT_EQ(trilinear, off);
    // The glossy term is really there in the first run: it differs from the diffuse-only one.
    double difference = 0.0;
    for (std::size_t i = 0; i < pixels.size(); ++i) difference += glm::length(out[i] - trilinear[i]);
    EXPECT_GT(difference, 0.1 * largest);
  }
}

// Extremes: a 1^3 grid, exponents 1 and 10^6, a tiny step, the strongest damping, a grid whose
// light is zero or negative in places, a camera sitting on the surface: always finite, >= 0.
TEST(RenderingVariants, ExtremeParametersGiveFiniteNonNegativeLight) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (glm::ivec3 resolution : {glm::ivec3(1), glm::ivec3(4, 1, 3)}) {
    const GridGeometry g = testGeometry(resolution);
    HandGrid grid(g, 2);
    grid.fill([&](glm::ivec3 cell, int, std::vector<double>& c) {
      if (cell.x % 2 == 1) return;  // dark cells next to lit ones
      for (double& v : c) v = 1e-3 * uniform(rng);  // 9 coefficients: order 2
    });
    std::vector<SurfacePixel> pixels = randomPixels(g, 20, 9);
    pixels.push_back({worldAt(g, dvec3(resolution) * 0.5), {0, 1, 0}, {1, 1, 1}});  // the camera's spot
    const glm::vec3 camera(pixels.back().position);
    for (double exponent : {1.0, 10000.0, 1e6})
      for (auto [step, distance] : {std::pair{0.01, 0.01}, std::pair{0.01, 40.0}, std::pair{16.0, 4096.0}}) {
        toml::table table{{"leak_damping", 16.0}, {"specular_albedo", 1.0}, {"exponent", exponent},
                          {"step", step}, {"max_distance", distance}, {"normal_offset", -2.0}};
        const std::vector<dvec3> out = renderPixels("glossy", table, grid, pixels, camera);
        for (std::size_t i = 0; i < out.size(); ++i)
          for (int ch = 0; ch < 3; ++ch) {
            EXPECT_TRUE(std::isfinite(out[i][ch])) << "pixel " << i << ", exponent " << exponent;
            EXPECT_GE(out[i][ch], 0.0) << "pixel " << i << ", exponent " << exponent;
          }
      }
  }
}

TEST(RenderingVariants, TooManyMarchSamplesIsAnErrorNamingTheKeys) {
  toml::table table{{"type", "glossy"}, {"step", 0.01}, {"max_distance", 100.0}};
  Params params(table, "rendering test", "rendering");
  // 10000 samples per pixel must not be accepted.
  const std::string message =
      test::errorOf([&] { Registry<RenderingStrategy>::instance().create(params, "trilinear"); });
  EXPECT_TRUE(test::contains(message, "max_distance"));
  EXPECT_TRUE(test::contains(message, "step"));
}

}  // namespace
}  // namespace lpvlab

// SH orders 2 and 3 in the standard kernels ([grid] sh_order), on hand-made grids:
//   - the standard gather at orders 2 and 3 is a double-precision C++ gather written for any
//     order from the shared GLSL (shBasisAt, shCosineLobeAt and standard_faces.glsl's faces);
//   - the flux of one VPL per iteration at orders 1-3: the 30 faces tile the sphere and their
//     solid-angle-weighted directions integrate bands 1-3 to zero (cube symmetry), so without the
//     clamp a cell sends exactly its flux; an isotropic source (no clamp at the first step) keeps
//     it exactly, and every step's flux is what the C++ gather's clamp predicts;
//   - rendering an order-2 grid that only has order-1 content is the order-1 rendering;
//   - every shipped propagation runs at orders 1-3; a composition asking more of a strategy than
//     its maxShOrder() is refused, naming the key and the strategy (a test-only order-1 rendering).

#include <cstring>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "error_support.h"
#include "framework/io/image.h"
#include "framework/math/solid_angle.h"
#include "framework/pipeline/composition.h"
#include "variants/resources/geometry_volume.h"
#include "order_grid_support.h"
#include "propagation_rig.h"

namespace lpvlab {
namespace {

using test::expectClose;
using test::forEachCell;
using test::Grid;
using test::kAxes;
using test::maxAbs;

using test::flux;
using test::OrderGrid;

// The standard gather at any order, in double precision, added to `accumulated`.
Grid gatherAnyOrder(const Grid& g, const OrderGrid& o, Grid& accumulated) {
  static const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  Grid out(o.floats(), 0.0f);
  forEachCell(o.res, [&](const glm::ivec3& cell) {
    std::vector<double> sum(std::size_t(3) * o.coefficients, 0.0);
    for (const glm::ivec3& d : kAxes) {
      const glm::ivec3 source = cell - d;  // sends along d into `cell`
      if (!shared::cellInside(source, o.res)) continue;
      for (int f = 0; f < shared::STANDARD_FACES; ++f) {
        const glm::dvec3 w = shared::standardFaceDirection(glm::dvec3(d), f);
        const glm::dvec3 n = shared::standardFaceNormal(glm::dvec3(d), f);
        const double omega = shared::standardFaceSolidAngle(f, angles.farFace, angles.sideFace);
        for (int channel = 0; channel < 3; ++channel) {
          double intensity = 0.0;
          for (int k = 0; k < o.coefficients; ++k)
            intensity += g[o.at(source, channel, k)] * shared::shBasisAt(k, w);
          const double phi = omega * std::max(0.0, intensity);
          for (int k = 0; k < o.coefficients; ++k)
            sum[std::size_t(channel) * o.coefficients + k] += phi / M_PI * shared::shCosineLobeAt(k, n);
        }
      }
    }
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < o.coefficients; ++k) {
        const double v = sum[std::size_t(channel) * o.coefficients + k];
        out[o.at(cell, channel, k)] = float(v);
        accumulated[o.at(cell, channel, k)] += float(v);
      }
  });
  return out;
}

class ShOrder : public ::testing::TestWithParam<int> {};

TEST_P(ShOrder, StandardGatherMatchesTheAnyOrderCppGather) {
  const int order = GetParam();
  const OrderGrid o{{6, 5, 4}, shared::shCoefficientCount(order)};
  std::mt19937 random(99 + order);
  const Grid current = test::randomFloats(o.floats(), random);
  const Grid accumulated = test::randomFloats(o.floats(), random);
  test::PropagationRig rig("standard", o.res, test::iterationsTable(1), order);
  rig.load(current, accumulated);
  rig.propagate();
  Grid expectedAccumulated = accumulated;
  const Grid expectedCurrent = gatherAnyOrder(current, o, expectedAccumulated);
  expectClose(rig.current(), expectedCurrent, 1e-5, "current");
  expectClose(rig.accumulated(), expectedAccumulated, 1e-5, "accumulated");
}

// One source cell at the centre of 15^3: an isotropic one (c0 only) or a Lambertian VPL.
Grid source(const OrderGrid& o, const glm::ivec3& cell, bool isotropic, double phi) {
  Grid g(o.floats(), 0.0f);
  const glm::dvec3 n = glm::normalize(glm::dvec3(1, -2, 3));
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < o.coefficients; ++k) {
      const double c = isotropic ? (k == 0 ? phi / (2.0 * std::sqrt(M_PI)) : 0.0)
                                 : phi / M_PI * shared::shCosineLobeAt(k, n);
      g[o.at(cell, channel, k)] = float(c);
    }
  return g;
}

void fluxPerIteration(int order, bool isotropic) {
  const OrderGrid o{{15, 15, 15}, shared::shCoefficientCount(order)};
  const double phiPerChannel = 1.0, phi = 3.0 * phiPerChannel;
  const int iterations = 6;  // the light stays inside the grid
  test::PropagationRig rig("standard", o.res, test::iterationsTable(1), order);
  Grid model = source(o, {7, 7, 7}, isotropic, phiPerChannel), modelAccumulated = model;
  EXPECT_NEAR(flux(model, o), phi, 1e-6 * phi);
  rig.load(model);
  double previous = phi;
  for (int k = 1; k <= iterations; ++k) {
    rig.propagate();
    model = gatherAnyOrder(model, o, modelAccumulated);
    const double gpu = flux(rig.current(), o), predicted = flux(model, o);
    std::cout << "[ sh order " << order << " ] " << (isotropic ? "isotropic" : "VPL lobe")
              << " it " << k << ": flux " << gpu / phi << " of injected (C++ " << predicted / phi << ")\n";
    EXPECT_NEAR(gpu, predicted, 1e-5 * predicted) << "iteration " << k;
    if (isotropic && k == 1) {
      EXPECT_NEAR(gpu, phi, 1e-5 * phi) << "no clamp: exactly conserved";
    }
    // The clamp only ever adds light.
    EXPECT_GE(gpu, previous * (1.0 - 1e-5)) << "iteration " << k;
    previous = gpu;
  }
  expectClose(rig.accumulated(), modelAccumulated, 1e-5, "accumulated");
}

TEST_P(ShOrder, IsotropicSourceFluxPerIteration) { fluxPerIteration(GetParam(), true); }
TEST_P(ShOrder, VplLobeFluxPerIteration) { fluxPerIteration(GetParam(), false); }

// Without the clamp a cell sends exactly its flux, at every order: the solid-angle-weighted sum
// of every basis function but Y00 over the 30 face directions vanishes.
TEST_P(ShOrder, FaceDirectionsIntegrateEveryBandAboveZeroToZero) {
  const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  for (int k = 0; k < shared::shCoefficientCount(GetParam()); ++k) {
    double sum = 0.0, solidAngle = 0.0;
    for (const glm::ivec3& d : kAxes)
      for (int f = 0; f < shared::STANDARD_FACES; ++f) {
        const double omega = shared::standardFaceSolidAngle(f, angles.farFace, angles.sideFace);
        sum += omega * shared::shBasisAt(k, shared::standardFaceDirection(glm::dvec3(d), f));
        solidAngle += omega;
      }
    EXPECT_NEAR(solidAngle, 4.0 * M_PI, 1e-12);
    EXPECT_NEAR(sum, k == 0 ? 4.0 * M_PI * shared::SH_Y0 : 0.0, 1e-12) << "Y" << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Orders, ShOrder, ::testing::Values(1, 2, 3),
                         [](const auto& info) { return "order" + std::to_string(info.param); });

// ---- rendering: an order-2 grid holding order-1 content renders as the order-1 grid ------------

Image renderTrilinear(const Grid& grid, int order, const glm::ivec3& res, int width, int height,
                      const std::vector<float>& positions, const std::vector<float>& normals,
                      const std::vector<float>& albedo);

TEST(ShOrderRendering, OrderTwoGridWithOrderOneContentRendersAsOrderOne) {
  const glm::ivec3 res{5, 4, 6};
  const int width = 16, height = 12;
  std::mt19937 random(31);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<float> positions, normals, albedo;
  for (int i = 0; i < width * height; ++i) {
    const glm::vec3 p = glm::vec3(uniform(random), uniform(random), uniform(random)) * glm::vec3(res);
    glm::vec3 n = glm::normalize(glm::vec3(uniform(random), uniform(random), uniform(random)) - 0.5f);
    positions.insert(positions.end(), {p.x, p.y, p.z, i % 7 == 0 ? 0.0f : 1.0f});
    normals.insert(normals.end(), {n.x, n.y, n.z, 1.0f});
    albedo.insert(albedo.end(), {uniform(random), uniform(random), uniform(random), 1.0f});
  }
  const OrderGrid o1{res, 4}, o2{res, 9};
  Grid g1(o1.floats()), g2(o2.floats(), 0.0f);
  for (float& v : g1) v = uniform(random);
  forEachCell(res, [&](const glm::ivec3& c) {
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < 4; ++k) g2[o2.at(c, channel, k)] = g1[o1.at(c, channel, k)];
  });
  const Image a = renderTrilinear(g1, 1, res, width, height, positions, normals, albedo);
  const Image b = renderTrilinear(g2, 2, res, width, height, positions, normals, albedo);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  double largest = 0.0;
  for (float v : a.pixels) largest = std::max(largest, double(std::abs(v)));
  ASSERT_GT(largest, 0.0);
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    ASSERT_NEAR(a.pixels[i], b.pixels[i], 1e-6 * largest) << "value " << i;
  // ... and order-2 content changes it (so the comparison can tell).
  for (std::size_t i = std::size_t(4) * o2.cells(); i < std::size_t(9) * o2.cells(); ++i) g2[i] = 0.5f;
  const Image c = renderTrilinear(g2, 2, res, width, height, positions, normals, albedo);
  double difference = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) difference = std::max(difference, double(std::abs(a.pixels[i] - c.pixels[i])));
  EXPECT_GT(difference, 1e-3 * largest);
}

gl::Texture texture(const std::vector<float>& rgba, int width, int height, const char* label) {
  gl::Texture t(GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, label);
  glTextureSubImage2D(t.id(), 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, rgba.data());
  return t;
}

Image renderTrilinear(const Grid& grid, int order, const glm::ivec3& res, int width, int height,
                      const std::vector<float>& positions, const std::vector<float>& normals,
                      const std::vector<float>& albedo) {
  test::glTestContext();
  toml::table table;
  Params params(table, "sh order test", "rendering");
  auto strategy = Registry<RenderingStrategy>::instance().create(params, "trilinear");
  params.finish();
  const GridGeometry geometry{glm::vec3(0.0f), 1.0f, res};
  Requirements requirements;
  requirements.shOrder = order;
  ShaderCompiler shaders;
  strategy->prepare({.shaders = shaders, .grid = geometry, .requirements = requirements});
  LightGrid light(geometry, order);
  light.accumulated.upload(grid.data(), grid.size() * sizeof(float));
  GBuffer gbuffer;
  gbuffer.width = width;
  gbuffer.height = height;
  gbuffer.position = texture(positions, width, height, "position");
  gbuffer.normal = texture(normals, width, height, "normal");
  gbuffer.albedo = texture(albedo, width, height, "albedo");
  LightMaps maps;
  DualImage indirect(width, height, "indirect");
  Frame frame{.gbuffer = gbuffer, .lightMaps = maps, .lightGrid = light, .indirect = indirect};
  strategy->render(frame);
  checkGl("sh order rendering test");
  Image image(width, height, 4);
  const HostImage& texels = indirect.hostRead();
  std::memcpy(image.pixels.data(), texels.texels.data(), image.pixels.size() * sizeof(float));
  return image;
}

// ---- composition -------------------------------------------------------------------------------

template <class Interface>
std::unique_ptr<Interface> createDefault(const std::string& type) {
  static const toml::table empty;
  Params params(empty, "sh order test");
  auto strategy = Registry<Interface>::instance().create(params, type);
  params.finish();
  return strategy;
}

// No shipped strategy is order-1 only any more; the refusal is the composition's, so a
// strategy that keeps the default maxShOrder() of 1 shows it.
class OrderOneRendering final : public RenderingStrategy {
public:
  void prepare(const StrategySetup&) override {}
  void render(Frame&) override {}
};

Strategies composition(const std::string& propagation) {
  Strategies strategies;
  strategies.injection.push_back(createDefault<InjectionStrategy>("rsm_vpl"));
  strategies.occlusion = createDefault<OcclusionStrategy>("none");
  strategies.propagation = createDefault<PropagationStrategy>(propagation);
  strategies.rendering.push_back(createDefault<RenderingStrategy>("trilinear"));
  return strategies;
}

TEST(ShOrderComposition, EveryPropagationRunsAtOrdersOneToThree) {
  test::glTestContext();
  for (const std::string type : {"standard", "directed", "tetrahedral"})
    for (int order = 1; order <= 3; ++order)
      EXPECT_EQ(resolveRequirements(composition(type), order).shOrder, order) << type;
}

TEST(ShOrderComposition, OrderTwoOfAnOrderOneStrategyIsRefusedNamingTheGridKey) {
  test::glTestContext();
  Strategies strategies = composition("directed");
  strategies.rendering.push_back(std::make_unique<OrderOneRendering>());
  strategies.rendering.back()->setRegisteredName("order_one");
  EXPECT_TRUE(resolveRequirements(strategies, 1).has(kNormalGrid));
  const std::string message =
      test::errorOf([&] { resolveRequirements(strategies, 2); });
  EXPECT_TRUE(test::contains(message, "[grid] sh_order")) << message;
  EXPECT_TRUE(test::contains(message, "[rendering.also[0]] type = \"order_one\"")) << message;
}

}  // namespace
}  // namespace lpvlab

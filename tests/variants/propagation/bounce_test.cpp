// Multiple bounces through the geometry volume (standard propagation's `bounces`; the mathematics
// in shaders/propagation/standard_faces.glsl): the light a face crossing blocks, Phi_b =
// (1 - T) Omega_f max(0, I(w_f)), is re-emitted by the GV's surfaces there as rho Phi_b / pi *
// cosLobe(n) into the cell it came from.
//   a. albedo 0 gives the grid of no bounces;
//   b. energy: per step, from the same source grid, the light after a step with bounces is the
//      light after the occluded step plus rho times what the GV blocked, so it never exceeds what
//      the step sends without any GV (equal for rho = 1), whatever the (random) albedo <= 1;
//      a fully blocking closed shell around one cell keeps every watt in that cell, and the flux
//      there decays exactly as rho^k (channel by channel) while the accumulated flux is the
//      geometric sum (1 - rho^(k+1)) / (1 - rho) Phi, on the GL and the CPU backend;
//   c. one GPU step (gather and scatter) equals the double-precision C++ of the same shared GLSL,
//      on a random grid, random GV and random albedo, and gather equals scatter at SH orders 1-3;
//   d. on the Cornell box the indirect light with bounces exceeds that without, and stays below
//      the one-bounce-per-generation bound 1 / (1 - rho_max) times it; the GV's albedo, from the
//      camera's G-buffer and from the RSMs (reflected over arriving flux), is the surfaces';
//   e. bounces without a GV are refused, naming the occlusion strategy to choose.

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "error_support.h"
#include "framework/experiment/experiment.h"
#include "framework/math/solid_angle.h"
#include "framework/pipeline/light_views.h"
#include "framework/pipeline/pipeline.h"
#include "framework/pipeline/raster_passes.h"
#include "framework/pipeline/scene_gpu.h"
#include "variants/resources/geometry_volume.h"
#include "propagation_rig.h"

namespace lpvlab {
namespace {

using test::Grid;
using test::maxAbs;
using test::maxDifference;
using test::randomFloats;
using test::randomAlbedo;
using test::randomGv;

toml::table bounceTable(int iterations, const std::string& method, bool bounces) {
  toml::table t = test::iterationsTable(iterations, method);
  t.insert("bounces", bounces);
  return t;
}

// A rig of standard propagation with a GV (and its albedo when bouncing), loaded and occluded
// from the first step on.
struct BounceRig {
  test::PropagationRig rig;
  BounceRig(const glm::ivec3& res, int iterations, const std::string& method, bool bounces,
            const Grid& gv, const Grid* albedo, int order = 1,
            ComputeBackend backend = ComputeBackend::Gl)
      : rig("standard", res, bounceTable(iterations, method, bounces), order, true, backend) {
    rig.loadGv(gv, 0);
    if (bounces) rig.loadAlbedo(*albedo);
  }
  Grid step(const Grid& current) {
    rig.load(current);
    rig.propagate();
    return rig.current();
  }
};

// The same albedo rho (grey) in every GV cell.
Grid uniformAlbedo(const glm::ivec3& gvRes, float rho) {
  Grid albedo(std::size_t(4) * test::cells(gvRes), rho);
  for (int i = 0; i < test::cells(gvRes); ++i) albedo[4 * i + 3] = 1.0f;
  return albedo;
}

// An order-1 grid whose every cell holds, per channel, a clamped-cosine lobe of random flux in
// [0, 1) W and random direction: the non-negative functions injection and propagation store.
Grid randomLobes(const glm::ivec3& res, std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Grid g(std::size_t(3) * test::kCoefficients * test::cells(res), 0.0f);
  test::forEachCell(res, [&](const glm::ivec3& cell) {
    for (int channel = 0; channel < 3; ++channel) {
      const double z = 2.0 * uniform(random) - 1.0, phi = 2.0 * M_PI * uniform(random);
      const double r = std::sqrt(1.0 - z * z);
      const glm::dvec4 c = uniform(random) / M_PI *
                           shared::shCosineLobe({r * std::cos(phi), r * std::sin(phi), z});
      for (int k = 0; k < test::kCoefficients; ++k) g[test::at(res, cell, channel, k)] = float(c[k]);
    }
  });
  return g;
}

// ---- a. albedo 0 -------------------------------------------------------------------------------

TEST(Bounces, AlbedoZeroGivesTheGridOfNoBounces) {
  const glm::ivec3 res{7, 6, 5};
  std::mt19937 random(501);
  const Grid current = randomLobes(res, random);
  const Grid gv = randomGv(res + 1, random);
  const Grid black = uniformAlbedo(res + 1, 0.0f);
  const Grid grey = uniformAlbedo(res + 1, 0.8f);
  for (const std::string method : {"gather", "scatter"}) {
    BounceRig plain(res, 4, method, false, gv, nullptr);
    BounceRig zero(res, 4, method, true, gv, &black);
    BounceRig bouncing(res, 4, method, true, gv, &grey);
    const Grid expected = plain.step(current);
    const Grid withZero = zero.step(current);
    const Grid accumulatedPlain = plain.rig.accumulated(), accumulatedZero = zero.rig.accumulated();
    // Gather adds exact zeros; scatter's atomics add in any order.
    const double tolerance = method == "gather" ? 0.0 : 2e-6 * maxAbs(expected);
    EXPECT_LE(maxDifference(withZero, expected), tolerance) << method;
    EXPECT_LE(maxDifference(accumulatedZero, accumulatedPlain), 2 * tolerance) << method;
    // With albedo the grid differs: the comparison can fail.
    EXPECT_GT(maxDifference(bouncing.step(current), expected), 0.05 * maxAbs(expected)) << method;
  }
}

// ---- b. energy ---------------------------------------------------------------------------------

// Blocking with nothing on the grid's outer faces (GV cells on the boundary planes left empty):
// light leaving the grid then leaves it with or without bounces, so the per-step comparison
// below is face by face.
Grid randomGvInside(const glm::ivec3& res, std::mt19937& random) {
  const glm::ivec3 gvRes = res + 1;
  Grid gv = randomGv(gvRes, random);
  test::forEachCell(gvRes, [&](const glm::ivec3& c) {
    if (glm::all(glm::greaterThan(c, glm::ivec3(0))) && glm::all(glm::lessThan(c, res))) return;
    for (int k = 0; k < 4; ++k) gv[std::size_t(k) * test::cells(gvRes) + shared::cellIndex(c, gvRes)] = 0.0f;
  });
  return gv;
}

TEST(Bounces, AStepNeverSendsMoreThanWithoutTheGvAndRhoTimesTheBlockedLightComesBack) {
  const glm::ivec3 res{8, 8, 8};
  std::mt19937 random(502);
  const Grid gv = randomGvInside(res, random);
  const Grid albedo = randomAlbedo(res + 1, random);
  const Grid half = uniformAlbedo(res + 1, 0.5f), white = uniformAlbedo(res + 1, 1.0f);
  test::PropagationRig open("standard", res, test::iterationsTable(1));
  BounceRig occluded(res, 1, "gather", false, gv, nullptr);
  BounceRig bouncing(res, 1, "gather", true, gv, &albedo);
  BounceRig grey(res, 1, "gather", true, gv, &half);
  BounceRig whiteRig(res, 1, "gather", true, gv, &white);

  Grid state = randomLobes(res, random);
  std::cout << "[ bounces ] step   sent (no GV)     occluded   random rho      rho=0.5        rho=1\n";
  for (int k = 1; k <= 6; ++k) {
    open.load(state);
    open.propagate();
    const double sent = test::flux(open.current(), res);
    const double kept = test::flux(occluded.step(state), res);
    const Grid next = bouncing.step(state);
    const double withBounces = test::flux(next, res);
    const double withHalf = test::flux(grey.step(state), res);
    const double withWhite = test::flux(whiteRig.step(state), res);
    std::cout << "[ bounces ] " << std::setw(4) << k << std::fixed << std::setprecision(5);
    for (double value : {sent, kept, withBounces, withHalf, withWhite}) std::cout << std::setw(13) << value;
    std::cout << "\n" << std::defaultfloat;
    const double tolerance = 1e-5 * sent;
    ASSERT_GT(sent - kept, 0.05 * sent) << "the GV blocks a good part (step " << k << ")";
    // Per face: T Phi + rho (1 - T) Phi, and the re-emitted lobe integrates to exactly its flux.
    EXPECT_NEAR(withWhite, sent, tolerance) << "rho = 1 keeps all the light sent, step " << k;
    EXPECT_NEAR(withHalf, kept + 0.5 * (sent - kept), tolerance) << "step " << k;
    EXPECT_LE(withBounces, sent + tolerance) << "step " << k;
    EXPECT_GE(withBounces, kept - tolerance) << "step " << k;
    state = next;
  }
}

TEST(Bounces, AClosedOpaqueShellKeepsTheLightAndItDecaysAsRhoToTheK) {
  const glm::ivec3 res{5, 5, 5}, centre{2, 2, 2};
  const glm::ivec3 gvRes = res + 1;
  const double rho[3] = {0.8, 0.5, 0.3};
  // The GV cells at the centre cell's eight corners: isotropic blocking c0 Y0 = 2.8 (T = 0 on all
  // of the cell's faces, as in occlusion_test's wall) and albedo rho; nothing anywhere else.
  Grid gv(std::size_t(4) * test::cells(gvRes), 0.0f), albedo(std::size_t(4) * test::cells(gvRes), 0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    const int i = shared::cellIndex(centre + glm::ivec3(corner & 1, (corner >> 1) & 1, corner >> 2), gvRes);
    gv[i] = 10.0f;
    for (int c = 0; c < 3; ++c) albedo[4 * i + c] = float(rho[c]);
    albedo[4 * i + 3] = 1.0f;
  }
  // Isotropic light in the cell: its 30 faces' blocked fluxes are Omega_f / (4 pi) of its flux,
  // re-emitted about -w_f (no direction in isotropic blocking), whose band 1 cancels over the
  // cube's symmetric faces: the cell stays isotropic, each step multiplies its flux by rho.
  for (const ComputeBackend backend : {ComputeBackend::Gl, ComputeBackend::Cpu})
  for (const std::string method0 : {"gather", "scatter"}) {
    const std::string method = method0 + (backend == ComputeBackend::Cpu ? " (CPU)" : " (GL)");
    BounceRig shell(res, 1, method0, true, gv, &albedo, 1, backend);
    Grid state = test::pointSource(res, centre, true);
    shell.rig.load(state);
    double accumulatedExpected[3] = {0, 0, 0};
    for (int c = 0; c < 3; ++c) accumulatedExpected[c] = test::kChannelFlux[c];
    for (int k = 1; k <= 12; ++k) {
      shell.rig.propagate();
      state = shell.rig.current();
      const Grid accumulated = shell.rig.accumulated();
      auto outside = [&](const glm::ivec3& c) { return c != centre; };
      EXPECT_EQ(test::flux(state, res, outside), 0.0) << method << " step " << k;
      ASSERT_TRUE(test::allFinite(state)) << method << " step " << k;
      for (int c = 0; c < 3; ++c) {
        const double phi = test::kChannelFlux[c];
        const glm::dvec4 cell = test::cellOf(state, res, centre, c);
        const double expected = phi * std::pow(rho[c], k);
        accumulatedExpected[c] += expected;
        EXPECT_NEAR(shared::shIntegral(cell), expected, 1e-5 * phi) << method << " step " << k;
        EXPECT_NEAR(glm::length(glm::dvec3(cell[1], cell[2], cell[3])), 0.0, 1e-6 * phi)
            << "stays isotropic";
        EXPECT_NEAR(shared::shIntegral(test::cellOf(accumulated, res, centre, c)),
                    accumulatedExpected[c], 1e-5 * phi * k)
            << method << " step " << k;
      }
    }
    const double total = test::flux(shell.rig.accumulated(), res);
    double geometric = 0.0;
    for (int c = 0; c < 3; ++c)
      geometric += test::kChannelFlux[c] * (1.0 - std::pow(rho[c], 13)) / (1.0 - rho[c]);
    std::cout << "[ bounces ] " << method << ": accumulated flux after 12 steps in the shell "
              << total << " W, geometric sum " << geometric << " W\n";
    EXPECT_NEAR(total, geometric, 1e-5 * geometric);
  }
}

// ---- c. against the double-precision C++ -------------------------------------------------------

// The albedo's (rho A, A) at light-grid coordinates g, interpolated as gvBlockingAt interpolates
// the blocking potential (GV cell centres at integer g).
glm::dvec4 albedoAt(const Grid& albedo, const glm::dvec3& g, const glm::ivec3& gvRes) {
  const glm::dvec3 base = glm::floor(g), f = g - base;
  glm::dvec4 sum(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::ivec3 o(corner & 1, (corner >> 1) & 1, corner >> 2);
    const glm::ivec3 c = glm::ivec3(base) + o;
    if (!shared::cellInside(c, gvRes)) continue;
    const glm::dvec3 w3 = glm::mix(1.0 - f, f, glm::dvec3(o));
    const int i = shared::cellIndex(c, gvRes);
    sum += w3.x * w3.y * w3.z *
           glm::dvec4(albedo[4 * i], albedo[4 * i + 1], albedo[4 * i + 2], albedo[4 * i + 3]);
  }
  return sum;
}

// One order-1 step by scattering in double precision: every cell sends through the 30 faces of
// its six neighbours (the grid's edge included), attenuated by the GV, and, with `albedo`, takes
// back what the surfaces at each crossing re-emit: the shared functions the kernels call.
Grid referenceStep(const glm::ivec3& res, const Grid& current, const Grid& gv, const Grid* albedo) {
  const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
  const glm::ivec3 gvRes = res + 1;
  shared::gvBlocking.assign(gv.begin(), gv.end());
  std::vector<glm::dvec4> next(std::size_t(3) * test::cells(res), glm::dvec4(0.0));
  auto slot = [&](const glm::ivec3& cell, int channel) -> glm::dvec4& {
    return next[std::size_t(channel) * test::cells(res) + shared::cellIndex(cell, res)];
  };
  test::forEachCell(res, [&](const glm::ivec3& from) {
    for (const glm::ivec3& offset : test::kAxes) {
      const glm::ivec3 to = from + offset;
      const glm::dvec3 d(offset);
      for (int f = 0; f < shared::STANDARD_FACES; ++f) {
        const glm::dvec3 w = shared::standardFaceDirection(d, f);
        const double omega = shared::standardFaceSolidAngle(f, angles.farFace, angles.sideFace);
        const glm::dvec3 crossing = shared::standardFaceCrossing(glm::dvec3(from) + 0.5, d, f);
        const glm::dvec4 b = shared::gvBlockingAt(crossing, gvRes);
        const double t = shared::gvTransmittance(b, w);
        const glm::dvec3 rho = albedo ? shared::gvMeanAlbedo(albedoAt(*albedo, crossing, gvRes))
                                      : glm::dvec3(0.0);
        const glm::dvec3 n = shared::gvSurfaceNormal(b, w);
        for (int channel = 0; channel < 3; ++channel) {
          const glm::dvec4 c = test::cellOf(current, res, from, channel);
          if (shared::cellInside(to, res))
            slot(to, channel) += shared::propagateThroughOccludedFace(
                c, w, shared::standardFaceNormal(d, f), omega, t);
          slot(from, channel) += shared::bounceAtFace(c, w, omega, t, n, rho[channel]);
        }
      }
    }
  });
  Grid out(current.size());
  test::forEachCell(res, [&](const glm::ivec3& cell) {
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < test::kCoefficients; ++k)
        out[test::at(res, cell, channel, k)] = float(slot(cell, channel)[k]);
  });
  return out;
}

void stepMatchesReference(const std::string& method) {
  const glm::ivec3 res{6, 5, 4};
  std::mt19937 random(503);
  const Grid current = randomFloats(std::size_t(3) * 4 * test::cells(res), random, -1.0f, 1.0f);
  const Grid accumulated = randomFloats(current.size(), random, -1.0f, 1.0f);
  const Grid gv = randomGv(res + 1, random);
  const Grid albedo = randomAlbedo(res + 1, random);

  BounceRig gpu(res, 1, method, true, gv, &albedo);
  gpu.rig.load(current, accumulated);
  gpu.rig.propagate();
  const Grid expected = referenceStep(res, current, gv, &albedo);
  const double tolerance = 1e-5 * maxAbs(expected);
  EXPECT_LE(maxDifference(gpu.rig.current(), expected), tolerance) << method;
  Grid expectedAccumulated = accumulated;
  for (std::size_t i = 0; i < expected.size(); ++i) expectedAccumulated[i] += expected[i];
  EXPECT_LE(maxDifference(gpu.rig.accumulated(), expectedAccumulated), 2 * tolerance) << method;
  // The bounces mattered: without the albedo the reference differs.
  const Grid withoutBounces = referenceStep(res, current, gv, nullptr);
  EXPECT_GT(maxDifference(expected, withoutBounces), 0.05 * maxAbs(expected));
}

TEST(Bounces, GatherStepMatchesTheSharedCpp) { stepMatchesReference("gather"); }
TEST(Bounces, ScatterStepMatchesTheSharedCpp) { stepMatchesReference("scatter"); }

TEST(Bounces, GatherEqualsScatterAtOrders1To3) {
  const glm::ivec3 res{7, 6, 5};
  for (int order = 1; order <= 3; ++order) {
    std::mt19937 random(504 + order);
    const std::size_t n = std::size_t(3) * (order + 1) * (order + 1) * test::cells(res);
    const Grid current = randomFloats(n, random, -1.0f, 1.0f);
    const Grid gv = randomGv(res + 1, random);
    const Grid albedo = randomAlbedo(res + 1, random);
    BounceRig gather(res, 3, "gather", true, gv, &albedo, order);
    BounceRig scatter(res, 3, "scatter", true, gv, &albedo, order);
    BounceRig plain(res, 3, "gather", false, gv, nullptr, order);
    const Grid g = gather.step(current), s = scatter.step(current);
    const double tolerance = 2e-5 * maxAbs(gather.rig.accumulated());
    EXPECT_LE(maxDifference(g, s), tolerance) << "order " << order;
    EXPECT_LE(maxDifference(gather.rig.accumulated(), scatter.rig.accumulated()), tolerance)
        << "order " << order;
    EXPECT_GT(maxDifference(g, plain.step(current)), 0.05 * maxAbs(g)) << "order " << order;
  }
}

// ---- d. the Cornell box ------------------------------------------------------------------------

// The mean indirect radiance per channel of the built-in Cornell box with GV occlusion.
glm::dvec3 meanIndirect(bool bounces) {
  test::glTestContext();
  Experiment e = loadExperiment(
      "", {"output.width=64", "output.height=64", "light_maps.shadow_resolution=128",
           "light_maps.rsm_resolution=64", "grid.resolution=16", "propagation.iterations=16",
           "occlusion.type=\"geometry_volume\"",
           std::string("propagation.bounces=") + (bounces ? "true" : "false")});
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  for (const NamedImage& output : pipeline.readOutputs()) {
    if (output.name != "indirect") continue;
    glm::dvec3 sum(0.0);
    for (int y = 0; y < output.image.height; ++y)
      for (int x = 0; x < output.image.width; ++x)
        for (int c = 0; c < 3; ++c) sum[c] += output.image.at(x, y, c);
    return sum / double(output.image.width * output.image.height);
  }
  ADD_FAILURE() << "no indirect output";
  return glm::dvec3(0.0);
}

TEST(Bounces, CornellBoxGetsMoreIndirectLightBelowTheGeometricBound) {
  const glm::dvec3 without = meanIndirect(false), with = meanIndirect(true);
  // The box's largest albedo per channel (the white walls, framework/scene/cornell_box.cpp).
  const glm::dvec3 rhoMax(0.725, 0.71, 0.68);
  std::cout << "[ bounces ] Cornell box mean indirect radiance: without bounces (" << without.x
            << ", " << without.y << ", " << without.z << "), with (" << with.x << ", " << with.y
            << ", " << with.z << ") W/(m^2 sr)\n";
  for (int c = 0; c < 3; ++c) {
    ASSERT_GT(without[c], 0.0);
    EXPECT_GT(with[c], 1.05 * without[c]) << "channel " << c;
    // Each generation of re-emitted light carries at most rho_max of the flux the previous one
    // lost to the GV, which is at most all of it: sum over generations <= 1 / (1 - rho_max).
    EXPECT_LT(with[c], without[c] / (1.0 - rhoMax[c])) << "channel " << c;
  }
}

// The GV's albedo (rho A, A per GV cell) as the occlusion strategy fills it from `sources` on the
// built-in Cornell box (its G-buffer and RSMs rendered at 128^2).
Grid gvAlbedoFrom(const std::string& source) {
  test::glTestContext();
  Experiment e = loadExperiment("", {"output.width=128", "output.height=128",
                                     "light_maps.shadow_resolution=128",
                                     "light_maps.rsm_resolution=128", "grid.resolution=16"});
  ShaderCompiler shaders;
  SceneGpu scene(e.scene);
  const PipelineSettings& s = e.settings;
  GBufferPass gbuffer(shaders, s.width, s.height);
  gbuffer.render(scene, e.camera);
  LightMapsPass lightMaps(shaders, buildLightViews(e.scene.lights, e.scene.bounds()),
                          s.rsmResolution, s.shadowResolution);
  lightMaps.renderRsms(scene);
  toml::table table;
  table.insert("sources", toml::array{source});
  Params params(table, "bounce test", "occlusion");
  auto strategy = Registry<OcclusionStrategy>::instance().create(params, "geometry_volume");
  params.finish();
  const Requirements requirements = test::standInRequirements(
      *strategy, 1, {std::string(kGeometryVolume.name), std::string(kSurfaceAlbedo.name)});
  LightGrid grid(s.grid, 1);
  strategy->prepare({.shaders = shaders, .grid = grid.geometry, .requirements = requirements});
  GeometryVolume gv(grid.geometry, 0);
  SurfaceAlbedo surfaceAlbedo(grid.geometry);
  gv.clear();
  surfaceAlbedo.clear();
  ResourceTable resources;
  resources.put(kGeometryVolume, gv);
  resources.put(kSurfaceAlbedo, surfaceAlbedo);
  DualImage indirect;
  Frame frame{.scene = &scene, .camera = &e.camera, .gbuffer = gbuffer.gbuffer(),
              .lightMaps = lightMaps.lightMaps(), .lightGrid = grid, .indirect = indirect,
              .resources = &resources};
  strategy->inject(frame);
  glFinish();
  checkGl("bounce test");
  Grid albedo(std::size_t(4) * gv.geometry.cellCount());
  surfaceAlbedo.albedo.download(albedo.data(), albedo.size() * sizeof(float));
  return albedo;
}

// Camera surfels carry the G-buffer's albedo; RSM surfels their reflected flux over the flux
// arriving, which must give the same albedo back: in cells that see one material only, the mean
// is that material's reflectance (to float rounding), and every mean lies between the box's
// smallest and largest reflectance per channel.
TEST(Bounces, TheGvKeepsTheSurfacesAlbedoFromTheCameraAndFromTheRsms) {
  const glm::dvec3 materials[3] = {{0.725, 0.71, 0.68}, {0.63, 0.065, 0.05}, {0.14, 0.45, 0.091}};
  for (const std::string source : {"camera", "light"}) {
    const Grid albedo = gvAlbedoFrom(source);
    int seen = 0, pure = 0;
    for (std::size_t i = 0; i < albedo.size() / 4; ++i) {
      if (albedo[4 * i + 3] <= 0.0f) continue;
      ++seen;
      const glm::dvec3 mean =
          glm::dvec3(albedo[4 * i], albedo[4 * i + 1], albedo[4 * i + 2]) / double(albedo[4 * i + 3]);
      bool isPure = false;
      for (const glm::dvec3& m : materials) isPure |= glm::length(mean - m) < 1e-4;
      pure += isPure;
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(mean[c], 0.05 - 1e-4) << source << " cell " << i;
        EXPECT_LE(mean[c], 0.725 + 1e-4) << source << " cell " << i;
      }
    }
    std::cout << "[ bounces ] GV albedo from the " << source << ": " << seen << " cells seen, "
              << pure << " of one material\n";
    EXPECT_GT(seen, 100) << source;
    EXPECT_GT(pure, seen / 2) << source;
  }
}

// The surfaces' albedo (4 floats per GV cell, as much as the GV) exists only when bounces consume
// it; the GV itself is the same either way.
TEST(Bounces, TheGvAlbedoIsAllocatedOnlyWithBounces) {
  test::glTestContext();
  for (const bool bounces : {false, true}) {
    Experiment e = loadExperiment(
        "", {"output.width=32", "output.height=32", "light_maps.rsm_resolution=32",
             "grid.resolution=12", "occlusion.type=\"geometry_volume\"",
             "occlusion.sources=[\"camera\"]",
             std::string("propagation.bounces=") + (bounces ? "true" : "false")});
    const std::size_t gvCells = std::size_t(test::cells(e.settings.grid.resolution + 1));
    ShaderCompiler shaders;
    Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
    const nlohmann::json memory = pipeline.memoryReport();
    EXPECT_EQ(memory.at("geometry_volume").get<std::size_t>(), gvCells * 4 * sizeof(float));
    EXPECT_EQ(memory.value("surface_albedo", std::size_t(0)), bounces ? gvCells * 4 * sizeof(float) : 0)
        << "bounces " << bounces;
  }
}

// ---- e. refusal --------------------------------------------------------------------------------

TEST(Bounces, WithoutAGeometryVolumeTheyAreRefusedNamingTheOcclusionStrategy) {
  test::glTestContext();
  // Loading the experiment or building its pipeline refuses it.
  const std::string message = test::errorOf([] {
    Experiment e = loadExperiment("", {"output.width=16", "output.height=16",
                                       "occlusion.type=\"none\"", "propagation.bounces=true"});
    ShaderCompiler shaders;
    Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  });
  EXPECT_TRUE(test::contains(message, "bounces"));
  EXPECT_TRUE(test::contains(message, "[occlusion] type = \"geometry_volume\""));
}

}  // namespace
}  // namespace lpvlab

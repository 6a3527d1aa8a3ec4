// Particle systems through the LPV pipeline (experiments/particles_cornell.toml, docs/particles.md),
// against a brute-force double-precision ray caster over the same scene:
//   a. the G-buffer sees a particle at exactly the pixels whose centre ray first hits one, in the
//      colour its life gives it;
//   b. the particles cast shadows: floor pixels whose shadow ray to the spot light is blocked
//      only by particles get less direct light than without the particles;
//   c. a sequence moves them: every frame's record counts the live particles and has a scene
//      hash of its own, and its images stay finite;
//   d. one large particle drawn as a light field and as geometry covers the same pixels in the
//      same colour and gets the same direct and indirect light, within the tolerances the test
//      states;
//   e. a light-field particle, turned and seen from one of its captured directions, lit only by a
//      light grid that holds the same linear intensity I(w) = I0 + I1 a.w in every cell, gets at
//      every pixel the closed form albedo (I0 - 2/3 I1 a.n) / s^2 of the surface a ray finds
//      there (its albedo times the particle's colour), for SH orders 1 and 2, nearest and
//      interpolated views;
//   f. inject = false leaves them out of the RSMs: the grid gets what the scene without them
//      injects, for either drawing;
//   g. a sweep's summary.csv counts them and names their drawing.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "sweep_support.h"
#include "lpv_support.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/run.h"
#include "framework/experiment/sweep_summary.h"
#include "framework/particles/particle_billboards.h"
#include "framework/pipeline/pipeline.h"
#include "framework/pipeline/raster_passes.h"
#include "io/temp_dir.h"
#include "particles/crystal_model.h"
#include "pipeline_test_support.h"
#include "rendering_rig.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/particles/light_field_views.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

const std::string kFile = std::string(LPVLAB_SOURCE_DIR) + "/experiments/particles_cornell.toml";
constexpr int kSize = 96;

std::vector<std::string> smallFrame(std::vector<std::string> more = {}) {
  std::vector<std::string> overrides = {"output.width=" + std::to_string(kSize),
                                        "output.height=" + std::to_string(kSize),
                                        "light_maps.shadow_resolution=1024", "timing.warmup=0",
                                        "timing.repeats=1"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  return overrides;
}

struct Frame {
  Experiment experiment;
  std::vector<NamedImage> outputs;
  InjectionBalance injection;  // the RSMs' flux and what went into the grid
};

Frame render(std::vector<std::string> overrides, bool withoutParticles = false) {
  test::glTestContext();
  Frame f{loadExperiment(kFile, overrides), {}};
  Experiment& e = f.experiment;
  if (withoutParticles)  // the same scene with every particle's triangles collapsed away
    for (const ParticleGeometry& p : e.particles)
      for (int m = p.firstMesh(); m < p.firstMesh() + p.meshCount(); ++m)
        for (glm::vec3& v : e.scene.meshes[std::size_t(m)].positions) v = glm::vec3(0.28f, 0.01f, 0.28f);
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  std::optional<ParticleBillboardSet> billboards;  // and no billboards without particles
  if (!withoutParticles) billboards.emplace(e.particles, e.animation.frameTime(0), shaders, pipeline);
  pipeline.renderFrame();
  f.outputs = pipeline.readOutputs();
  f.injection = test::lpvOf(pipeline).measureInjection();
  return f;
}

bool isParticle(const Experiment& e, int mesh) {
  for (const ParticleGeometry& p : e.particles)
    if (mesh >= p.firstMesh() && mesh < p.firstMesh() + p.meshCount()) return true;
  return false;
}

// With the file's colour keys (warm at birth, cool at death), each copy's albedo is the crystal's
// times its own colour: the G-buffer shows at every pixel the albedo of what the ray caster hits
// there, vertex colours included, and the particles show more than one colour.
TEST(Particles, TheGBufferSeesThemWhereRaysFirstHitThemInTheirColours) {
  const Frame f = render(smallFrame({"particles[0].draw=geometry"}));
  const Experiment& e = f.experiment;
  ASSERT_EQ(e.particles.size(), 1u);
  ASSERT_TRUE(e.particles[0].colouredPerParticle());
  const test::SceneRaycaster caster(e.scene);
  const Image& albedo = findAov(f.outputs, "albedo");
  int hitPixels = 0, particlePixels = 0, agree = 0, particlesAgree = 0;
  double bluest = 0.0, reddest = 1e9;  // of the particles' blue over red
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::dvec3 ray = test::cameraRay(e.camera, kSize, kSize, x, y);
      const auto hit = caster.cast(glm::dvec3(e.camera.position), ray);
      if (!hit) continue;
      const bool particle = isParticle(e, hit->mesh);
      const glm::dvec3 expected = caster.untexturedAlbedo(*hit);
      const glm::dvec3 a(albedo.at(x, y, 0), albedo.at(x, y, 1), albedo.at(x, y, 2));
      const bool same = glm::length(a - expected) < 1e-3;
      ++hitPixels;
      agree += same;
      particlePixels += particle;
      particlesAgree += particle && same;
      if (particle && same) {
        bluest = std::max(bluest, expected.b / expected.r);
        reddest = std::min(reddest, expected.b / expected.r);
      }
    }
  std::cout << "[ particles ] " << particlePixels << " of " << kSize * kSize
            << " pixels show a particle; the G-buffer's albedo is the ray caster's at " << agree << " of " << hitPixels
            << " (" << particlesAgree << " of the particles'); blue over red " << reddest << " to " << bluest << "\n";
  EXPECT_GT(particlePixels, 20);
  // Rasterisation samples pixel centres too: only pixels whose centre grazes an edge may differ.
  EXPECT_GE(agree, hitPixels - kSize / 8);
  EXPECT_GE(particlesAgree, particlePixels - kSize / 8);
  EXPECT_GT(bluest / reddest, 1.3);  // young and old crystals are told apart
}

TEST(Particles, TheyCastShadows) {
  const Frame with = render(smallFrame({"particles[0].draw=geometry"}));
  const Frame without = render(smallFrame({"particles[0].draw=geometry"}), true);
  const Experiment& e = with.experiment;
  const test::SceneRaycaster caster(e.scene);
  const glm::dvec3 light(e.scene.lights.at(0).position);
  const Image& lit = findAov(with.outputs, "direct");
  const Image& bare = findAov(without.outputs, "direct");
  int shadowed = 0, darker = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::dvec3 eye(e.camera.position);
      const auto hit = caster.cast(eye, test::cameraRay(e.camera, kSize, kSize, x, y));
      if (!hit || isParticle(e, hit->mesh) || std::abs(hit->normal.y) < 0.99) continue;
      const glm::dvec3 p = eye + hit->t * test::cameraRay(e.camera, kSize, kSize, x, y);
      if (p.y > 0.01) continue;  // the floor only
      const auto blocker = caster.cast(p + 1e-6 * hit->normal, light - p, 1e-6);
      if (!blocker || blocker->t >= 1.0 || !isParticle(e, blocker->mesh)) continue;
      ++shadowed;
      darker += lit.at(x, y, 0) < 0.5f * bare.at(x, y, 0);
    }
  std::cout << "[ particles ] " << shadowed << " floor pixels in a particle's shadow, " << darker
            << " of them under half as bright as without particles\n";
  EXPECT_GT(shadowed, 5);
  EXPECT_GE(darker, int(0.7 * shadowed));
}

TEST(Particles, ASequenceMovesThemFrameByFrame) {
  const GlContext& context = test::glTestContext();
  test::TempDir dir;
  Experiment e = loadExperiment(kFile, smallFrame({"animation.frames=3", "output.width=48", "output.height=48"}));
  const nlohmann::json manifest = runExperiment(e, context, dir.file("run"));
  ASSERT_EQ(manifest.at("particles").size(), 1u);
  EXPECT_EQ(manifest.at("particles")[0].at("model_triangles").get<int>(), 8);
  const nlohmann::json& records = manifest.at("sequence").at("frame_records");
  ASSERT_EQ(records.size(), 3u);
  std::string previousHash;
  for (int frame = 0; frame < 3; ++frame) {
    const nlohmann::json& record = records[std::size_t(frame)];
    EXPECT_GT(record.at("particles_alive").at("fountain").get<int>(), 100) << frame;
    EXPECT_NE(record.at("scene_hash").get<std::string>(), previousHash);
    previousHash = record.at("scene_hash");
  }
}

// inject = false leaves the particles out of the RSMs, for either drawing: the grid then gets what
// the same scene without particles injects, to float rounding, where inject = true differs.
TEST(Particles, WithoutInjectionTheGridGetsWhatTheSceneWithoutThemInjects) {
  for (const std::string draw : {"geometry", "light_field"}) {
    const std::vector<std::string> base = smallFrame({"particles[0].draw=\"" + draw + "\""});
    std::vector<std::string> off = base;
    off.push_back("particles[0].inject=false");
    const double bare = render(base, true).injection.rsmFlux;
    const double injecting = render(base).injection.rsmFlux;
    const double notInjecting = render(off).injection.rsmFlux;
    std::cout << "[ particles ] " << draw << ": RSM flux " << injecting << " W injecting, " << notInjecting
              << " W not, " << bare << " W without particles\n";
    ASSERT_GT(bare, 0.0);
    EXPECT_NEAR(notInjecting, bare, 1e-5 * bare) << draw;
    EXPECT_GT(std::abs(injecting - bare), 1e-3 * bare) << draw << ": the particles change nothing injected";
  }
}

// A sweep's summary.csv counts each run's particles over its systems and names the first system's
// drawing even where no sweep sets it (the report's particle sections need it); a sweep without
// particles has no such columns.
TEST(Particles, TheSweepSummaryHasTheirCountsAndDrawing) {
  test::TempDir dir;
  const auto write = [&](const std::string& id, nlohmann::json manifest) {  // one timed repeat
    manifest["timing"] = {{"samples", {{"stage_ms", {{"total", {12.5}}}}}}};
    std::filesystem::create_directories(dir.path() / id);
    std::ofstream(dir.path() / id / "manifest.json") << manifest.dump();
  };
  const auto table = [&]() {
    test::writeSweepIndex(dir.path(), {"a", "b"});
    writeSweepSummary(dir.path().string());
    std::ifstream csv(dir.path() / "summary.csv");
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(csv, line);) {
      rows.emplace_back();
      std::stringstream fields(line);
      for (std::string field; std::getline(fields, field, ',');) rows.back().push_back(field);
      if (!line.empty() && line.back() == ',') rows.back().push_back("");
    }
    return rows;
  };
  const auto column = [](const std::vector<std::vector<std::string>>& rows, const std::string& name) {
    const auto at = std::find(rows.at(0).begin(), rows.at(0).end(), name);
    return at == rows[0].end() ? -1 : int(at - rows[0].begin());
  };
  write("a", {{"configuration", {{"grid", {{"resolution", 32}}}}}});
  std::vector<std::vector<std::string>> rows = table();
  EXPECT_EQ(column(rows, "param.particles[0].draw"), -1);
  EXPECT_EQ(column(rows, "particles.alive"), -1);

  // A run with particle systems names their drawing among its summary keys (run_outputs.cpp).
  write("b", {{"configuration", {{"particles", {{{"draw", "light_field"}}, {{"draw", "geometry"}}}}}},
              {"summary_keys", {"indirect.method", "scene.file", "particles[0].draw"}},
              {"particles", {{{"alive_at_frame_0", 10}, {"capacity", 20}, {"triangles", 160}},
                             {{"alive_at_frame_0", 5}, {"capacity", 6}, {"triangles", 48}}}}});
  rows = table();
  ASSERT_EQ(rows.size(), 3u);  // header, a, b
  const int draw = column(rows, "param.particles[0].draw"), alive = column(rows, "particles.alive"),
            triangles = column(rows, "particles.triangles");
  ASSERT_GE(draw, 0);
  ASSERT_GE(alive, 0);
  ASSERT_GE(triangles, 0);
  EXPECT_EQ(rows[1].at(std::size_t(draw)), "");
  EXPECT_EQ(rows[2].at(std::size_t(draw)), "light_field");
  EXPECT_EQ(std::stod(rows[2].at(std::size_t(alive))), 15.0);
  EXPECT_EQ(std::stod(rows[2].at(std::size_t(triangles))), 208.0);
}

// One crystal, 0.2 m, still, unturned, in the middle of the box, at frame 0, in a 192^2 image.
std::vector<std::string> oneParticle(const std::string& draw) {
  return smallFrame({"particles[0].emitters[0].rate=0.01", "particles[0].emitters[0].lifetime=100.0",
                     "particles[0].emitters[0].lifetime_variation=0.0", "particles[0].emitters[0].speed=0.0",
                     "particles[0].emitters[0].speed_variation=0.0", "particles[0].emitters[0].radius=0.0",
                     "particles[0].emitters[0].position=[0.28, 0.2, 0.3]", "particles[0].gravity=[0.0, 0.0, 0.0]",
                     "particles[0].prewarm=0.0", "particles[0].random_rotation=false", "particles[0].spin_deg=0.0",
                     "particles[0].over_life[0].size=0.2", "particles[0].over_life[1].size=0.2",
                     "particles[0].draw=" + draw, "output.width=192", "output.height=192"});
}

TEST(Particles, ALightFieldParticleLooksAndIsLitLikeItsGeometry) {
  std::vector<std::string> lightField = oneParticle("light_field");
  lightField.insert(lightField.end(), {"particles[0].azimuths=32", "particles[0].elevations=16",
                                       "particles[0].resolution=128"});
  const Frame geometry = render(oneParticle("geometry"));
  const Frame field = render(lightField);
  // The crystal's albedo times the particle's colour (the file's colour key at birth): the
  // geometry's vertex colours and the billboard's tint.
  const Experiment& e = geometry.experiment;
  const std::vector<Particle> alive = particlesAt(e.particles[0].system(), e.animation.frameTime(0));
  ASSERT_EQ(alive.size(), 1u);
  const glm::vec3 crystal =
      e.scene.materials[std::size_t(e.scene.meshes[std::size_t(e.particles[0].firstMesh())].material)].baseColor *
      glm::vec3(alive[0].color);
  ASSERT_GT(glm::length(glm::vec3(alive[0].color) - glm::vec3(1.0f)), 0.1f);  // a colour, not white
  const Image& ga = findAov(geometry.outputs, "albedo");
  const Image& fa = findAov(field.outputs, "albedo");
  int both = 0, either = 0;
  double directG = 0, directF = 0, indirectG = 0, indirectF = 0;
  for (int y = 0; y < ga.height; ++y)
    for (int x = 0; x < ga.width; ++x) {
      const auto isCrystal = [&](const Image& a) {
        return glm::length(glm::vec3(a.at(x, y, 0), a.at(x, y, 1), a.at(x, y, 2)) - crystal) < 0.02f;
      };
      const bool g = isCrystal(ga), f = isCrystal(fa);
      either += g || f;
      if (!(g && f)) continue;
      ++both;
      for (int c = 0; c < 3; ++c) {
        directG += findAov(geometry.outputs, "direct").at(x, y, c);
        directF += findAov(field.outputs, "direct").at(x, y, c);
        indirectG += findAov(geometry.outputs, "indirect").at(x, y, c);
        indirectF += findAov(field.outputs, "indirect").at(x, y, c);
      }
    }
  std::cout << "[ particles ] light field against geometry: " << both << " pixels in both of " << either
            << " in either; direct " << directF / std::max(directG, 1e-30) << " x, indirect "
            << indirectF / std::max(indirectG, 1e-30) << " x the geometry's over the common pixels\n";
  ASSERT_GT(either, 100);
  EXPECT_GE(double(both) / either, 0.85);            // coverage: the silhouettes agree but at edges
  EXPECT_NEAR(directF / directG, 1.0, 0.1);          // blended normals and the billboard's shadow
  EXPECT_NEAR(indirectF / indirectG, 1.0, 0.1);      // the same grid, read at the same points
}

// The light grid's cells hold intensity I(w) = I0 + I1 a.w (W/sr, light travelling along w), the
// same in every cell. Its SH coefficients in closed form (sh.glsl's basis: Y00 = 1 / (2 sqrt(pi)),
// (Y1-1, Y10, Y11) = sqrt(3 / (4 pi)) (-y, z, -x)): c0 = 2 sqrt(pi) I0, c1m = I1 <a.w, Y1m> with
// <w_j, Y1m> = (4 pi / 3) of Y1m's factor of w_j. A surface with normal n receives
// E = integral I(w) max(0, -w.n) dw = pi I0 - (2 pi / 3) I1 a.n, and a Lambertian one of albedo
// rho sends rho E / (pi s^2) (the grid's intensity spread over a cell's face s^2: sh.glsl).
struct LinearIntensity {
  glm::dvec3 i0, i1;  // per channel
  glm::dvec3 a;       // unit
  std::vector<double> coefficients(int channel, int count) const {
    const double y1 = 0.5 * std::sqrt(3.0 / M_PI), toBand1 = 4.0 * M_PI / 3.0 * y1;
    std::vector<double> c(std::size_t(count), 0.0);
    c[0] = 2.0 * std::sqrt(M_PI) * i0[channel];
    c[1] = -toBand1 * i1[channel] * a.y;
    c[2] = toBand1 * i1[channel] * a.z;
    c[3] = -toBand1 * i1[channel] * a.x;
    return c;
  }
  glm::dvec3 radiance(glm::dvec3 albedo, glm::dvec3 n, double cellSize) const {
    return albedo * (i0 - 2.0 / 3.0 * i1 * glm::dot(a, n)) / (cellSize * cellSize);
  }
};

TEST(Particles, ALightFieldParticleInAUniformGridGetsTheClosedFormRadiance) {
  test::glTestContext();
  ShaderCompiler shaders;
  const ParticleModel model = test::crystalModel();
  Scene modelScene;
  modelScene.meshes = model.meshes;
  modelScene.materials = model.materials;
  const test::SceneRaycaster caster(modelScene);
  const SceneGpu gpu(test::nothingInView());

  Particle particle;
  particle.position = {0.4, 1.1, 2.3};
  particle.size = 0.5;
  particle.orientation = glm::angleAxis(0.7, glm::normalize(glm::dvec3(0.3, -1.0, 0.5)));
  particle.color = {0.6, 0.9, 0.5};  // the billboard's tint multiplies the captured albedo
  const GridGeometry geometry{glm::vec3(-0.6f, 0.1f, 1.3f), 0.25f, glm::ivec3(8)};
  const LinearIntensity light{.i0 = {2e-3, 1.2e-3, 0.7e-3}, .i1 = {1.5e-3, 1.0e-3, 0.2e-3},
                              .a = glm::normalize(glm::dvec3(0.4, -1.0, 0.3))};
  const int resolution = 40;
  const double distance = 1000.0;
  for (bool interpolate : {false, true}) {
    const ParticleDrawing drawing{.lightField = true, .views = {8, 4}, .resolution = resolution,
                                  .interpolate = interpolate};
    ParticleBillboards billboards(model, drawing, 1, shaders);
    billboards.update({particle});
    const double halfWidth = particle.size * billboards.lightField().radius();
    GBufferPass pass(shaders, resolution, resolution, false);
    for (int order = 1; order <= 2; ++order) {
      test::HandGrid grid(geometry, order);
      grid.fill([&](glm::ivec3, int channel, std::vector<double>& c) {
        c = light.coefficients(channel, grid.coefficients());
      });
      int pixels = 0, agree = 0, compared = 0, close = 0;
      for (const auto& [i, j] : {std::pair{1, 1}, std::pair{4, 2}, std::pair{7, 0}}) {
        // The view's direction and up vector in object space, turned into the world.
        const glm::dvec3 d = particle.orientation * shared::lightFieldViewDirection(i, j, drawing.views);
        const glm::dvec3 up = particle.orientation * shared::lightFieldUp(shared::lightFieldViewDirection(i, j, drawing.views));
        Camera camera;
        camera.position = glm::vec3(particle.position + distance * d);
        camera.forward = glm::vec3(-d);
        camera.up = glm::vec3(up);
        camera.verticalFov = float(2.0 * std::atan(halfWidth / distance));
        camera.nearPlane = float(distance - 2.0);
        camera.farPlane = float(distance + 2.0);
        pass.render(gpu, camera, {&billboards});
        const std::vector<glm::dvec3> out =
            test::renderGBuffer("trilinear", {}, {grid}, pass.gbuffer(), camera);
        std::vector<float> covered(std::size_t(resolution) * resolution * 4);
        glGetTextureImage(pass.gbuffer().position.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(covered.size() * sizeof(float)),
                          covered.data());
        // Each pixel's centre ray, into the model's frame (centred, largest extent 1).
        const glm::dvec3 eye(camera.position), forward(camera.forward);
        const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
        const glm::dvec3 cameraUp = glm::cross(right, forward);
        const double tanHalf = std::tan(0.5 * double(camera.verticalFov));
        const glm::dquat toObject = glm::conjugate(particle.orientation);
        for (int y = 0; y < resolution; ++y)
          for (int x = 0; x < resolution; ++x) {
            const std::size_t p = std::size_t(y) * resolution + std::size_t(x);
            const glm::dvec3 ray = glm::normalize(forward + tanHalf * ((2.0 * (x + 0.5) / resolution - 1.0) * right +
                                                                       (2.0 * (y + 0.5) / resolution - 1.0) * cameraUp));
            const auto hit = caster.cast(toObject * (eye - particle.position) / particle.size, toObject * ray);
            const bool seen = covered[4 * p + 3] > 0.5f;
            ++pixels;
            agree += seen == bool(hit);
            if (!hit || !seen) continue;
            ++compared;
            glm::dvec3 n = particle.orientation * hit->normal;
            if (glm::dot(n, ray) > 0.0) n = -n;
            const glm::dvec3 expected =
                light.radiance(glm::dvec3(caster.material(*hit).baseColor) * particle.color, n,
                               double(geometry.cellSize));
            close += glm::length(out[p] - expected) < 5e-3 * glm::length(expected);
          }
      }
      std::cout << "[ particles ] uniform grid, order " << order << (interpolate ? ", interpolated" : ", nearest")
                << ": coverage as the rays' at " << agree << " of " << pixels << " pixels, radiance within 0.5 % of"
                << " the closed form at " << close << " of " << compared << "\n";
      EXPECT_GT(compared, pixels / 10);
      EXPECT_GE(agree, pixels - pixels / 50);      // edge pixels only
      EXPECT_GE(close, compared - compared / 50);  // a pixel whose ray grazes a ridge shows either face
    }
  }
}

}  // namespace
}  // namespace lpvlab

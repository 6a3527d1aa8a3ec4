// Particle systems through the LPV pipeline (experiments/particles_cornell.toml, docs/particles.md),
// against a brute-force double-precision ray caster over the same scene:
//   a. the G-buffer sees a particle at exactly the pixels whose centre ray first hits one;
//   b. the particles cast shadows: floor pixels whose shadow ray to the spot light is blocked
//      only by particles get less direct light than without the particles;
//   c. a sequence moves them: every frame's record counts the live particles and has a scene
//      hash of its own, and its images stay finite;
//   d. one large particle drawn as a light field and as geometry covers the same pixels and gets
//      the same direct and indirect light, within the tolerances the test states.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "framework/experiment/experiment.h"
#include "framework/experiment/run.h"
#include "framework/particles/particle_billboards.h"
#include "framework/pipeline/pipeline.h"
#include "io/temp_dir.h"
#include "pipeline_test_support.h"

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
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.strategies), shaders);
  const ParticleBillboardSet billboards(e.particles, e.animation.frameTime(0), shaders, pipeline);
  pipeline.renderFrame();
  f.outputs = pipeline.readOutputs();
  return f;
}

bool isParticle(const Experiment& e, int mesh) {
  for (const ParticleGeometry& p : e.particles)
    if (mesh >= p.firstMesh() && mesh < p.firstMesh() + p.meshCount()) return true;
  return false;
}

TEST(Particles, TheGBufferSeesThemWhereRaysFirstHitThem) {
  const Frame f = render(smallFrame({"particles[0].draw=geometry"}));
  const Experiment& e = f.experiment;
  ASSERT_EQ(e.particles.size(), 1u);
  const test::SceneRaycaster caster(e.scene);
  const Image& albedo = findAov(f.outputs, "albedo");
  const glm::vec3 crystal = e.scene.materials[std::size_t(e.scene.meshes[std::size_t(e.particles[0].firstMesh())].material)].baseColor;
  int particlePixels = 0, agree = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const glm::dvec3 ray = test::cameraRay(e.camera, kSize, kSize, x, y);
      const auto hit = caster.cast(glm::dvec3(e.camera.position), ray);
      const bool expected = hit && isParticle(e, hit->mesh);
      const glm::vec3 a(albedo.at(x, y, 0), albedo.at(x, y, 1), albedo.at(x, y, 2));
      const bool seen = glm::length(a - crystal) < 1e-3f;
      particlePixels += expected;
      agree += expected == seen;
    }
  std::cout << "[ particles ] " << particlePixels << " of " << kSize * kSize
            << " pixels show a particle; the G-buffer agrees with the ray caster at " << agree << "\n";
  EXPECT_GT(particlePixels, 20);
  // Rasterisation samples pixel centres too: only pixels whose centre grazes an edge may differ.
  EXPECT_GE(agree, kSize * kSize - kSize / 8);
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
  const glm::vec3 crystal = geometry.experiment.scene.materials[std::size_t(
      geometry.experiment.scene.meshes[std::size_t(geometry.experiment.particles[0].firstMesh())].material)].baseColor;
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

}  // namespace
}  // namespace lpvlab

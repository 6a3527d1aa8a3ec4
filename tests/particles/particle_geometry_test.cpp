// Particles placed into a scene as copies of their model: each live particle's copy is the model
// centred, scaled to its size, turned and moved to its position (checked vertex by vertex against
// the particle), empty slots cover no area, a particle keeps its slot for its whole life, and the
// model's problems (a mesh it lacks, no extent, emission, too many triangles) are named errors;
// with colour keys each copy's vertex colours are its particle's colour at the life it has lived.

#include "framework/particles/particle_geometry.h"

#include <gtest/gtest.h>

#include <map>

#include "error_support.h"

namespace lpvlab {
namespace {

using test::contains;
using test::errorOf;

// A model file: one triangle 2 m wide (so the normalised model is half as large) and a quad.
Scene modelFile() {
  Scene file;
  file.source = "model.obj";
  file.materials.push_back(Material{.name = "red", .baseColor = glm::vec3(0.8f, 0.1f, 0.1f)});
  Mesh tri;
  tri.name = "tri";
  tri.positions = {{1, 1, 1}, {3, 1, 1}, {1, 2, 1}};
  tri.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  tri.uvs.resize(3);
  tri.indices = {0, 1, 2};
  file.meshes.push_back(tri);
  Mesh quad = tri;
  quad.name = "quad";
  quad.positions = {{1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
  quad.normals.assign(4, glm::vec3(0, 0, 1));
  quad.uvs.resize(4);
  quad.indices = {0, 1, 2, 0, 2, 3};
  file.meshes.push_back(quad);
  return file;
}

ParticleSystem system() {
  ParticleSystem s;
  s.name = "test";
  s.gravity = {0, -1, 0};
  s.spin = 1.0;
  s.size = 0.3;
  s.color = {0.5, 1.0, 1.0};
  Emitter e;
  e.position = {5, 5, 5};
  e.spread = 1.0;
  e.rate = 30;
  e.lifetime = 0.4;
  e.lifetimeVariation = 0.1;
  s.emitters.push_back(e);
  e.position = {-5, 0, 0};
  e.rate = 7;
  s.emitters.push_back(e);
  return s;
}

double area(const Mesh& mesh, std::size_t triangle) {
  const glm::vec3 a = mesh.positions[mesh.indices[3 * triangle]];
  const glm::vec3 b = mesh.positions[mesh.indices[3 * triangle + 1]];
  const glm::vec3 c = mesh.positions[mesh.indices[3 * triangle + 2]];
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

TEST(ParticleGeometry, TheModelIsCentredAndItsLargestExtentIsOne) {
  const ParticleModel model = particleModel(modelFile(), {});
  ASSERT_EQ(model.meshes.size(), 2u);
  EXPECT_EQ(model.materials.size(), 1u);  // both meshes share the file's one material
  Bounds b;
  for (const Mesh& m : model.meshes)
    for (const glm::vec3& p : m.positions) b.extend(p);
  EXPECT_NEAR(glm::length(b.center()), 0.0, 1e-6);
  EXPECT_NEAR(b.extent().x, 1.0, 1e-6);  // 2 m wide
  EXPECT_NEAR(b.extent().y, 0.5, 1e-6);
  EXPECT_EQ(particleModel(modelFile(), {"quad"}).meshes.size(), 1u);
}

TEST(ParticleGeometry, EveryLiveParticleIsItsModelScaledTurnedAndMoved) {
  Scene scene;
  scene.materials.push_back(Material{});
  const ParticleModel model = particleModel(modelFile(), {"tri"});
  const ParticleGeometry geometry(system(), model, scene, 0.0, 1'000'000);
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_NEAR(scene.materials[1].baseColor.x, 0.4f, 1e-6f);  // the colour multiplies the albedo
  const Mesh& mesh = scene.meshes[0];
  const std::size_t capacity = geometry.system().capacity();
  ASSERT_EQ(mesh.indices.size(), 3 * capacity);

  for (double t : {0.0, 0.37, 2.0, 5.55}) {
    const std::size_t alive = geometry.place(scene, t);
    const std::vector<Particle> particles = particlesAt(geometry.system(), t);
    ASSERT_EQ(alive, particles.size());
    // Each particle is found in exactly one slot, vertex for vertex.
    std::size_t covered = 0;
    for (std::size_t s = 0; s < capacity; ++s) covered += area(mesh, s) > 0.0;
    EXPECT_EQ(covered, particles.size()) << t;
    for (const Particle& p : particles) {
      const glm::dmat3 r = glm::mat3_cast(p.orientation);
      bool found = false;
      for (std::size_t s = 0; s < capacity && !found; ++s) {
        const glm::vec3 expected = glm::vec3(p.position + p.size * (r * glm::dvec3(model.meshes[0].positions[0])));
        if (glm::length(mesh.positions[3 * s] - expected) > 1e-5f) continue;
        found = true;
        for (int v = 0; v < 3; ++v) {
          const glm::dvec3 x = p.position + p.size * (r * glm::dvec3(model.meshes[0].positions[std::size_t(v)]));
          EXPECT_LT(glm::length(glm::dvec3(mesh.positions[3 * s + std::size_t(v)]) - x), 1e-5);
          EXPECT_LT(glm::length(glm::dvec3(mesh.normals[3 * s + std::size_t(v)]) - r * glm::dvec3(0, 0, 1)), 1e-5);
        }
      }
      EXPECT_TRUE(found) << "particle " << p.index << " at " << t << " s";
    }
  }
}

TEST(ParticleGeometry, AParticleKeepsItsSlotForItsWholeLife) {
  Scene scene;
  const ParticleModel model = particleModel(modelFile(), {"tri"});
  ParticleSystem s = system();
  s.spin = 0.0;
  s.randomRotation = false;
  const ParticleGeometry geometry(s, model, scene, 0.0, 1'000'000);
  const std::size_t capacity = geometry.system().capacity();
  std::map<std::int64_t, std::size_t> slotOf;  // emitter 0's births
  for (double t = 0.0; t < 1.0; t += 0.01) {
    geometry.place(scene, t);
    for (const Particle& p : particlesAt(geometry.system(), t)) {
      if (p.emitter != 0) continue;
      const glm::vec3 first = glm::vec3(p.position + p.size * glm::dvec3(model.meshes[0].positions[0]));
      std::size_t slot = capacity;
      for (std::size_t i = 0; i < capacity; ++i)
        if (glm::length(scene.meshes[0].positions[3 * i] - first) < 1e-5f) slot = i;
      ASSERT_LT(slot, capacity);
      const auto [it, inserted] = slotOf.emplace(p.index, slot);
      EXPECT_EQ(it->second, slot) << "particle " << p.index << " moved slots at " << t << " s";
    }
  }
  EXPECT_GT(slotOf.size(), 20u);
}

TEST(ParticleGeometry, TheModelsTexturesComeAlongRenumbered) {
  Scene file = modelFile();
  file.textures.push_back(TextureImage{.path = "unused.png"});
  file.textures.push_back(TextureImage{.path = "bark.png"});
  file.materials[0].baseColorTexture = 1;
  const ParticleModel model = particleModel(file, {});
  ASSERT_EQ(model.textures.size(), 1u);  // only the one its materials use
  Scene scene;
  scene.textures.push_back(TextureImage{.path = "wall.png"});
  scene.materials.push_back(Material{.baseColorTexture = 0});
  const ParticleGeometry geometry(system(), model, scene, 0.0, 1'000'000);
  const Material& particle = scene.materials.at(std::size_t(scene.meshes.at(0).material));
  ASSERT_GE(particle.baseColorTexture, 0);
  EXPECT_EQ(scene.textures.at(std::size_t(particle.baseColorTexture)).path, "bark.png");
  EXPECT_EQ(scene.textures.at(0).path, "wall.png");
}

TEST(ParticleGeometry, TheModelsProblemsAreNamedErrors) {
  EXPECT_TRUE(contains(errorOf([] { particleModel(modelFile(), {"sphere"}); }), "no mesh 'sphere'"));
  Scene flat = modelFile();
  for (Mesh& m : flat.meshes) m.positions.assign(m.positions.size(), glm::vec3(1.0f));
  EXPECT_TRUE(contains(errorOf([&] { particleModel(flat, {}); }), "no extent"));
  Scene glowing = modelFile();
  glowing.materials[0].emission = glm::vec3(1.0f);
  EXPECT_TRUE(contains(errorOf([&] { particleModel(glowing, {}); }), "emits light"));

  const ParticleModel model = particleModel(modelFile(), {});
  Scene scene;
  EXPECT_TRUE(contains(errorOf([&] { ParticleGeometry(system(), model, scene, 0.0, 10); }),
                       "lower the emitters' rate"));
}

// Colour keys from red at birth to blue at death: every live particle's copy has, at each of its
// vertices, (1 - f, 0, f) for the fraction f of its life lived (the closed form of the two keys),
// and the material keeps the model's albedo (the colour is the vertices', not multiplied twice).
TEST(ParticleGeometry, ColourKeysColourEachCopyByTheLifeItHasLived) {
  Scene scene;
  const ParticleModel model = particleModel(modelFile(), {"quad"});
  ParticleSystem keyed = system();
  keyed.colorOverLife = KeyframeTrack<glm::dvec3>({0.0, 1.0}, {glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1)},
                                                  Interpolation::Linear);
  const ParticleGeometry geometry(keyed, model, scene, 0.0, 1'000'000);
  ASSERT_TRUE(geometry.colouredPerParticle());
  const Mesh& mesh = scene.meshes.at(0);
  ASSERT_EQ(mesh.colors.size(), mesh.positions.size());
  EXPECT_EQ(scene.materials.at(std::size_t(mesh.material)).baseColor, glm::vec3(0.8f, 0.1f, 0.1f));
  const std::size_t capacity = geometry.system().capacity();
  std::size_t checked = 0;
  for (double t : {0.0, 0.21, 1.7}) {
    geometry.place(scene, t);
    for (const Particle& p : particlesAt(geometry.system(), t)) {
      const double f = p.age / p.lifetime;
      const glm::vec3 expected(float(1.0 - f), 0.0f, float(f));
      const glm::vec3 first = glm::vec3(p.position + p.size * (glm::mat3_cast(p.orientation) *
                                                               glm::dvec3(model.meshes[0].positions[0])));
      std::size_t slot = capacity;
      for (std::size_t i = 0; i < capacity; ++i)
        if (glm::length(mesh.positions[4 * i] - first) < 1e-5f) slot = i;
      ASSERT_LT(slot, capacity) << "particle " << p.index << " at " << t << " s";
      for (std::size_t v = 0; v < 4; ++v)
        EXPECT_LT(glm::length(mesh.colors[4 * slot + v] - expected), 1e-6f) << p.index << " at " << t << " s";
      ++checked;
    }
  }
  EXPECT_GT(checked, 20u);
}

}  // namespace
}  // namespace lpvlab

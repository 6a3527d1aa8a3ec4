#include "framework/particles/particle_geometry.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "framework/core/error.h"

namespace lpvlab {

std::size_t ParticleModel::triangleCount() const {
  std::size_t count = 0;
  for (const Mesh& mesh : meshes) count += mesh.indices.size() / 3;
  return count;
}

ParticleModel particleModel(const Scene& file, const std::vector<std::string>& meshNames) {
  ParticleModel model;
  model.source = file.source;
  std::vector<int> materialOf(file.materials.size(), -1);  // file material -> model material
  std::vector<int> textureOf(file.textures.size(), -1);    // file texture -> model texture
  for (const std::string& name : meshNames)
    if (std::none_of(file.meshes.begin(), file.meshes.end(), [&](const Mesh& m) { return m.name == name; })) {
      std::string names;
      for (const Mesh& m : file.meshes) names += (names.empty() ? "" : ", ") + m.name;
      throw Error("the model " + file.source + " has no mesh '" + name + "' (it has: " + names + ")");
    }
  for (const Mesh& mesh : file.meshes) {
    if (!meshNames.empty() && std::find(meshNames.begin(), meshNames.end(), mesh.name) == meshNames.end())
      continue;
    const Material& material = file.materials.at(std::size_t(mesh.material));
    if (material.emits())
      throw Error("the model " + file.source + ": mesh '" + mesh.name + "' emits light (material '" +
                  material.name + "'); particles that are lights are not supported");
    int& index = materialOf[std::size_t(mesh.material)];
    if (index < 0) {
      index = int(model.materials.size());
      model.materials.push_back(material);
      if (material.baseColorTexture >= 0) {  // the model keeps the textures it uses, renumbered
        int& texture = textureOf[std::size_t(material.baseColorTexture)];
        if (texture < 0) {
          texture = int(model.textures.size());
          model.textures.push_back(file.textures.at(std::size_t(material.baseColorTexture)));
        }
        model.materials.back().baseColorTexture = texture;
      }
    }
    model.meshes.push_back(mesh);
    model.meshes.back().material = index;
  }
  Bounds bounds;
  for (const Mesh& mesh : model.meshes)
    for (const glm::vec3& p : mesh.positions) bounds.extend(p);
  const float largest = bounds.empty() ? 0.0f : glm::max(glm::max(bounds.extent().x, bounds.extent().y), bounds.extent().z);
  if (!(largest > 0.0f))
    throw Error("the model " + file.source + " has no extent (no triangles, or all at one point)");
  const glm::vec3 centre = bounds.center();
  for (Mesh& mesh : model.meshes)
    for (glm::vec3& p : mesh.positions) p = (p - centre) / largest;
  return model;
}

ParticleGeometry::ParticleGeometry(ParticleSystem system, const ParticleModel& model, Scene& scene,
                                   double seconds, std::size_t maxTriangles, ParticleDrawing drawing)
    : system_(std::move(system)), model_(model), drawing_(drawing) {
  const std::string what = "particle system '" + system_.name + "'";
  const std::size_t capacity = system_.capacity();
  if (capacity * model_.triangleCount() > maxTriangles)
    throw Error(what + ": up to " + std::to_string(capacity) + " particles of " +
                std::to_string(model_.triangleCount()) + " triangles each exceed the " +
                std::to_string(maxTriangles) +
                " triangles particles may add: lower the emitters' rate or lifetime, or use a "
                "model with fewer triangles");
  std::size_t slot = 0;
  for (std::size_t e = 0; e < system_.emitters.size(); ++e) {
    emitterSlot_.push_back(slot);
    slot += system_.capacity(int(e));
  }

  const int firstMaterial = int(scene.materials.size());
  const int firstTexture = int(scene.textures.size());
  scene.textures.insert(scene.textures.end(), model_.textures.begin(), model_.textures.end());
  for (Material material : model_.materials) {
    material.name = "particles:" + system_.name + ":" + material.name;
    if (!colouredPerParticle()) material.baseColor *= glm::vec3(system_.color);
    material.injects = drawing_.inject;
    if (material.baseColorTexture >= 0) material.baseColorTexture += firstTexture;
    scene.materials.push_back(material);
  }
  firstMesh_ = int(scene.meshes.size());
  for (const Mesh& part : model_.meshes) {
    Mesh mesh;
    mesh.name = "particles:" + system_.name + ":" + part.name;
    mesh.material = firstMaterial + part.material;
    mesh.rasterised = !drawing_.lightField;  // billboards draw them in the LPV pipeline
    const std::size_t vertices = part.positions.size();
    mesh.positions.resize(capacity * vertices);
    mesh.normals.resize(capacity * vertices, glm::vec3(0, 1, 0));
    mesh.uvs.resize(capacity * vertices);
    if (colouredPerParticle()) mesh.colors.resize(capacity * vertices, glm::vec3(1.0f));
    mesh.indices.reserve(capacity * part.indices.size());
    for (std::size_t s = 0; s < capacity; ++s) {
      for (std::size_t v = 0; v < vertices; ++v) mesh.uvs[s * vertices + v] = part.uvs.at(v);
      for (std::uint32_t index : part.indices) mesh.indices.push_back(std::uint32_t(s * vertices + index));
    }
    scene.meshes.push_back(std::move(mesh));
  }
  place(scene, seconds);
}

std::size_t ParticleGeometry::place(Scene& scene, double seconds) const {
  const std::vector<Particle> particles = particlesAt(system_, seconds);
  const std::size_t capacity = system_.capacity();
  // Which particle each slot holds this frame (-1: empty).
  std::vector<int> occupant(capacity, -1);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Particle& p = particles[i];
    const std::int64_t slots = std::int64_t(system_.capacity(p.emitter));
    const std::int64_t local = ((p.index % slots) + slots) % slots;  // k may be negative (prewarm)
    occupant[emitterSlot_[std::size_t(p.emitter)] + std::size_t(local)] = int(i);
  }
  std::vector<int> emitterOfSlot(capacity);
  for (std::size_t e = 0; e < emitterSlot_.size(); ++e)
    std::fill(emitterOfSlot.begin() + std::ptrdiff_t(emitterSlot_[e]),
              emitterOfSlot.begin() + std::ptrdiff_t(emitterSlot_[e] + system_.capacity(int(e))), int(e));
  for (std::size_t m = 0; m < model_.meshes.size(); ++m) {
    const Mesh& part = model_.meshes[m];
    Mesh& mesh = scene.meshes.at(std::size_t(firstMesh_) + m);
    const std::size_t vertices = part.positions.size();
    tbb::parallel_for(std::size_t(0), capacity, [&](std::size_t s) {
      glm::vec3* positions = mesh.positions.data() + s * vertices;
      glm::vec3* normals = mesh.normals.data() + s * vertices;
      glm::vec3* colors = mesh.colors.empty() ? nullptr : mesh.colors.data() + s * vertices;
      if (occupant[s] < 0) {  // empty: collapsed onto its emitter's centre
        const glm::vec3 centre(system_.emitters[std::size_t(emitterOfSlot[s])].position);
        std::fill(positions, positions + vertices, centre);
        std::fill(normals, normals + vertices, glm::vec3(0, 1, 0));
        return;
      }
      const Particle& p = particles[std::size_t(occupant[s])];
      const glm::dmat3 rotation = glm::mat3_cast(p.orientation);
      for (std::size_t v = 0; v < vertices; ++v) {
        positions[v] = glm::vec3(p.position + p.size * (rotation * glm::dvec3(part.positions[v])));
        normals[v] = glm::vec3(glm::normalize(rotation * glm::dvec3(part.normals[v])));
      }
      if (colors) std::fill(colors, colors + vertices, glm::clamp(glm::vec3(p.color), 0.0f, 1.0f));
    });
  }
  return particles.size();
}

}  // namespace lpvlab

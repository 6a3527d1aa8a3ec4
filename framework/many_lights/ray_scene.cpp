#include "framework/many_lights/ray_scene.h"

namespace lpvlab {

RayScene::RayScene(const Scene& scene, const RayEngineSettings& engine)
    : engine_(engine), scene_(scene) {
  build();
}

void RayScene::build() {
  embree_.reset();  // before the materials it points into
  materials_ = prepareMaterials(scene_);
  embree_ = std::make_unique<EmbreeScene>(scene_, materials_, engine_);
  lights_ = std::make_unique<LightSampler>(scene_, materials_);
  bounds_ = scene_.bounds();
}

void RayScene::moveLights(const Scene& scene) {
  scene_.lights = scene.lights;
  lights_ = std::make_unique<LightSampler>(scene_, materials_);
}

void RayScene::moveGeometry(const Scene& scene) {
  scene_.lights = scene.lights;
  for (std::size_t i = 0; i < scene_.meshes.size() && i < scene.meshes.size(); ++i) {
    scene_.meshes[i].positions = scene.meshes[i].positions;
    scene_.meshes[i].normals = scene.meshes[i].normals;
    scene_.meshes[i].colors = scene.meshes[i].colors;  // a particle's colour over its life
  }
  stale_ = true;
}

void RayScene::update() {
  if (stale_) build();
  stale_ = false;
}

std::size_t RayScene::memoryBytes() const {
  std::size_t bytes = 0;
  for (const Mesh& mesh : scene_.meshes)
    bytes += mesh.positions.size() * sizeof(glm::vec3) + mesh.normals.size() * sizeof(glm::vec3) +
             mesh.uvs.size() * sizeof(glm::vec2) + mesh.colors.size() * sizeof(glm::vec3) +
             mesh.indices.size() * sizeof(std::uint32_t);
  for (const TextureImage& texture : scene_.textures) bytes += texture.rgba8.size();
  return bytes;
}

}  // namespace lpvlab

#include "framework/radiosity/patch_ray_scene.h"

#include "framework/core/error.h"

namespace lpvlab {

PatchRayScene::PatchRayScene(const Scene& scene, const PatchMesh& mesh) {
  if (mesh.patches.empty()) throw Error(scene.source + ": radiosity: the scene has no patches (no triangle of non-zero area)");
  scene_.source = scene.source;
  scene_.materials = scene.materials;
  // Albedo is the patches' own (averaged over each): the copy needs neither textures nor masks.
  for (Material& m : scene_.materials) m.alphaMode = AlphaMode::Opaque, m.baseColorTexture = -1;
  scene_.meshes.resize(scene.meshes.size());
  firstPatch_.assign(scene.meshes.size(), 0);
  // Patches come grouped by mesh, in mesh order (meshPatches and splitPatches keep it).
  for (std::size_t p = 1; p < mesh.patches.size(); ++p)
    if (mesh.patches[p].mesh < mesh.patches[p - 1].mesh) throw Error("radiosity: patches are not grouped by mesh");
  for (std::size_t p = mesh.patches.size(); p-- > 0;) firstPatch_[std::size_t(mesh.patches[p].mesh)] = p;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    scene_.meshes[m].name = scene.meshes[m].name;
    scene_.meshes[m].material = scene.meshes[m].material;
  }
  for (const Patch& p : mesh.patches) {
    Mesh& out = scene_.meshes[std::size_t(p.mesh)];
    for (int k = 0; k < 3; ++k) {
      out.indices.push_back(std::uint32_t(out.positions.size()));
      out.positions.push_back(p.corners[k]);
      out.normals.push_back(p.normal);
      out.uvs.push_back(p.uv[k]);
    }
  }
  materials_ = prepareMaterials(scene_);
  embree_ = std::make_unique<EmbreeScene>(scene_, materials_);
}

std::size_t PatchRayScene::memoryBytes() const {
  std::size_t bytes = firstPatch_.size() * sizeof(std::size_t);
  for (const Mesh& m : scene_.meshes)
    bytes += m.positions.size() * (2 * sizeof(glm::vec3) + sizeof(glm::vec2)) + m.indices.size() * 4;
  return bytes;
}

}  // namespace lpvlab

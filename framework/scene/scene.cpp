#include "framework/scene/scene.h"

namespace lpvlab {

std::size_t Scene::triangleCount() const {
  std::size_t count = 0;
  for (const Mesh& mesh : meshes) count += mesh.indices.size() / 3;
  return count;
}

Bounds Scene::bounds() const {
  Bounds b;
  for (const Mesh& mesh : meshes)
    for (const glm::vec3& p : mesh.positions) b.extend(p);
  return b;
}

}  // namespace lpvlab

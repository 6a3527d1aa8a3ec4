#include <iostream>

#include "framework/cli/commands.h"
#include "framework/experiment/experiment.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab::cli {

namespace {

std::ostream& operator<<(std::ostream& out, const glm::vec3& v) {
  return out << "[" << v.x << ", " << v.y << ", " << v.z << "]";
}

}  // namespace

int infoCommand(const Options& options) {
  const Scene scene = loadSceneByName(resolveScenePath(options.experiment, ""));
  const Bounds bounds = scene.bounds();
  std::cout << "scene      " << scene.source << "\n"
            << "hash       " << sceneHash(scene) << "\n"
            << "triangles  " << scene.triangleCount() << " in " << scene.meshes.size() << " meshes\n"
            << "materials  " << scene.materials.size() << ", textures " << scene.textures.size() << "\n"
            << "bounds     " << bounds.min << " .. " << bounds.max << " (extent " << bounds.extent() << ")\n";
  for (const Light& l : scene.lights)
    std::cout << "light      " << l.name << ": type " << int(l.type) << " at " << l.position
              << " towards " << l.direction << ", intensity " << l.intensity << "\n";
  for (const Camera& c : scene.cameras)
    std::cout << "camera     " << c.name << ": at " << c.position << " looking " << c.forward
              << ", vertical fov " << glm::degrees(c.verticalFov) << " deg\n";
  return 0;
}

}  // namespace lpvlab::cli

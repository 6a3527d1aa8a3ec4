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
            << "bounds     " << bounds.min << " .. " << bounds.max << " m (extent " << bounds.extent()
            << " m)\n";
  // Each light as an experiment file's [[lights]] would give it, with the units of its quantities
  // (scene.h): positions in metres, a point or spot light's radiant intensity in W/sr, a
  // directional light's irradiance in W/m^2.
  for (const Light& l : scene.lights) {
    std::cout << "light      " << l.name << ": " << lightTypeName(l.type);
    if (l.type != LightType::Directional) std::cout << " at " << l.position << " m";
    if (l.type != LightType::Point) std::cout << " towards " << l.direction;
    if (l.type == LightType::Directional)
      std::cout << ", irradiance " << l.intensity << " W/m^2";
    else
      std::cout << ", intensity " << l.intensity << " W/sr";
    if (l.type == LightType::Spot)
      std::cout << ", cone half-angles " << glm::degrees(l.innerConeAngle) << " .. "
                << glm::degrees(l.outerConeAngle) << " deg";
    std::cout << ", colour " << l.color << " (linear RGB)\n";
  }
  for (const Camera& c : scene.cameras)
    std::cout << "camera     " << c.name << ": at " << c.position << " m looking " << c.forward
              << ", vertical fov " << glm::degrees(c.verticalFov) << " deg, clip " << c.nearPlane
              << " .. " << c.farPlane << " m\n";
  return 0;
}

}  // namespace lpvlab::cli

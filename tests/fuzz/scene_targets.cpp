// Fuzz target of scene files: Assimp's import and lpvlab's conversion of what it imported.

#include <string>

#include "framework/core/error.h"
#include "framework/scene/scene_loader.h"
#include "fuzz/fuzz_targets.h"
#include "fuzz/fuzz_workspace.h"

namespace lpvlab::fuzz {

void sceneFile(Bytes data, std::size_t size) {
  if (size == 0) return;
  const std::string name = data[0] % 2 == 0 ? "scene.obj" : "scene.gltf";
  const std::string path = FuzzWorkspace::instance().write(name, data + 1, size - 1);
  try {
    const Scene scene = loadScene(path);
    sceneHash(scene);
    scene.bounds();
  } catch (const Error&) {
  }
}

}  // namespace lpvlab::fuzz

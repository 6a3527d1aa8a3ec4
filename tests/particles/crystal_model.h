#pragma once
// The crystal of experiments/models/crystal.obj as a particle model, and a scene with nothing in
// view, for the GL tests of the light field and the billboards.

#include <filesystem>

#include "framework/particles/particle_geometry.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab::test {

inline ParticleModel crystalModel() {
  return particleModel(
      loadSceneByName((std::filesystem::path(LPVLAB_SOURCE_DIR) / "experiments/models/crystal.obj").string()), {});
}

// One triangle 500 m out, outside every test view: the G-buffer pass draws a scene, the billboards
// beside it.
inline Scene nothingInView() {
  Scene scene;
  scene.materials.push_back(Material{});
  scene.meshes.push_back(Mesh{.positions = {{-500, -500, -500}, {-501, -500, -500}, {-500, -501, -500}},
                              .normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}},
                              .uvs = {{0, 0}, {0, 0}, {0, 0}},
                              .indices = {0, 1, 2}});
  return scene;
}

}  // namespace lpvlab::test

#pragma once
// The crystal of experiments/models/crystal.obj as a particle model, for the GL tests of the
// light field and the billboards.

#include <filesystem>

#include "framework/particles/particle_geometry.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab::test {

inline ParticleModel crystalModel() {
  return particleModel(
      loadSceneByName((std::filesystem::path(LPVLAB_SOURCE_DIR) / "experiments/models/crystal.obj").string()), {});
}

}  // namespace lpvlab::test

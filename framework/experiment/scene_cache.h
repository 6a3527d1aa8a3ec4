#pragma once
// Each scene file read once: every experiment loaded through the cache gets a copy of it (the
// experiment adds its own lights and material overrides to the copy), so a fit of many
// renderings, or the check of a sweep's every configuration, reads Sponza once. Pass it as
// loadExperiment's SceneLoader.

#include <map>
#include <string>

#include "framework/scene/scene.h"

namespace lpvlab {

class SceneCache {
 public:
  Scene operator()(const std::string& resolvedPath);
  int loads() const { return int(scenes_.size()); }  // distinct files read

 private:
  std::map<std::string, Scene> scenes_;
};

}  // namespace lpvlab

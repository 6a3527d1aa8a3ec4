#include "framework/experiment/scene_cache.h"

#include "framework/scene/scene_loader.h"

namespace lpvlab {

Scene SceneCache::operator()(const std::string& resolvedPath) {
  auto found = scenes_.find(resolvedPath);
  if (found == scenes_.end())
    found = scenes_.emplace(resolvedPath, loadSceneByName(resolvedPath)).first;
  return found->second;
}

}  // namespace lpvlab

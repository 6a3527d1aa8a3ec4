#pragma once
// Views of an experiment under a command's table ([[fit.views]], [[tune.views]], their
// [[<owner>.held_out]]): each a name and experiment tables (scene, camera, lights, ...), each of
// which replaces the file's table whole, so that `lpvlab fit` and `lpvlab tune` measure the same
// configuration on several cameras and scenes.

#include <string>
#include <vector>

#include <toml++/toml.h>

namespace lpvlab {

struct NamedView {
  std::string name;
  toml::table keys;  // experiment tables of this view, replacing the file's
};

// `owner`'s array of tables `key` (`ownerName` names the owner in messages: "fit", "tune"); none
// when absent. Throws an Error naming the file, line and key for a view without a name, a name
// used twice, or a view holding `ownerName`'s own table or a [sweep].
std::vector<NamedView> readNamedViews(const toml::table& owner, const std::string& ownerName,
                                      const std::string& key, const std::string& file);

// `base` with the view's tables in place of its own.
toml::table withView(const toml::table& base, const NamedView& view);

}  // namespace lpvlab

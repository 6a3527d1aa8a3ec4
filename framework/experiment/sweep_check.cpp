#include "framework/experiment/sweep_check.h"

#include <functional>

#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/scene_cache.h"
#include "framework/reference/reference_cache.h"

namespace lpvlab {

std::vector<std::string> checkConfigurations(
    const toml::table& root, const std::string& file,
    const std::vector<SweepConfiguration>& configurations) {
  std::vector<std::string> referenceKeys;
  SceneCache scenes;
  std::string sweepWhere = file;
  if (const toml::node* sweep = root.get("sweep"); sweep && sweep->source().begin.line > 0)
    sweepWhere += ":" + std::to_string(sweep->source().begin.line);
  for (const SweepConfiguration& c : configurations) {
    toml::table table = root;
    table.erase("sweep");
    table.erase("fit");
    table.erase("tune");
    for (const std::string& o : c.overrides) applyOverride(table, o);
    try {
      const Experiment e = loadExperiment(table, file, std::ref(scenes));
      referenceKeys.push_back(e.compareWithReference ? referenceKey(e.scene, e.camera, e.reference)
                                                     : "");
    } catch (const Error& error) {
      throw Error(sweepWhere + ": key 'sweep': configuration " + c.name +
                  " fails: " + error.what());
    }
  }
  return referenceKeys;
}

}  // namespace lpvlab

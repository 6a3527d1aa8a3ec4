#pragma once
// An experiment: a scene (a file or the built-in Cornell box), the lights it adds, the camera, the
// output, the light grid's placement, the strategy of each stage with its parameters, and how to
// time. Read from a TOML file (see experiments/ for commented examples); without a file every
// key takes its default, which is the built-in Cornell box with standard LPV. Command-line
// overrides ("propagation.iterations=16") are applied before reading, so they are checked like
// the file's keys. Any key nobody reads is an error naming the file, the line and the valid keys.

#include <toml++/toml.h>

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/animation/animation.h"
#include "framework/io/image.h"
#include "framework/particles/particle_geometry.h"
#include "framework/pipeline/pipeline.h"
#include "framework/reference/reference_cache.h"
#include "framework/scene/scene.h"

namespace lpvlab {

struct GridPlacement {
  int resolution = 32;          // cells along the scene's longest axis
  float marginCells = 1.0f;     // empty cells around the scene bounds
  std::optional<glm::vec3> origin;      // fixed placement: all three of these given
  std::optional<float> cellSize;
  std::optional<glm::ivec3> cells;
  GridGeometry resolve(const Bounds& sceneBounds) const;
};

// What a run that compares with its reference measures ([metrics] table).
struct ComparisonSettings {
  // (run output, reference output) pairs; the first pair's FLIP heat map is written per run.
  std::vector<std::pair<std::string, std::string>> pairs{{"indirect", "indirect1"},
                                                         {"direct", "direct"}};
  // Image regions with figures of their own: (left, top, right, bottom) as fractions of the
  // image's width and height, (0, 0) the top-left corner.
  struct Region {
    std::string name;
    glm::vec4 rect{0, 0, 1, 1};
  };
  std::vector<Region> regions;
};

struct Experiment {
  std::string name;             // the file's stem, or "cornell_box" for the built-in default
  std::string file;             // the experiment file, or "" for the built-in default
  Scene scene;                  // at frame 0 of the animation (as loaded when nothing moves)
  Camera camera;
  Animation animation;  // [animation]: one frame where the file has none
  // [[particles]]: each system's copies of its model, meshes of `scene` placed for the frame's
  // time beside what the animation moves (setSceneTime).
  std::vector<ParticleGeometry> particles;
  PipelineSettings settings;
  // [indirect] method: LPV by default (its strategies are its own), or another.
  std::unique_ptr<IndirectMethod> method;
  int warmupFrames = 2;
  int repeats = 5;
  // The PNG only (data in the EXR is never scaled): with autoExposure the median lit pixel goes
  // to middle grey and exposureStops is added to that; without, exposureStops alone.
  bool autoExposure = true;
  // [output] tone_curve and white_stops: the PNG's curve (framework/io/image.h).
  ToneCurve toneCurve = ToneCurve::Reinhard;
  float whiteStops = 10.0f;
  // [output] dump_grid (lpvlab run --dump-grid): the method's light grid after the last frame is
  // written beside the images (grid.npy, grid.json); only for a method with one, in a static run.
  bool dumpGrid = false;
  float exposureStops = 0.0f;
  std::string glBackend = "auto";
  // The path-traced reference of the same scene, camera and output size ([reference] table);
  // its tracer's sky is the experiment's [sky] radiance.
  ReferenceRequest reference;
  bool compareWithReference = false;  // [reference] compare: runs measure their error against it
  ComparisonSettings comparison;
  nlohmann::json configuration; // every parameter as resolved (defaults included)
};

// Reads the scene file at a resolved path (loadSceneByName): a fit passes one that loads each
// scene once and hands out copies (the experiment adds its lights and materials to its copy).
using SceneLoader = std::function<Scene(const std::string& resolvedPath)>;
// [indirect] method where the file names none.
extern const char* const kDefaultIndirectMethod;

// Reads `path` ("" for the built-in default) with the overrides applied. Throws an Error naming
// the file and key for anything wrong.
Experiment loadExperiment(const std::string& path, const std::vector<std::string>& overrides = {},
                          const SceneLoader& loadScene = {});
// The same from a table already read (`extends` and `include` merged, overrides applied, no
// [sweep] or [fit] table); `path` names it in messages and anchors relative scene files.
Experiment loadExperiment(const toml::table& root, const std::string& path,
                          const SceneLoader& loadScene = {});

// Sets `experiment`'s scene and camera to their state at `seconds`: the animation's camera,
// lights and meshes, then the particles alive then. Returns how many particles each system has
// alive.
std::vector<std::size_t> setSceneTime(Experiment& experiment, double seconds);
// Whether geometry moves between frames: meshes the animation moves, or particles.
bool movesGeometry(const Experiment& experiment);

// The folder "shared:<path>" scene references are relative to: env LPVLAB_SHARED_DIR, else the
// build's default (the ../shared beside the source tree).
std::string sharedDirectory();

// Resolves a scene reference from an experiment: "builtin:cornell_box", "shared:<path>" (relative
// to the shared folder: env LPVLAB_SHARED_DIR, else the build's default), or a path relative to
// the experiment file's folder.
std::string resolveScenePath(const std::string& reference, const std::string& experimentFile);

}  // namespace lpvlab

#include "framework/experiment/experiment.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

#include "framework/animation/animation_file.h"
#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/experiment/experiment_file.h"
#include "framework/experiment/sweep_expansion.h"
#include "framework/particles/particle_file.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {

namespace fs = std::filesystem;

namespace {

constexpr float kDegrees = float(M_PI) / 180.0f;
// The most triangles all copies of one particle system's model may add to the scene (they are
// stored as the scene's meshes: 30 million take about 2 GB with their vertices).
constexpr std::size_t kMaxParticleTriangles = 30'000'000;

// A number as a person writes it (10, 0.02), not std::to_string's 10.000000.
std::string shortNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

Light readLight(Params& p) {
  Light light;
  const std::string type = p.getChoice("type", "point", {"point", "spot", "directional"});
  light.type = type == "point" ? LightType::Point
               : type == "spot" ? LightType::Spot : LightType::Directional;
  light.name = p.get<std::string>("name", type);
  light.color = p.get<glm::vec3>("color", glm::vec3(1.0f), {.min = glm::vec3(0.0f), .max = glm::vec3(1e12f)});
  light.intensity = p.require<float>("intensity", {.min = 0.0f, .max = 1e12f});
  // What reaches the kernels is their product; 1e12 is the brightest light the extremes tests
  // render finite (a colour of 1e30 ran, and 1e38 ended in NaN far from this file).
  const float brightest = std::max({light.color.x, light.color.y, light.color.z}) * light.intensity;
  if (brightest > 1e12f)
    throw Error(p.where("color") + ": colour x intensity reaches " + shortNumber(brightest) +
                ", above 1e12, the brightest light lpvlab is tested with");
  if (light.type != LightType::Directional) light.position = p.require<glm::vec3>("position");
  if (light.type != LightType::Point) {
    const glm::vec3 d = p.require<glm::vec3>("direction");
    if (glm::length(d) < 1e-6f) throw Error(p.where("direction") + ": must not be zero");
    light.direction = glm::normalize(d);
  }
  if (light.type == LightType::Spot) {
    light.outerConeAngle = kDegrees * p.get<float>("outer_cone_deg", 45.0f, {.min = 0.01f, .max = 90.0f});
    light.innerConeAngle = kDegrees * p.get<float>("inner_cone_deg", 0.0f, {.min = 0.0f, .max = 90.0f});
    if (light.innerConeAngle > light.outerConeAngle)
      throw Error(p.where("inner_cone_deg") + ": must not exceed outer_cone_deg");
  }
  return light;
}

// The index of the item named by `p`'s `key` in `items` (a scene's meshes or materials); an
// Error naming the key, the scene and the names it has if there is none.
template <class Item>
int findNamed(Params& p, const std::string& key, const std::vector<Item>& items, const Scene& scene,
              const char* what) {
  const std::string name = p.require<std::string>(key);
  const auto found = std::find_if(items.begin(), items.end(), [&](const Item& i) { return i.name == name; });
  if (found != items.end()) return int(found - items.begin());
  std::string names;
  for (const Item& item : items) names += (names.empty() ? "" : ", ") + item.name;
  throw Error(p.where(key) + ": the scene " + scene.source + " has no " + what + " '" + name +
              "' (it has: " + names + ")");
}

// One material's keys of a [[materials]] table (each defaults to the material's own value).
// What it reflects diffusely, specularly and lets in must not exceed the whole.
void overrideMaterial(Params& p, Material& material) {
  const Range<glm::vec3> unit{.min = glm::vec3(0.0f), .max = glm::vec3(1.0f)};
  material.baseColor = p.get<glm::vec3>("base_color", material.baseColor, unit);
  material.transmittance = p.get<glm::vec3>("transmittance", glm::vec3(0.0f), unit);
  material.extinction = p.get<float>("extinction", 0.0f, {.min = 0.0f, .max = 1e6f});
  material.specular = p.get<glm::vec3>("specular", material.specular, unit);
  material.shininess = p.get<float>("shininess", material.shininess, {.min = 0.0f, .max = 1e4f});
  material.metallic = p.get<float>("metallic", material.metallic, {.min = 0.0f, .max = 1.0f});
  const glm::vec3 total = material.baseColor + material.transmittance;
  if (glm::any(glm::greaterThan(total, glm::vec3(1.0f + 1e-6f))))
    throw Error(p.where("transmittance") + ": material '" + material.name + "' would reflect and " +
                "transmit more than it receives (base_color + transmittance = " +
                std::to_string(total.x) + ", " + std::to_string(total.y) + ", " +
                std::to_string(total.z) + "; at most 1 per channel)");
  // Only the overridden keys are checked: a file's own materials follow the loaders' rule
  // (phongAt limits the diffuse part to 1 - rho_s).
  const glm::vec3 reflected = material.baseColor + material.specular;
  if ((p.has("specular") || p.has("base_color")) && material.metallic == 0.0f &&
      glm::any(glm::greaterThan(reflected, glm::vec3(1.0f + 1e-6f))))
    throw Error(p.where(p.has("specular") ? "specular" : "base_color") + ": material '" +
                material.name + "' would reflect more than it receives (base_color + specular = " +
                std::to_string(reflected.x) + ", " + std::to_string(reflected.y) + ", " +
                std::to_string(reflected.z) + "; at most 1 per channel)");
}

// A [[materials]] table: translucency (thesis 5.4; read by rendering "subsurface"), the glossy
// lobe of the reference's brdf "phong", and optionally another base colour, for the scene's
// material `name` (name = "*": every material), or for the material of one mesh only (`mesh`:
// that mesh gets its own copy of its material, named "<material> (<mesh>)").
void readMaterialOverride(Params& p, Scene& scene) {
  if (p.has("name") == p.has("mesh"))
    throw Error(p.where("name") + ": give exactly one of name (a material), \"*\" (every material) "
                "and mesh (a mesh)");
  if (p.has("mesh")) {
    Mesh& mesh = scene.meshes[std::size_t(findNamed(p, "mesh", scene.meshes, scene, "mesh"))];
    Material copy = scene.materials.at(mesh.material);
    copy.name += " (" + mesh.name + ")";
    scene.materials.push_back(copy);
    mesh.material = int(scene.materials.size()) - 1;
    overrideMaterial(p, scene.materials.back());
  } else if (p.get<std::string>("name", "") == "*") {
    for (Material& material : scene.materials) overrideMaterial(p, material);
  } else {
    overrideMaterial(p, scene.materials[std::size_t(findNamed(p, "name", scene.materials, scene, "material"))]);
  }
}

// A [[materials]] table that sets a glossy lobe asks for the reference's brdf "phong": with the
// Lambertian reference the lobe would be ignored without a word.
void refuseIgnoredGlossyKeys(Params& params, const Experiment& e) {
  if (e.reference.tracer.glossy) return;
  for (Params& p : params.tables("materials"))
    for (const char* key : {"specular", "shininess", "metallic"})
      if (p.has(key))
        throw Error(p.where(key) + ": only the reference's brdf = \"phong\" reads a material's "
                    "glossy lobe; with [reference] brdf = \"lambertian\" (the default) it would be ignored");
}

Camera readCamera(Params& p, const Scene& scene) {
  if (p.has("position")) {
    Camera camera;
    // With a position, `name` only labels the camera (so a file can replace the camera of the
    // file it extends).
    camera.name = p.get<std::string>("name", "experiment");
    camera.position = p.require<glm::vec3>("position");
    const glm::vec3 target = p.require<glm::vec3>("look_at");
    const glm::vec3 up = p.get<glm::vec3>("up", glm::vec3(0, 1, 0));
    switch (orientCamera(camera, target, up)) {
      case CameraOrientation::TargetAtPosition:
        throw Error(p.where("look_at") + ": must differ from the camera position");
      case CameraOrientation::UpAlongView:
        throw Error(p.where("up") + ": parallel to the view direction");
      case CameraOrientation::Oriented:
        break;
    }
    camera.verticalFov = kDegrees * p.get<float>("fov_deg", 45.0f, {.min = 1.0f, .max = 170.0f});
    const float diagonal = glm::length(scene.bounds().extent());
    camera.nearPlane = p.get<float>("near", std::max(1e-4f, 1e-4f * diagonal), {.min = 1e-6f});
    camera.farPlane = p.get<float>("far", 4.0f * diagonal + glm::length(camera.position - scene.bounds().center()),
                                   {.min = 1e-5f});
    // As [animation.camera] does: with far <= near every depth is clipped (all outputs black) or
    // the depth range is inverted.
    if (!(camera.farPlane > camera.nearPlane))
      throw Error(p.where("far") + ": must exceed near (" + shortNumber(camera.nearPlane) + " m)");
    return camera;
  }
  if (scene.cameras.empty())
    throw Error(p.file() + ": the scene " + scene.source + " has no camera; give one with "
                "[camera] position, look_at (and fov_deg)");
  std::vector<std::string> names;
  for (const Camera& c : scene.cameras) names.push_back(c.name);
  const std::string name = p.getChoice("name", scene.cameras.front().name, names);
  for (const Camera& c : scene.cameras)
    if (c.name == name) {
      if (!(c.nearPlane > 0.0f) || !(c.farPlane > c.nearPlane))
        throw Error(p.where("name") + ": the scene " + scene.source + "'s camera '" + c.name +
                    "' has near " + shortNumber(c.nearPlane) + " m and far " +
                    shortNumber(c.farPlane) + " m (far must exceed near > 0); give the " +
                    "camera in the experiment instead ([camera] position, look_at, near, far)");
      return c;
    }
  return scene.cameras.front();
}

}  // namespace

GridGeometry GridPlacement::resolve(const Bounds& sceneBounds) const {
  if (origin && cellSize && cells) return GridGeometry{*origin, *cellSize, *cells};
  return GridGeometry::fitted(sceneBounds, resolution, marginCells);
}

std::string resolveScenePath(const std::string& reference, const std::string& experimentFile) {
  if (reference.rfind("builtin:", 0) == 0) return reference;
  if (reference.rfind("shared:", 0) == 0)
    return (fs::path(sharedDirectory()) / reference.substr(7)).string();
  const fs::path path(reference);
  if (path.is_absolute() || experimentFile.empty()) return path.string();
  return (fs::path(experimentFile).parent_path() / path).string();
}

const char* const kDefaultIndirectMethod = "lpv";

std::vector<std::size_t> setSceneTime(Experiment& experiment, double seconds) {
  applyAnimation(experiment.animation, seconds, experiment.scene, experiment.camera);
  std::vector<std::size_t> alive;
  for (const ParticleGeometry& particles : experiment.particles)
    alive.push_back(particles.place(experiment.scene, seconds));
  return alive;
}

bool movesGeometry(const Experiment& experiment) {
  return experiment.animation.movesGeometry() || !experiment.particles.empty();
}

std::string sharedDirectory() {
  if (const char* env = std::getenv("LPVLAB_SHARED_DIR")) return env;
  return LPVLAB_SHARED_DIR;
}

Experiment loadExperiment(const std::string& path, const std::vector<std::string>& overrides,
                          const SceneLoader& loadScene) {
  // `extends` and `include` are merged here; a [sweep] table is checked and left to `lpvlab
  // sweep`: read on its own, a sweep file is its base configuration. Likewise a [fit] table is
  // `lpvlab fit`'s (framework/fit/fit_spec.h).
  toml::table root = path.empty() ? toml::table{} : readExperimentTable(path);
  for (const std::string& assignment : overrides) applyOverride(root, assignment);
  if (root.contains("sweep")) {
    checkSweep(root, path.empty() ? "built-in default experiment" : path);
    root.erase("sweep");
  }
  root.erase("fit");   // lpvlab fit's and lpvlab tune's own tables: the rest is the experiment
  root.erase("tune");
  return loadExperiment(root, path, loadScene);
}

namespace {

// [scene], [[lights]] and [[materials]]: the scene, its lights replaced or added to, its materials changed.
void readScene(Params& params, const std::string& path, const SceneLoader& loadScene, Experiment& e) {
  Params sceneParams = params.table("scene");
  const std::string sceneRef = sceneParams.get<std::string>("file", "builtin:cornell_box");
  try {
    const std::string scenePath = resolveScenePath(sceneRef, path);
    e.scene = loadScene ? loadScene(scenePath) : loadSceneByName(scenePath);
  } catch (const Error& error) {
    throw Error(sceneParams.where("file") + ": " + error.what());
  }
  if (sceneParams.get<bool>("replace_lights", false)) e.scene.lights.clear();
  for (Params& lightParams : params.tables("lights")) e.scene.lights.push_back(readLight(lightParams));
  for (Params& materialParams : params.tables("materials")) readMaterialOverride(materialParams, e.scene);
}

void readCameraAndAnimation(Params& params, const toml::table& root, Experiment& e) {
  // The camera is [camera]'s (or the scene's first); a path in [animation.camera] moves it, and
  // then needs none (a scene without cameras and no [camera] table).
  Params cameraParams = params.table("camera");
  Params animationParams = params.table("animation");
  const bool cameraGiven =
      !animationParams.has("camera") || root.contains("camera") || !e.scene.cameras.empty();
  if (cameraGiven) e.camera = readCamera(cameraParams, e.scene);
  e.animation = readAnimation(animationParams, e.scene, e.camera, cameraGiven);
  applyAnimation(e.animation, e.animation.frameTime(0), e.scene, e.camera);
}

// [[particles]]: each system with its model, placed in the scene at frame 0.
void readParticles(Params& params, const std::string& path, const SceneLoader& loadScene, Experiment& e) {
  std::vector<Params> particleTables = params.tables("particles");
  for (std::size_t i = 0; i < particleTables.size(); ++i) {
    ParticleSettings settings = readParticleSettings(particleTables[i], int(i));
    Params& table = settings.table;
    try {
      const std::string modelPath = resolveScenePath(settings.model, path);
      const ParticleModel model =
          particleModel(loadScene ? loadScene(modelPath) : loadSceneByName(modelPath), settings.modelMeshes);
      e.particles.emplace_back(std::move(settings.system), model, e.scene, e.animation.frameTime(0),
                               kMaxParticleTriangles, settings.drawing);
    } catch (const Error& error) {
      throw Error(table.where("model") + ": " + error.what());
    }
    table.finish();
  }
}

// [output] and [light_maps]: the image and the light views' maps.
void readImages(Params& params, Experiment& e) {
  Params output = params.table("output");
  e.settings.width = output.get<int>("width", 512, {.min = 1, .max = 16384});
  e.settings.height = output.get<int>("height", 512, {.min = 1, .max = 16384});
  e.autoExposure = output.get<bool>("auto_exposure", true);
  e.toneCurve = output.getChoice("tone_curve", "reinhard", {"reinhard", "logarithmic"}) == "logarithmic"
                    ? ToneCurve::Logarithmic
                    : ToneCurve::Reinhard;
  if (e.toneCurve == ToneCurve::Logarithmic)
    e.whiteStops = output.get<float>("white_stops", 10.0f, {.min = 0.5f, .max = 40.0f});
  e.exposureStops = output.get<float>("exposure", 0.0f, {.min = -40.0f, .max = 40.0f});
  e.dumpGrid = output.get<bool>("dump_grid", false);

  Params lightMaps = params.table("light_maps");
  e.settings.rsmResolution = lightMaps.get<int>("rsm_resolution", 256, {.min = 1, .max = 8192});
  e.settings.shadowResolution = lightMaps.get<int>("shadow_resolution", 1024, {.min = 1, .max = 16384});
  e.settings.shadow.normalOffsetTexels =
      lightMaps.get<float>("shadow_normal_offset", 1.5f, {.min = 0.0f, .max = 100.0f});
  e.settings.shadow.depthBias = lightMaps.get<float>("shadow_depth_bias", 2e-5f, {.min = 0.0f, .max = 0.1f});
  // Direct light's shadows: the shadow maps, or exact rays (framework/raster/raster_choice.h).
  e.settings.shadow.rays = lightMaps.getChoice("shadows", "map", {"map", "rays"}) == "rays";
  // A directional light's view: around the whole scene, or a box following the camera (thesis
  // 6.2), snapped to whole texels unless asked not to.
  const bool follows = lightMaps.getChoice("directional", "scene", {"scene", "camera"}) == "camera";
  if (follows)
    e.settings.directional.followWidth =
        lightMaps.require<float>("directional_width", {.min = 1e-4f, .max = 1e6f});
  else if (lightMaps.has("directional_width") || lightMaps.has("directional_snap"))
    throw Error(lightMaps.where(lightMaps.has("directional_width") ? "directional_width"
                                                                   : "directional_snap") +
                ": only used with light_maps.directional = \"camera\"");
  e.settings.directional.snap = lightMaps.get<bool>("directional_snap", true);
}

// [grid] and [cascades]: the light grid's placement and its levels.
void readGrid(Params& params, Experiment& e) {
  Params gridParams = params.table("grid");
  GridPlacement placement;
  placement.resolution = gridParams.get<int>("resolution", 32, {.min = 1, .max = 1024});
  placement.marginCells = gridParams.get<float>("margin", 1.0f, {.min = 0.0f, .max = 64.0f});
  if (gridParams.has("origin") || gridParams.has("cell_size") || gridParams.has("cells")) {
    placement.origin = gridParams.require<glm::vec3>("origin");
    placement.cellSize = gridParams.require<float>("cell_size", {.min = 1e-6f});
    placement.cells = gridParams.require<glm::ivec3>("cells", {.min = glm::ivec3(1), .max = glm::ivec3(1024)});
  }
  e.settings.grid = placement.resolve(e.scene.bounds());
  e.settings.shOrder = gridParams.get<int>("sh_order", 1, {.min = 1, .max = 3});
  Params cascades = params.table("cascades");
  e.settings.cascades.levels = cascades.get<int>("levels", 1, {.min = 1, .max = 8});
  e.settings.cascades.blendCells = cascades.get<float>("blend_cells", 2.0f, {.min = 0.0f, .max = 16.0f});
  const bool followsEye = cascades.getChoice("placement", "eye", {"eye", "depth"}) == "eye";
  e.settings.cascades.placement = followsEye ? CascadePlacement::Eye : CascadePlacement::Depth;
  // Read with "depth" too: it places the levels of a frame that sees nothing.
  e.settings.cascades.viewShift = cascades.get<float>("view_shift", 0.25f, {.min = -1.0f, .max = 1.0f});
  e.settings.cascades.carry = cascades.get<bool>("carry", true);
  e.settings.cascades.snap = cascades.get<bool>("snap", true);
  if (!e.settings.cascades.snap && e.settings.cascades.carry && e.settings.cascades.levels > 1)
    throw Error(cascades.where("snap") +
                ": false needs cascades.carry = false (carrying a level's light to its parent "
                "needs the level on whole parent cells)");
}

// [timing], [gl] and [compute].
void readTimingAndBackends(Params& params, Experiment& e) {
  Params timing = params.table("timing");
  e.warmupFrames = timing.get<int>("warmup", 2, {.min = 0, .max = 1000});
  e.repeats = timing.get<int>("repeats", 5, {.min = 1, .max = 100000});
  e.glBackend = params.table("gl").getChoice("backend", "auto", {"auto", "osmesa", "egl", "none"});
  e.settings.gl = e.glBackend != "none";  // "auto" may still find none: the pipeline checks again
  e.settings.backend = params.table("compute").getChoice("backend", "auto", {"auto", "gl", "cpu"});
  e.settings.raster = params.table("compute").getChoice("raster", "auto", {"auto", "gl", "embree"});
  // Shadow rays are traced on the CPU, where direct light must then run: refused here, before any
  // GL, when the backend is GL by name ("auto" on a GPU is refused by raster_choice.h).
  if (e.settings.shadow.rays && e.settings.backend == "gl")
    throw Error(params.table("light_maps").where("shadows") +
                ": \"rays\" are traced on the CPU, where direct light must then run; "
                "[compute] backend = \"gl\" runs it on GL (use \"cpu\", or \"auto\" on a software GL renderer)");
}

// [sky] and [reference]: what the path tracer renders and how long.
void readReference(Params& params, Experiment& e) {
  Params sky = params.table("sky");
  e.reference.tracer.skyRadiance = sky.get<glm::vec3>("radiance", glm::vec3(0.0f), {.min = glm::vec3(0.0f)});
  e.settings.skyRadiance = e.reference.tracer.skyRadiance;
  Params reference = params.table("reference");
  e.reference.width = e.settings.width;
  e.reference.height = e.settings.height;
  e.reference.target.samples = reference.get<int>("samples", 256, {.min = 0, .max = 1 << 24});
  e.reference.target.seconds = reference.get<double>("seconds", 0.0, {.min = 0.0});
  e.reference.target.relativeError = reference.get<double>("relative_error", 0.0, {.min = 0.0, .max = 1.0});
  if (!e.reference.target.any())
    throw Error(params.where("reference") + ": no sample budget: set samples, seconds or "
                "relative_error above 0");
  e.reference.tracer.seed = std::uint64_t(reference.get<int>("seed", 1, {.min = 0}));
  e.reference.tracer.maxBounces = reference.get<int>("max_bounces", 64, {.min = 1, .max = 100000});
  e.reference.tracer.rouletteAfter = reference.get<int>("roulette_after", 3, {.min = 0, .max = 100000});
  e.reference.tracer.sampler = samplerFromName(reference.getChoice("sampler", "independent", samplerNames()));
  e.reference.tracer.glossy = reference.getChoice("brdf", "lambertian", {"lambertian", "phong"}) == "phong";
  e.reference.threads = reference.get<int>("threads", 0, {.min = 0, .max = 4096});
  // How often the sums are saved for resuming (0: after every pass of about a second).
  e.reference.checkpointSeconds =
      reference.get<double>("checkpoint_seconds", 30.0, {.min = 0.0, .max = 86400.0});
  std::vector<std::string> isas = {"auto"};
  isas.insert(isas.end(), embreeInstructionSets().begin(), embreeInstructionSets().end());
  e.reference.tracer.engine.isa = reference.getChoice("isa", "auto", isas);
  const std::vector<std::string> supported = supportedInstructionSets();
  if (e.reference.tracer.engine.isa != "auto" &&
      std::find(supported.begin(), supported.end(), e.reference.tracer.engine.isa) == supported.end()) {
    std::string has;
    for (const std::string& isa : supported) has += (has.empty() ? "" : ", ") + isa;
    throw Error(reference.where("isa") + ": this CPU lacks '" + e.reference.tracer.engine.isa +
                "' (it has " + has + ")");
  }
  e.reference.tracer.engine.packetWidth = reference.get<int>("packet_width", 0, {.min = 0, .max = 16});
  const auto& widths = rayPacketWidths();
  if (std::find(widths.begin(), widths.end(), e.reference.tracer.engine.packetWidth) == widths.end())
    throw Error(reference.where("packet_width") + ": " +
                std::to_string(e.reference.tracer.engine.packetWidth) +
                " is not one of 0 (the instruction set's native width), 1, 4, 8, 16");
  e.compareWithReference = reference.get<bool>("compare", false);
}

// [metrics]: the comparison's pairs and regions.
void readMetrics(Params& params, Experiment& e) {
  Params metrics = params.table("metrics");
  const std::vector<std::string> runOutputs = {"direct", "indirect", "combined"};
  const std::vector<std::string> referenceOutputs = {"direct", "indirect", "indirect1", "combined"};
  if (metrics.has("pairs")) {
    e.comparison.pairs.clear();
    for (const std::string& pair : metrics.get<std::vector<std::string>>("pairs", {})) {
      const auto colon = pair.find(':');
      const std::string mine = pair.substr(0, colon);
      const std::string theirs = colon == std::string::npos ? "" : pair.substr(colon + 1);
      const auto known = [](const std::vector<std::string>& names, const std::string& name) {
        return std::find(names.begin(), names.end(), name) != names.end();
      };
      if (!known(runOutputs, mine) || !known(referenceOutputs, theirs))
        throw Error(metrics.where("pairs") + ": '" + pair + "' is not RUN:REFERENCE with RUN one "
                    "of direct, indirect, combined and REFERENCE one of direct, indirect, "
                    "indirect1, combined");
      e.comparison.pairs.emplace_back(mine, theirs);
    }
    if (e.comparison.pairs.empty()) throw Error(metrics.where("pairs") + ": names no pair");
  }
  for (Params& region : metrics.tables("regions")) {
    ComparisonSettings::Region r;
    r.name = region.require<std::string>("name");
    const Range<float> unit{.min = 0.0f, .max = 1.0f};
    r.rect = glm::vec4(region.get<float>("left", 0.0f, unit), region.get<float>("top", 0.0f, unit),
                       region.get<float>("right", 1.0f, unit), region.get<float>("bottom", 1.0f, unit));
    if (!(r.rect.x < r.rect.z && r.rect.y < r.rect.w))
      throw Error(region.where("right") + ": region '" + r.name + "' is empty (left < right and "
                  "top < bottom are required)");
    e.comparison.regions.push_back(r);
  }
}

// [indirect] method: a registered method (framework/pipeline/indirect_method.h), "lpv" by
// default. So that one file can sweep indirect.method over methods, the tables another method
// reads (LPV's stages) are read and checked whichever method runs; they are returned, to be left
// out of the configuration (a summary's param.propagation.* columns are then empty on another
// method's rows, not defaults it never used).
std::set<std::string> readIndirect(Params& params, Experiment& e) {
  Params indirect = params.table("indirect");
  const auto& methods = Registry<IndirectMethod>::instance();
  const std::string chosen = indirect.getChoice("method", kDefaultIndirectMethod, methods.names());
  e.method = methods.entries().at(chosen).factory(indirect);
  e.method->setRegisteredName(chosen);
  const std::vector<std::string>& own = methods.entries().at(chosen).tables;
  std::set<std::string> foreign;
  for (const auto& [name, entry] : methods.entries()) {
    if (name == chosen || entry.tables.empty()) continue;
    entry.factory(indirect);  // reads and checks its tables' keys; never run
    for (const std::string& table : entry.tables)
      if (std::find(own.begin(), own.end(), table) == own.end()) foreign.insert(table);
  }
  return foreign;
}

// After every table is read: the method's check, and the resolved configuration the manifest
// records (without `foreignTables`, the tables only another method reads).
void recordConfiguration(Params& params, const std::string& file,
                         const std::set<std::string>& foreignTables, Experiment& e) {
  params.finish();
  try {
    e.method->check(e.settings);
  } catch (const Error& error) {
    const std::string what = error.what();
    if (what.starts_with(file + ":")) throw;  // it names the file already (Params::where)
    throw Error(file + ": " + what);
  }
  e.configuration = params.resolved();
  for (const std::string& table : foreignTables) e.configuration.erase(table);
  e.configuration["scene"]["resolved_path"] = e.scene.source;
  e.configuration["camera"]["resolved"] = {
      {"name", e.camera.name},
      {"position", {e.camera.position.x, e.camera.position.y, e.camera.position.z}},
      {"forward", {e.camera.forward.x, e.camera.forward.y, e.camera.forward.z}},
      {"vertical_fov_deg", e.camera.verticalFov / kDegrees}};
  const GridGeometry& g = e.settings.grid;
  if (e.configuration.contains("grid")) e.configuration["grid"]["resolved"] = {
      {"origin", {g.origin.x, g.origin.y, g.origin.z}},
      {"cell_size", g.cellSize},
      {"cells", {g.resolution.x, g.resolution.y, g.resolution.z}}};
}

}  // namespace

Experiment loadExperiment(const toml::table& root, const std::string& path, const SceneLoader& loadScene) {
  const std::string file = path.empty() ? "built-in default experiment" : path;
  Params params(root, file);

  Experiment e;
  e.file = path;
  e.name = path.empty() ? "cornell_box" : fs::path(path).stem().string();
  // A label for analyses only (recorded in the manifest, so a sweep that sweeps it has a
  // param.series column): the report compares every configuration with those whose series is
  // "baseline" (docs/experiments.md, "Equal time").
  params.get<std::string>("series", "");

  readScene(params, path, loadScene, e);
  readCameraAndAnimation(params, root, e);
  readParticles(params, path, loadScene, e);
  readImages(params, e);
  readGrid(params, e);
  readTimingAndBackends(params, e);
  readReference(params, e);
  refuseIgnoredGlossyKeys(params, e);
  readMetrics(params, e);
  const std::set<std::string> foreignTables = readIndirect(params, e);
  if (e.dumpGrid && !e.method->hasLightGrid())
    throw Error(params.table("output").where("dump_grid") + ": indirect method \"" + e.method->name() +
                "\" keeps no light grid to dump (LPV does)");
  if (e.dumpGrid && e.animation.animated())
    throw Error(params.table("output").where("dump_grid") +
                ": only a static run dumps its grid (this experiment is animated)");
  recordConfiguration(params, file, foreignTables, e);
  return e;
}

}  // namespace lpvlab

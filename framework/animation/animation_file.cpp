#include "framework/animation/animation_file.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

constexpr double kDegrees = M_PI / 180.0;

// The [[...keys]] of one animated object, each with its time: `time` in seconds or `frame` (a
// frame number, possibly fractional), in increasing order.
struct Keys {
  Params owner;  // the table holding `keys` and `interpolation`
  std::vector<Params> tables;
  std::vector<double> times;
  Interpolation interpolation = Interpolation::CatmullRom;
};

Keys readKeys(Params owner, double fps) {
  Keys keys{owner, owner.tables("keys"), {}, Interpolation::CatmullRom};
  keys.interpolation =
      interpolationNamed(owner.getChoice("interpolation", "catmull_rom", interpolationNames()));
  if (keys.tables.empty()) throw Error(owner.where("keys") + ": no keys (give [[...keys]] tables)");
  for (Params& key : keys.tables) {
    if (key.has("time") == key.has("frame"))
      throw Error(key.where("time") + ": give exactly one of time (seconds) and frame");
    const double time =
        key.has("time") ? key.require<double>("time") : key.require<double>("frame") / fps;
    if (!keys.times.empty() && !(time > keys.times.back()))
      throw Error(key.where(key.has("time") ? "time" : "frame") + ": " + std::to_string(time) +
                  " s does not come after the previous key's " + std::to_string(keys.times.back()) +
                  " s (keys must be in increasing time)");
    keys.times.push_back(time);
  }
  return keys;
}

// The track of one quantity: the keys that give `name`, read by `read`. Empty when no key gives it.
template <class T>
KeyframeTrack<T> channel(Keys& keys, const std::string& name, const std::function<T(Params&)>& read,
                         std::optional<Interpolation> interpolation = {}) {
  std::vector<double> times;
  std::vector<T> values;
  for (std::size_t i = 0; i < keys.tables.size(); ++i) {
    if (!keys.tables[i].has(name)) continue;
    times.push_back(keys.times[i]);
    values.push_back(read(keys.tables[i]));
  }
  if (times.empty()) return {};
  try {
    return KeyframeTrack<T>(times, values, interpolation.value_or(keys.interpolation));
  } catch (const Error& error) {
    throw Error(keys.owner.where("keys") + ": " + name + ": " + error.what());
  }
}

// A key naming a quantity the object does not have is an error naming it (before "no key
// changes anything" would hide it).
void finishKeys(const Keys& keys) {
  for (const Params& key : keys.tables) key.finish();
}

// Intensity and colour never overshoot below zero: linear between keys, unless held (step).
Interpolation nonNegative(Interpolation interpolation) {
  return interpolation == Interpolation::Step ? Interpolation::Step : Interpolation::Linear;
}

glm::dvec3 vector(Params& key, const char* name) {
  return glm::dvec3(key.require<glm::vec3>(name));
}

// Index of the one item named `name`; an Error naming the key if none or several are.
template <class Item>
int uniqueNamed(Params& p, const char* key, const std::string& name, const std::vector<Item>& items,
                const Scene& scene, const char* what) {
  int found = -1, count = 0;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (items[i].name == name) found = int(i), ++count;
  if (count == 1) return found;
  std::string names;
  for (const Item& item : items) names += (names.empty() ? "" : ", ") + item.name;
  if (count == 0)
    throw Error(p.where(key) + ": the scene " + scene.source + " has no " + what + " '" + name +
                "' (it has: " + names + ")");
  throw Error(p.where(key) + ": " + std::to_string(count) + " " + what + "s are named '" + name +
              "'; give them distinct names to animate one");
}

// `camera`: the experiment's camera when `cameraGiven` ([camera], or the scene's), whose field of
// view and planes the path keeps unless it gives its own.
CameraMotion readCameraMotion(Params p, double fps, const Scene& scene, Camera& camera,
                              bool cameraGiven) {
  CameraMotion motion;
  Keys keys = readKeys(p, fps);
  motion.up = p.get<glm::vec3>("up", glm::vec3(0, 1, 0));
  motion.position =
      channel<glm::dvec3>(keys, "position", [](Params& k) { return vector(k, "position"); });
  motion.lookAt =
      channel<glm::dvec3>(keys, "look_at", [](Params& k) { return vector(k, "look_at"); });
  motion.verticalFov = channel<double>(keys, "fov_deg", [](Params& k) {
    return kDegrees * k.require<double>("fov_deg", {.min = 1.0, .max = 170.0});
  });
  finishKeys(keys);
  if (motion.position.empty() || motion.lookAt.empty())
    throw Error(p.where("keys") +
                ": the camera path needs position and look_at in at least one key");
  if (!cameraGiven) camera = Camera{.name = "animation", .verticalFov = float(45.0 * kDegrees)};
  camera.verticalFov = float(kDegrees * p.get<double>("fov_deg", camera.verticalFov / kDegrees,
                                                      {.min = 1.0, .max = 170.0}));
  // Planes for the whole path: the far plane reaches past the scene from the path's farthest key.
  const Bounds bounds = scene.bounds();
  double farthest = 0.0;
  for (const glm::dvec3& position : motion.position.values())
    farthest = std::max(farthest, glm::length(position - glm::dvec3(bounds.center())));
  const float diagonal = glm::length(bounds.extent());
  const float coveringFar = 4.0f * diagonal + float(farthest);
  camera.nearPlane = p.get<float>(
      "near", cameraGiven ? camera.nearPlane : std::max(1e-4f, 1e-4f * diagonal), {.min = 1e-6f});
  camera.farPlane = p.get<float>(
      "far", cameraGiven ? std::max(camera.farPlane, coveringFar) : coveringFar, {.min = 1e-5f});
  if (!(camera.farPlane > camera.nearPlane))
    throw Error(p.where("far") + ": must exceed near (" + std::to_string(camera.nearPlane) + ")");
  return motion;
}

LightMotion readLightMotion(Params p, double fps, const Scene& scene) {
  LightMotion motion;
  const std::string name = p.require<std::string>("light");
  motion.light = uniqueNamed(p, "light", name, scene.lights, scene, "light");
  const Light& light = scene.lights[std::size_t(motion.light)];
  Keys keys = readKeys(p, fps);
  if (light.type != LightType::Directional)
    motion.position =
        channel<glm::dvec3>(keys, "position", [](Params& k) { return vector(k, "position"); });
  if (light.type != LightType::Point)
    motion.direction = channel<glm::dvec3>(keys, "direction", [](Params& k) {
      const glm::dvec3 d = vector(k, "direction");
      if (!(glm::length(d) > 1e-9)) throw Error(k.where("direction") + ": must not be zero");
      return glm::normalize(d);
    });
  motion.intensity = channel<double>(
      keys, "intensity",
      [](Params& k) { return k.require<double>("intensity", {.min = 0.0, .max = 1e12}); },
      nonNegative(keys.interpolation));
  motion.color = channel<glm::dvec3>(
      keys, "color",
      [](Params& k) { return glm::dvec3(k.require<glm::vec3>("color", {.min = glm::vec3(0.0f)})); },
      nonNegative(keys.interpolation));
  finishKeys(keys);
  if (motion.position.empty() && motion.direction.empty() && motion.intensity.empty() &&
      motion.color.empty())
    throw Error(p.where("keys") + ": light '" + name + "' is keyed but no key changes it (a " +
                (light.type == LightType::Point  ? "point light has position"
                 : light.type == LightType::Spot ? "spot light has position, direction"
                                                 : "directional light has direction") +
                ", intensity, color)");
  return motion;
}

MeshMotion readMeshMotion(Params p, double fps, const Scene& scene) {
  MeshMotion motion;
  const std::vector<std::string> names = p.require<std::vector<std::string>>("meshes");
  if (names.empty()) throw Error(p.where("meshes") + ": names no mesh");
  Bounds bounds;
  for (const std::string& name : names) {
    bool found = false;
    // Every mesh of that name: an instanced object flattened at load keeps its name per instance.
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
      if (scene.meshes[i].name != name) continue;
      found = true;
      motion.meshes.push_back(int(i));
      motion.restPositions.push_back(scene.meshes[i].positions);
      motion.restNormals.push_back(scene.meshes[i].normals);
      for (const glm::vec3& position : scene.meshes[i].positions) bounds.extend(position);
    }
    if (!found) uniqueNamed(p, "meshes", name, scene.meshes, scene, "mesh");  // throws the error
  }
  motion.pivot = glm::dvec3(p.get<glm::vec3>("pivot", bounds.center()));
  Keys keys = readKeys(p, fps);
  motion.translation =
      channel<glm::dvec3>(keys, "translation", [](Params& k) { return vector(k, "translation"); });
  motion.rotation = channel<glm::dquat>(keys, "rotation_deg", [](Params& k) {
    // Degrees about x, then y, then z (extrinsic), as a quaternion.
    const glm::dvec3 angles = kDegrees * vector(k, "rotation_deg");
    return glm::angleAxis(angles.z, glm::dvec3(0, 0, 1)) *
           glm::angleAxis(angles.y, glm::dvec3(0, 1, 0)) *
           glm::angleAxis(angles.x, glm::dvec3(1, 0, 0));
  });
  finishKeys(keys);
  if (motion.translation.empty() && motion.rotation.empty())
    throw Error(p.where("keys") + ": no key gives translation or rotation_deg");
  return motion;
}

// The scene file's node animations named `name` ("all": every one), as mesh motions.
std::vector<MeshMotion> sceneNodeMotions(Params& p, const Scene& scene) {
  const std::string name = p.require<std::string>("scene_animation");
  std::vector<std::string> names;
  for (const NodeAnimation& node : scene.nodeAnimations)
    if (std::find(names.begin(), names.end(), node.animation) == names.end())
      names.push_back(node.animation);
  if (names.empty())
    throw Error(p.where("scene_animation") + ": " + scene.source + " has no node animations");
  if (name != "all" && std::find(names.begin(), names.end(), name) == names.end()) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
    throw Error(p.where("scene_animation") + ": " + scene.source + " has no animation '" + name +
                "' (it has " + list + "; \"all\" plays every one)");
  }
  std::vector<MeshMotion> motions;
  for (const NodeAnimation& node : scene.nodeAnimations) {
    if (name != "all" && node.animation != name) continue;
    if (node.meshes.empty()) continue;  // moves no mesh (a camera or light node: not played)
    const std::string what = p.where("scene_animation") + ": animation '" + node.animation +
                             "', node '" + node.node + "'";
    MeshMotion motion;
    motion.meshes = node.meshes;
    for (int mesh : node.meshes) {
      motion.restPositions.push_back(scene.meshes[std::size_t(mesh)].positions);
      motion.restNormals.push_back(scene.meshes[std::size_t(mesh)].normals);
    }
    motion.pivot = node.pivot;
    try {
      if (!node.translationTimes.empty())
        motion.translation =
            KeyframeTrack<glm::dvec3>(node.translationTimes, node.translations,
                                      interpolationNamed(node.translationInterpolation));
      if (!node.rotationTimes.empty())
        motion.rotation = KeyframeTrack<glm::dquat>(node.rotationTimes, node.rotations,
                                                    interpolationNamed(node.rotationInterpolation));
    } catch (const Error& error) {
      throw Error(what + ": " + error.what());
    }
    motions.push_back(std::move(motion));
  }
  return motions;
}

}  // namespace

Animation readAnimation(Params p, const Scene& scene, Camera& camera, bool cameraGiven) {
  Animation animation;
  animation.frames = p.get<int>("frames", 1, {.min = 1, .max = 1000000});
  animation.fps = p.get<double>("fps", 30.0, {.min = 1e-3, .max = 1e6});
  animation.video = p.get<bool>("video", true);
  if (p.has("camera"))
    animation.camera =
        readCameraMotion(p.table("camera"), animation.fps, scene, camera, cameraGiven);
  for (Params& lightParams : p.tables("lights")) {
    animation.lights.push_back(readLightMotion(lightParams, animation.fps, scene));
    for (std::size_t i = 0; i + 1 < animation.lights.size(); ++i)
      if (animation.lights[i].light == animation.lights.back().light)
        throw Error(lightParams.where("light") +
                    ": this light is already animated by an earlier "
                    "[[animation.lights]]; key all its quantities in one");
  }
  std::vector<int> moved;
  if (p.has("scene_animation")) {
    animation.meshes = sceneNodeMotions(p, scene);
    for (const MeshMotion& motion : animation.meshes)
      moved.insert(moved.end(), motion.meshes.begin(), motion.meshes.end());
  }
  for (Params& meshParams : p.tables("meshes")) {
    animation.meshes.push_back(readMeshMotion(meshParams, animation.fps, scene));
    for (int mesh : animation.meshes.back().meshes) {
      if (std::find(moved.begin(), moved.end(), mesh) != moved.end())
        throw Error(meshParams.where("meshes") + ": mesh '" + scene.meshes[std::size_t(mesh)].name +
                    "' is already moved by an earlier [[animation.meshes]] or the scene's "
                    "animation (scene_animation)");
      moved.push_back(mesh);
    }
  }
  // Every frame's camera and lights, checked now through the code that renders them (meshes are
  // rigid: finite keys stay finite).
  Animation cameraOnly, lightsOnly;
  cameraOnly.camera = animation.camera;
  lightsOnly.lights = animation.lights;
  Scene lights;
  lights.lights = scene.lights;
  Camera probe = camera;
  for (int frame = 0; frame < animation.frames; ++frame) {
    const double seconds = animation.frameTime(frame);
    for (const auto& [only, key] :
         {std::pair{&cameraOnly, "camera"}, std::pair{&lightsOnly, "lights"}}) {
      try {
        applyAnimation(*only, seconds, lights, probe);
      } catch (const Error& error) {
        throw Error(p.where(key) + ": frame " + std::to_string(frame) + ": " + error.what());
      }
    }
  }
  return animation;
}

}  // namespace lpvlab

#include "framework/particles/particle_file.h"

#include <cmath>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

constexpr double kDegrees = M_PI / 180.0;

EmitterShape shapeNamed(const std::string& name) {
  if (name == "sphere") return EmitterShape::Sphere;
  if (name == "box") return EmitterShape::Box;
  if (name == "disk") return EmitterShape::Disk;
  return EmitterShape::Point;
}

Emitter readEmitter(Params& p, int index) {
  Emitter e;
  e.name = p.get<std::string>("name", "emitter" + std::to_string(index));
  e.shape = shapeNamed(p.getChoice("shape", "point", {"point", "sphere", "box", "disk"}));
  e.position = glm::dvec3(p.require<glm::vec3>("position"));
  if (e.shape == EmitterShape::Sphere || e.shape == EmitterShape::Disk)
    e.radius = p.require<double>("radius", {.min = 0.0, .max = 1e6});
  if (e.shape == EmitterShape::Box)
    e.halfExtent = glm::dvec3(p.require<glm::vec3>("half_extent", {.min = glm::vec3(0.0f), .max = glm::vec3(1e6f)}));
  e.rate = p.require<double>("rate", {.min = 0.0, .max = 1e7});
  if (!(e.rate > 0.0)) throw Error(p.where("rate") + ": must be above 0 (births per second)");
  const glm::dvec3 direction(p.get<glm::vec3>("direction", glm::vec3(0, 1, 0)));
  if (!(glm::length(direction) > 1e-9)) throw Error(p.where("direction") + ": must not be zero");
  e.direction = glm::normalize(direction);
  e.spread = kDegrees * p.get<double>("spread_deg", 0.0, {.min = 0.0, .max = 180.0});
  e.radial = e.shape == EmitterShape::Sphere && p.get<bool>("radial", false);
  e.speed = p.get<double>("speed", 1.0, {.min = 0.0, .max = 1e6});
  e.speedVariation = p.get<double>("speed_variation", 0.0, {.min = 0.0, .max = 1e6});
  if (e.speedVariation > e.speed)
    throw Error(p.where("speed_variation") + ": " + std::to_string(e.speedVariation) +
                " exceeds speed " + std::to_string(e.speed) + " (a speed would be negative)");
  e.lifetime = p.require<double>("lifetime", {.min = 0.0, .max = 1e6});
  e.lifetimeVariation = p.get<double>("lifetime_variation", 0.0, {.min = 0.0, .max = 1e6});
  if (!(e.lifetime - e.lifetimeVariation > 0.0))
    throw Error(p.where(e.lifetimeVariation > 0.0 ? "lifetime_variation" : "lifetime") +
                ": every lifetime must be above 0 s (lifetime " + std::to_string(e.lifetime) +
                " s, variation " + std::to_string(e.lifetimeVariation) + " s)");
  p.finish();
  return e;
}

// [[particles.over_life]]: keys at `life` (the fraction of the life lived, increasing in
// [0, 1]), each giving `size`, `color` or both.
void readOverLife(Params& p, ParticleSystem& system) {
  std::vector<double> sizeTimes, colorTimes, sizes;
  std::vector<glm::dvec3> colors;
  double previous = -1.0;
  for (Params& key : p.tables("over_life")) {
    const double life = key.require<double>("life", {.min = 0.0, .max = 1.0});
    if (!(life > previous))
      throw Error(key.where("life") + ": keys must be in increasing life (" + std::to_string(life) +
                  " does not come after " + std::to_string(previous) + ")");
    previous = life;
    if (!key.has("size") && !key.has("color"))
      throw Error(key.where("life") + ": the key gives neither size nor color");
    if (key.has("size")) {
      sizeTimes.push_back(life);
      sizes.push_back(key.require<double>("size", {.min = 0.0, .max = 1e6}));
    }
    if (key.has("color")) {
      colorTimes.push_back(life);
      colors.push_back(glm::dvec3(key.require<glm::vec3>("color", {.min = glm::vec3(0.0f), .max = glm::vec3(1.0f)})));
    }
    key.finish();
  }
  if (!sizes.empty()) system.sizeOverLife = KeyframeTrack<double>(sizeTimes, sizes, Interpolation::Linear);
  if (!colors.empty())
    system.colorOverLife = KeyframeTrack<glm::dvec3>(colorTimes, colors, Interpolation::Linear);
}

}  // namespace

ParticleSettings readParticleSettings(Params p, int index) {
  ParticleSettings settings{{}, {}, {}, {}, p};
  ParticleSystem& system = settings.system;
  system.name = p.get<std::string>("name", "particles" + std::to_string(index));
  if (!p.has("model"))
    throw Error(p.where("model") + ": a particle system needs a model (a scene file whose meshes "
                                   "each particle copies, e.g. \"models/crystal.obj\")");
  settings.model = p.require<std::string>("model");
  settings.modelMeshes = p.get<std::vector<std::string>>("model_meshes", {});
  system.seed = std::uint64_t(p.get<int>("seed", 1, {.min = 0}));
  system.gravity = glm::dvec3(p.get<glm::vec3>("gravity", glm::vec3(0.0f, -9.81f, 0.0f)));
  system.prewarm = p.get<double>("prewarm", 0.0, {.min = 0.0, .max = 1e6});
  system.randomRotation = p.get<bool>("random_rotation", true);
  system.spin = kDegrees * p.get<double>("spin_deg", 0.0, {.min = -1e6, .max = 1e6});
  system.size = p.get<double>("size", 0.1, {.min = 0.0, .max = 1e6});
  system.color = glm::dvec3(p.get<glm::vec3>("color", glm::vec3(1.0f), {.min = glm::vec3(0.0f), .max = glm::vec3(1.0f)}));
  // How the LPV pipeline draws the particles: as the scene's geometry, or as billboards showing
  // the model's light field (its view grid and resolution, one view or four blended).
  // The light field's keys are read (and checked) with either drawing, so that a sweep over
  // `draw` can keep them in its base file.
  settings.drawing.lightField = p.getChoice("draw", "geometry", {"geometry", "light_field"}) == "light_field";
  settings.drawing.views = {p.get<int>("azimuths", 16, {.min = 1, .max = 1024}),
                            p.get<int>("elevations", 8, {.min = 1, .max = 1024})};
  settings.drawing.resolution = p.get<int>("resolution", 64, {.min = 1, .max = 4096});
  settings.drawing.interpolate = p.get<bool>("interpolate", true);
  settings.drawing.interpolateShadows = p.get<bool>("interpolate_shadows", false);
  settings.drawing.inject = p.get<bool>("inject", true);
  readOverLife(p, system);
  std::vector<Params> emitters = p.tables("emitters");
  if (emitters.empty())
    throw Error(p.where("emitters") + ": a particle system needs at least one [[particles.emitters]]");
  for (std::size_t i = 0; i < emitters.size(); ++i)
    system.emitters.push_back(readEmitter(emitters[i], int(i)));
  return settings;
}

}  // namespace lpvlab

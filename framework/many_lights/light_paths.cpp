#include "framework/many_lights/light_paths.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/math/shared.h"
#include "framework/reference/hemisphere_sampling.h"
#include "framework/reference/random.h"

namespace lpvlab {

namespace {

double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// The integral of the spot falloff (shaders/common/lights.glsl) over cos(theta) in [cosOuter, 1]:
// t = clamp((c - cosOuter) / s, 0, 1)^2 with s = max(0.001, cosInner - cosOuter).
double spotFalloffIntegral(double cosInner, double cosOuter) {
  const double s = std::max(0.001, cosInner - cosOuter), span = 1.0 - cosOuter;
  if (span <= s) return std::pow(span / s, 3.0) * s / 3.0;
  return s / 3.0 + (span - s);
}

// A uniform direction in the cone of half-angle acos(cosMax) about unit `axis`.
glm::vec3 coneDirection(const glm::vec3& axis, double cosMax, float u1, float u2) {
  const double cosTheta = 1.0 - u1 * (1.0 - cosMax);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  const double phi = 2.0 * M_PI * u2;
  const glm::vec3 t = std::abs(axis.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 tangent = glm::normalize(glm::cross(axis, t));
  const glm::vec3 bitangent = glm::cross(axis, tangent);
  return glm::normalize(float(sinTheta * std::cos(phi)) * tangent +
                        float(sinTheta * std::sin(phi)) * bitangent + float(cosTheta) * axis);
}

struct Emission {
  glm::vec3 origin, direction;
  glm::vec3 flux;  // W per channel, for this walk
};

class Emitter {
public:
  Emitter(const RayScene& scene, int paths) : lights_(scene.lights()), paths_(paths) {
    const Bounds& b = scene.bounds();
    centre_ = b.center();
    radius_ = 0.5 * glm::length(glm::dvec3(b.extent())) * 1.01 + 1e-6;
    double total = 0.0;
    for (const PunctualLight& light : lights_) {
      const glm::dvec3 power = lightPower(light, radius_);
      emitted_ += power;
      total += luminance(power);
      cumulative_.push_back(total);
    }
    if (!std::isfinite(total))
      throw Error("light paths: the scene's lights emit an infinite power");
    if (total > 0.0)
      for (double& c : cumulative_) c /= total;
  }

  // Lights of zero power (black, or intensity 0): no walk starts, no VPL, a black image.
  bool dark() const { return cumulative_.empty() || !(cumulative_.back() > 0.0); }

  const glm::dvec3& emitted() const { return emitted_; }

  Emission emit(SampleRandom& random) const {
    const float pick = random.uniform();
    const std::size_t i = std::min<std::size_t>(
        std::upper_bound(cumulative_.begin(), cumulative_.end(), double(pick)) - cumulative_.begin(),
        lights_.size() - 1);
    const PunctualLight& light = lights_[i];
    const double chance = (cumulative_[i] - (i ? cumulative_[i - 1] : 0.0));
    const double scale = 1.0 / (chance * paths_);
    const float u1 = random.uniform(), u2 = random.uniform();
    Emission e;
    switch (light.type) {
      case LightType::Point: {
        const double z = 1.0 - 2.0 * u1, r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = 2.0 * M_PI * u2;
        e.origin = light.position;
        e.direction = glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
        e.flux = glm::vec3(glm::dvec3(light.radiant) * (4.0 * M_PI * scale));
        break;
      }
      case LightType::Spot: {
        e.origin = light.position;
        e.direction = coneDirection(light.direction, light.cosOuter, u1, u2);
        const double falloff = shared::spotFalloff(double(glm::dot(light.direction, e.direction)),
                                                   light.cosInner, light.cosOuter);
        e.flux = glm::vec3(glm::dvec3(light.radiant) *
                           (falloff * 2.0 * M_PI * (1.0 - light.cosOuter) * scale));
        break;
      }
      case LightType::Directional: {
        // A uniform point on the disk across the light, outside the scene's bounding sphere.
        const glm::vec3 axis = light.direction;
        const glm::vec3 t = std::abs(axis.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 tangent = glm::normalize(glm::cross(axis, t));
        const glm::vec3 bitangent = glm::cross(axis, tangent);
        const double r = radius_ * std::sqrt(double(u1)), phi = 2.0 * M_PI * u2;
        e.origin = centre_ - float(2.0 * radius_) * axis + float(r * std::cos(phi)) * tangent +
                   float(r * std::sin(phi)) * bitangent;
        e.direction = axis;
        e.flux = glm::vec3(glm::dvec3(light.radiant) * (M_PI * radius_ * radius_ * scale));
        break;
      }
    }
    return e;
  }

private:
  const std::vector<PunctualLight>& lights_;
  int paths_;
  glm::vec3 centre_;
  double radius_ = 0.0;
  std::vector<double> cumulative_;
  glm::dvec3 emitted_{0.0};
};

// One packet of walks: their VPLs in walk order, bounce by bounce merged per walk.
struct PacketWalks {
  std::vector<std::vector<Vpl>> perWalk;
  std::size_t rays = 0;
};

void walkPacket(const RayScene& scene, const Emitter& emitter, const LightPathSettings& settings,
                int firstWalk, int walks, PacketWalks& out) {
  const EmbreeScene& embree = scene.embree();
  out.perWalk.assign(std::size_t(walks), {});
  SampleRandom randoms[kPacketWidth];
  glm::vec3 flux[kPacketWidth];
  RayPacket packet;
  for (int lane = 0; lane < walks; ++lane) {
    const std::uint64_t walk = std::uint64_t(firstWalk + lane);
    randoms[lane] = settings.sampler == SampleSequence::Sobol
                        ? SampleRandom(settings.seed, 0, walk, SampleSequence::Sobol)  // point `walk`
                        : SampleRandom(settings.seed, walk, 0);                        // stream `walk`
    const Emission e = emitter.emit(randoms[lane]);
    flux[lane] = e.flux;
    if (glm::any(glm::greaterThan(e.flux, glm::vec3(0.0f))))
      packet.set(lane, e.origin, e.direction, 0.0f, std::numeric_limits<float>::infinity());
  }
  for (int bounce = 1; packet.any(); ++bounce) {
    for (int lane = 0; lane < kPacketWidth; ++lane) out.rays += packet.active(lane) ? 1 : 0;
    embree.intersect(packet, bounce == 1);
    for (int lane = 0; lane < walks; ++lane) {
      if (!packet.active(lane)) continue;
      if (!packet.hit(lane)) {
        packet.deactivate(lane);
        continue;
      }
      const RayHit hit = packet.hitAt(lane);
      const glm::vec3 origin(packet.query.ray.org_x[lane], packet.query.ray.org_y[lane],
                             packet.query.ray.org_z[lane]);
      const glm::vec3 direction(packet.query.ray.dir_x[lane], packet.query.ray.dir_y[lane],
                                packet.query.ray.dir_z[lane]);
      const SurfacePoint x = surfaceAt(embree, hit, origin, direction);
      const glm::vec3 albedo = surfaceAlbedo(x);
      const glm::vec3 reflected = flux[lane] * albedo;
      if (glm::any(glm::greaterThan(reflected, glm::vec3(0.0f))))
        out.perWalk[std::size_t(lane)].push_back(Vpl{x.position, x.shadingNormal, reflected, bounce});
      bool goes = !settings.firstHitsOnly && bounce < settings.maxBounces;
      float survival = 1.0f;
      SampleRandom& random = randoms[lane];
      if (goes && bounce >= settings.rouletteAfter) {
        survival = std::min(0.95f, std::max({albedo.r, albedo.g, albedo.b}));
        goes = random.uniform() < survival;
      }
      glm::vec3 next(0.0f);
      if (goes) {
        const float u1 = random.uniform(), u2 = random.uniform();
        next = cosineHemisphere(x.shadingNormal, u1, u2);
        // A shading normal that leans past the geometric one can send the walk into the surface.
        const float side = glm::dot(x.geometricNormal, -direction);
        goes = glm::dot(x.geometricNormal, next) * side > 0.0f;
      }
      if (!goes) {
        packet.deactivate(lane);
        continue;
      }
      flux[lane] = reflected / survival;
      packet.set(lane, offsetRayOrigin(embree, x, next), next, 0.0f,
                 std::numeric_limits<float>::infinity());
    }
  }
}

}  // namespace

glm::dvec3 lightPower(const PunctualLight& light, double sceneRadius) {
  const glm::dvec3 radiant(light.radiant);
  switch (light.type) {
    case LightType::Point:
      return radiant * (4.0 * M_PI);
    case LightType::Spot:
      return radiant * (2.0 * M_PI * spotFalloffIntegral(light.cosInner, light.cosOuter));
    case LightType::Directional:
      return radiant * (M_PI * sceneRadius * sceneRadius);
  }
  return glm::dvec3(0.0);
}

std::vector<Vpl> traceLightPaths(const RayScene& scene, const LightPathSettings& settings,
                                 LightPathCounts* counts) {
  if (settings.paths < 1) throw Error("light paths: at least one walk is needed");
  const Emitter emitter(scene, settings.paths);
  if (emitter.dark()) {
    if (counts) *counts = {};
    return {};
  }
  const int packets = (settings.paths + kPacketWidth - 1) / kPacketWidth;
  std::vector<PacketWalks> results(static_cast<std::size_t>(packets));
  tbb::parallel_for(tbb::blocked_range<int>(0, packets), [&](const tbb::blocked_range<int>& range) {
    for (int p = range.begin(); p != range.end(); ++p)
      walkPacket(scene, emitter, settings, p * kPacketWidth,
                 std::min(kPacketWidth, settings.paths - p * kPacketWidth),
                 results[std::size_t(p)]);
  });
  std::vector<Vpl> vpls;
  std::size_t rays = 0;
  for (const PacketWalks& packet : results) {
    rays += packet.rays;
    for (const std::vector<Vpl>& walk : packet.perWalk) vpls.insert(vpls.end(), walk.begin(), walk.end());
  }
  if (counts) *counts = {vpls.size(), rays, emitter.emitted()};
  return vpls;
}

}  // namespace lpvlab

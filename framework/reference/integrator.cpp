#include "framework/reference/integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/error.h"
#include "framework/math/shared.h"
#include "framework/reference/hemisphere_sampling.h"
#include "framework/reference/punctual_arrival.h"

namespace lpvlab {

namespace {

constexpr float kInvPi = float(1.0 / M_PI);
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Adds a contribution with `scatterings` scatterings to the AOVs it belongs to.
void attribute(PathSample& sample, int scatterings, const glm::vec3& radiance) {
  if (scatterings <= 1) {
    sample.direct += radiance;
    return;
  }
  sample.indirect += radiance;
  if (scatterings == 2) sample.indirect1 += radiance;
}

float largestChannel(const glm::vec3& c) { return std::max({c.r, c.g, c.b}); }

}  // namespace

Integrator::Integrator(const EmbreeScene& scene, const LightSampler& lights,
                       const CameraRays* camera, const TracerSettings& settings)
    : scene_(scene),
      lights_(lights),
      camera_(camera),
      sky_(settings.skyRadiance),
      hasSky_(glm::any(glm::greaterThan(settings.skyRadiance, glm::vec3(0.0f)))),
      emission_(settings.emission),
      glossy_(settings.glossy),
      maxBounces_(settings.maxBounces),
      rouletteAfter_(settings.rouletteAfter) {
  if (settings.maxBounces < 0 || settings.rouletteAfter < 0)
    throw Error("path tracer: maxBounces and rouletteAfter must not be negative");
  for (int i = 0; i < 3; ++i) {
    requireFinite(sky_[i], "path tracer", "sky radiance");
    if (sky_[i] < 0.0f) throw Error("path tracer: sky radiance is negative");
  }
}


void Integrator::queueNextEvents(const SurfacePoint& x, const VertexBrdf& brdf, int lane,
                                 int scatterings, SampleRandom& random,
                                 std::vector<ShadowQuery>& shadows) const {
  const glm::vec3 n = x.shadingNormal;
  const float epsilon = scene_.epsilon();
  auto queue = [&](const glm::vec3& direction, float tFar, const glm::vec3& irradiance) {
    shadows.push_back({lane, scatterings, offsetOrigin(x, direction), direction, tFar,
                       brdf.reflectance(n, direction) * irradiance});
  };

  // Every punctual light: E = I falloff cos / r^2 (point, spot) or E_perp cos (directional).
  for (const PunctualLight& light : lights_.punctual()) {
    PunctualArrival a;
    if (!punctualArrival(light, x.position, a)) continue;
    const float cosine = glm::dot(n, a.toLight);
    if (cosine > 0.0f && glm::any(glm::greaterThan(a.arriving, glm::vec3(0.0f))))
      queue(a.toLight, a.distance, a.arriving * cosine);
  }

  // One point on one emissive triangle, MIS-weighted against the BRDF-sampled continuation; the
  // shadow ray stops short of the light's own triangle.
  if (emission_ && lights_.hasEmitters()) {
    const float pick = random.uniform();
    const float s = random.uniform();
    const float t = random.uniform();
    EmitterSample light;
    if (lights_.sampleEmitter(x.position, pick, s, t, light)) {
      const float cosine = glm::dot(n, light.direction);
      if (cosine > 0.0f)
        queue(light.direction, light.distance - 2.0f * epsilon,
              light.radiance * (cosine / light.pdf * powerHeuristic(light.pdf, brdf.pdf(n, light.direction))));
    }
  }

  // The sky from a cosine-weighted direction: L cos / pdf = pi L, MIS weight 1/2 (see the header).
  if (hasSky_) {
    const float u1 = random.uniform();
    const float u2 = random.uniform();
    const glm::vec3 direction = cosineHemisphere(n, u1, u2);
    const float pdf = glm::dot(n, direction) * kInvPi;
    if (pdf > 0.0f && !brdf.phong) queue(direction, kInfinity, sky_ * (float(M_PI) * powerHeuristic(pdf, pdf)));
    // A glossy BRDF samples other directions: E's estimate L cos / pdf, weighed against its density.
    if (pdf > 0.0f && brdf.phong)
      queue(direction, kInfinity, sky_ * (glm::dot(n, direction) / pdf * powerHeuristic(pdf, brdf.pdf(n, direction))));
  }
}

float Integrator::emissionWeight(const SurfacePoint& x, const RayHit& hit,
                                 const glm::vec3& direction, float brdfPdf) const {
  if (!lights_.hasEmitters()) return 1.0f;  // emitters of zero area: BRDF sampling only
  const int emitter = lights_.firstEmitterOfMesh(x.geometry->meshIndex) + int(hit.primID);
  const float cosAtEmitter = std::abs(glm::dot(x.geometricNormal, direction));
  return powerHeuristic(brdfPdf, lights_.emitterPdf(emitter, hit.distance, cosAtEmitter));
}

bool Integrator::scatter(const SurfacePoint& x, const RayHit& hit, int lane, PathState& path,
                         PathSample& sample, SampleRandom& random,
                         std::vector<ShadowQuery>& shadows) const {
  const SurfaceMaterial& material = *x.geometry->material;
  if (material.emissive && emission_) {
    const float weight =
        path.scatterings == 0 ? 1.0f : emissionWeight(x, hit, path.direction, path.brdfPdf);
    attribute(sample, path.scatterings, path.throughput * material.emission * weight);
  }
  const glm::vec3 albedo = surfaceAlbedo(x);
  if (path.scatterings == 0) {  // a camera path's first hit
    sample.albedo = albedo;
    sample.normal = x.shadingNormal;
    sample.depth = camera_->viewDepth(x.position);
  }
  const int scatterings = ++path.scatterings;  // light leaving x towards the camera scatters here
  if (glossy_ && glossyMaterial(material)) {
    const PhongBrdf phong = phongAt(material, albedo);
    if (scatterings > maxBounces_ || largestChannel(phong.diffuse + phong.specular) <= 0.0f) return false;
    return scatterGlossy(x, phong, lane, path, random, shadows);
  }
  if (scatterings > maxBounces_ || largestChannel(albedo) <= 0.0f) return false;

  queueNextEvents(x, {path.throughput * albedo * kInvPi}, lane, scatterings, random, shadows);

  // At the last permitted vertex only emission or sky can still be found by the continuation.
  if (scatterings == maxBounces_ && !(emission_ && lights_.hasEmitters()) && !hasSky_) return false;
  if (scatterings > rouletteAfter_) {
    const float survival = std::min(0.95f, largestChannel(albedo));
    if (random.uniform() >= survival) return false;
    path.throughput /= survival;
  }
  path.throughput *= albedo;  // Lambertian: BRDF cos / pdf = albedo for cosine-weighted directions

  const float u1 = random.uniform();
  const float u2 = random.uniform();
  path.direction = cosineHemisphere(x.shadingNormal, u1, u2);
  path.brdfPdf = glm::dot(x.shadingNormal, path.direction) * kInvPi;
  path.skyPdf = path.brdfPdf;
  path.origin = offsetOrigin(x, path.direction);
  return true;
}

bool Integrator::scatterGlossy(const SurfacePoint& x, const PhongBrdf& phong, int lane,
                               PathState& path, SampleRandom& random,
                               std::vector<ShadowQuery>& shadows) const {
  const glm::vec3 n = x.shadingNormal, wo = -path.direction;
  queueNextEvents(x, {glm::vec3(0.0f), &phong, path.throughput, wo}, lane, path.scatterings, random,
                  shadows);
  if (path.scatterings == maxBounces_ && !(emission_ && lights_.hasEmitters()) && !hasSky_) return false;
  if (path.scatterings > rouletteAfter_) {
    const float survival = std::min(0.95f, largestChannel(phong.diffuse + phong.specular));
    if (random.uniform() >= survival) return false;
    path.throughput /= survival;
  }
  const float u0 = random.uniform(), u1 = random.uniform(), u2 = random.uniform();
  glm::vec3 wi;
  if (!phong.sample(n, wo, u0, u1, u2, wi)) return false;  // below the horizon: not reflected
  const float pdf = phong.pdf(n, wo, wi), cosine = glm::dot(n, wi);
  if (!(pdf > 0.0f)) return false;
  path.throughput *= phong.evaluate(n, wo, wi) * (cosine / pdf);
  path.direction = wi;
  path.brdfPdf = pdf;
  path.skyPdf = cosine * kInvPi;  // the density next-event estimation draws the sky with
  path.origin = offsetOrigin(x, wi);
  return true;
}

void Integrator::resolveShadows(const std::vector<ShadowQuery>& shadows,
                                PathSample* samples) const {
  for (std::size_t first = 0; first < shadows.size(); first += kPacketWidth) {
    const int count = int(std::min<std::size_t>(kPacketWidth, shadows.size() - first));
    ShadowPacket packet;
    for (int i = 0; i < count; ++i) {
      const ShadowQuery& query = shadows[first + i];
      packet.set(i, query.origin, query.direction, scene_.epsilon(), query.tFar);
    }
    scene_.occluded(packet);
    for (int i = 0; i < count; ++i) {
      const ShadowQuery& query = shadows[first + i];
      ++samples[query.lane].rays;
      if (!packet.occluded(i)) attribute(samples[query.lane], query.scatterings, query.radiance);
    }
  }
}

void Integrator::trace(int lanes, const glm::vec2* positions, SampleRandom* randoms,
                       PathSample* samples, std::vector<ShadowQuery>& shadows) const {
  if (!camera_) throw Error("path tracer: camera paths need a camera");
  PathState paths[kPacketWidth];
  RayPacket rays;
  for (int lane = 0; lane < lanes; ++lane) {
    const glm::vec3 direction = camera_->direction(positions[lane].x, positions[lane].y);
    paths[lane] = {camera_->origin(), direction, glm::vec3(1.0f), 0.0f, 0.0f, 0, false};
    rays.set(lane, camera_->origin(), direction, camera_->nearDistance(direction),
             camera_->farDistance(direction));
  }
  tracePaths(lanes, paths, rays, true, randoms, samples, shadows, nullptr);
}

void Integrator::trace(int lanes, const PathStart* starts, SampleRandom* randoms,
                       PathSample* samples, std::vector<ShadowQuery>& shadows,
                       const FirstHitWeight* weight) const {
  PathState paths[kPacketWidth];
  RayPacket rays;
  for (int lane = 0; lane < lanes; ++lane) {
    const PathStart& start = starts[lane];
    paths[lane] = {start.origin, start.direction, start.throughput, start.brdfPdf,
                   start.brdfPdf, start.scatterings, std::isinf(start.tFar)};
    rays.set(lane, start.origin, start.direction, start.tNear, start.tFar);
  }
  tracePaths(lanes, paths, rays, false, randoms, samples, shadows, weight);
}

void Integrator::tracePaths(int lanes, PathState* paths, RayPacket& rays, bool coherent,
                            SampleRandom* randoms, PathSample* samples,
                            std::vector<ShadowQuery>& shadows, const FirstHitWeight* weight) const {
  for (int lane = 0; lane < lanes; ++lane) samples[lane] = PathSample{};
  // Bounce by bounce: a lane stays active while its path goes on, and gets its next ray in place.
  for (bool first = true; rays.any(); first = false) {
    scene_.intersect(rays, first && coherent);
    shadows.clear();
    for (int lane = 0; lane < lanes; ++lane) {
      if (!rays.active(lane)) continue;
      PathState& path = paths[lane];
      PathSample& sample = samples[lane];
      ++sample.rays;
      bool goesOn = false;
      if (rays.hit(lane)) {
        const RayHit hit = rays.hitAt(lane);
        const SurfacePoint x = surfaceAt(scene_, hit, path.origin, path.direction);
        if (first && weight) path.throughput *= (*weight)(lane, x);
        if (largestChannel(path.throughput) > 0.0f)
          goesOn = scatter(x, hit, lane, path, sample, randoms[lane], shadows);
      } else if (hasSky_ && path.scatterings > 0 && path.skyOnMiss) {
        // The camera's own misses are background (zero); later ones see the sky.
        attribute(sample, path.scatterings,
                  path.throughput * sky_ * powerHeuristic(path.brdfPdf, path.skyPdf));
      }
      if (goesOn) {
        path.skyOnMiss = true;
        rays.set(lane, path.origin, path.direction, scene_.epsilon(), kInfinity);
      } else {
        rays.deactivate(lane);
      }
    }
    resolveShadows(shadows, samples);
  }
}

}  // namespace lpvlab

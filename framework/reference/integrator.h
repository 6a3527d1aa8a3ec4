#pragma once
// Paths from the camera through Lambertian surfaces, with next-event estimation at every surface
// vertex, cosine-weighted BRDF sampling to continue, and Russian roulette. Up to kPacketWidth
// paths are traced together, bounce by bounce, so their rays go to Embree as packets; each path
// draws only from its own random stream.
//
// Scattering count. A contribution has k scatterings when light changed direction at k surface
// vertices on its way to the camera: emission seen at the first hit has 0; next-event estimation
// at vertex k, and emission (or sky) found by the ray leaving vertex k, have k. AOVs:
//   direct     k = 0 or 1      indirect   k >= 2      indirect1  k = 2
// Area lights and the sky are reached by two strategies (next-event estimation and the BRDF-sampled
// continuation), combined with the power heuristic; emission seen from the camera (k = 0) has one
// strategy only and counts in full. Punctual lights are found by next-event estimation alone.
//
// Sky (TracerSettings::skyRadiance, a constant environment): next-event estimation draws a
// cosine-weighted direction, the same density as BRDF sampling, so the power heuristic weighs
// each strategy 1/2: two independent visibility samples of the sky per vertex. A camera ray that
// hits nothing returns zero in every AOV (the LPV pipeline's background is 0), sky or not.
//
// Russian roulette: from vertex rouletteAfter + 1 on, a path continues with probability
// min(0.95, largest albedo channel) and its throughput is divided by that probability (unbiased).
// maxBounces caps k: vertices beyond it are not lit, and their emission is not counted.
//
// Paths from the camera are the reference's. A caller can also start paths at a surface
// (PathStart): light found along them counts the scatterings the start says it already has, and
// a weight of the first hit scales all that the path finds beyond it (how the many-light
// methods' clamp compensation weighs a path by where its first ray lands: clamp_compensation.h).

#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "framework/reference/camera_rays.h"
#include "framework/reference/embree_scene.h"
#include "framework/reference/light_sampler.h"
#include "framework/reference/phong_brdf.h"
#include "framework/reference/path_tracer.h"
#include "framework/reference/random.h"
#include "framework/reference/ray_packets.h"

namespace lpvlab {

// One path's estimates (radiance in W/(m^2 sr)) and what its camera ray hit.
struct PathSample {
  glm::vec3 direct{0.0f}, indirect{0.0f}, indirect1{0.0f};
  glm::vec3 albedo{0.0f};  // first hit's; all first-hit values are zero when the camera ray misses
  glm::vec3 normal{0.0f};  // first hit's shading normal, facing the camera
  float depth = 0.0f;      // first hit's view depth, m (camera paths)
  int rays = 0;            // camera, continuation and shadow rays traced
};

// A shadow ray queued by next-event estimation: its radiance counts if nothing blocks it.
struct ShadowQuery {
  int lane;
  int scatterings;
  glm::vec3 origin, direction;
  float tFar;
  glm::vec3 radiance;  // W/(m^2 sr) towards the camera, throughput and MIS weight included
};

// A path that starts at a surface: its first ray (a unit direction) and what the light it finds
// is multiplied by. A miss before a finite tFar sees no sky (the ray was cut short, it did not
// escape).
struct PathStart {
  glm::vec3 origin, direction;
  float tNear, tFar;
  glm::vec3 throughput{1.0f};  // e.g. albedo: the start vertex's BRDF cos / pdf
  float brdfPdf = 0.0f;        // density of `direction`, 1/sr: MIS weight of emission it hits
  int scatterings = 1;         // vertices the light will already have scattered at
};

// Scales a path's throughput at its first hit (RGB; zero in every channel ends the path).
using FirstHitWeight = std::function<glm::vec3(int lane, const SurfacePoint& hit)>;

class Integrator {
public:
  // Throws an Error for settings out of range (negative bounce counts, a negative or non-finite
  // sky). Keeps references to its arguments. `camera` may be null for paths that start at
  // surfaces only.
  Integrator(const EmbreeScene& scene, const LightSampler& lights, const CameraRays* camera,
             const TracerSettings& settings);

  // Traces `lanes` (<= kPacketWidth) paths, path i through image position positions[i] in pixels
  // ((0, 0) the image's top-left corner) drawing from randoms[i], into samples[i]. `shadows` is
  // scratch space, kept by the caller so that tracing allocates nothing once it has grown.
  void trace(int lanes, const glm::vec2* positions, SampleRandom* randoms, PathSample* samples,
             std::vector<ShadowQuery>& shadows) const;
  // The same for paths that start at surfaces, with an optional weight of their first hits.
  // Their first-hit values (albedo, normal, depth) stay zero.
  void trace(int lanes, const PathStart* starts, SampleRandom* randoms, PathSample* samples,
             std::vector<ShadowQuery>& shadows, const FirstHitWeight* weight = nullptr) const;

private:

  // A path between bounces.
  struct PathState {
    glm::vec3 origin, direction;  // the ray being traced
    glm::vec3 throughput;         // product of albedo / survival probability so far
    float brdfPdf;                // density of `direction` (after the camera ray), 1/sr
    float skyPdf;                 // the density next-event estimation draws it with (sky MIS)
    int scatterings;              // surface vertices so far
    bool skyOnMiss;               // the ray runs to infinity: a miss sees the sky
  };

  // The bounce loop of both trace()s: `coherent` when the first rays are the camera's.
  void tracePaths(int lanes, PathState* paths, RayPacket& rays, bool coherent,
                  SampleRandom* randoms, PathSample* samples, std::vector<ShadowQuery>& shadows,
                  const FirstHitWeight* weight) const;

  glm::vec3 offsetOrigin(const SurfacePoint& x, const glm::vec3& direction) const {
    return offsetRayOrigin(scene_, x, direction);
  }
  // Everything at the vertex `hit`: emission, first-hit values, next-event shadow rays (queued),
  // roulette and the continuation direction. False when the path ends there.
  bool scatter(const SurfacePoint& x, const RayHit& hit, int lane, PathState& path,
               PathSample& sample, SampleRandom& random, std::vector<ShadowQuery>& shadows) const;
  // A vertex's BRDF as next-event estimation reads it: Lambertian, reflecting `lambertian` =
  // throughput * albedo / pi of the irradiance towards the camera, or the Phong BRDF seen from wo.
  struct VertexBrdf {
    glm::vec3 lambertian{0.0f};
    const PhongBrdf* phong = nullptr;
    glm::vec3 throughput{0.0f}, wo{0.0f};
    glm::vec3 reflectance(const glm::vec3& n, const glm::vec3& l) const {
      return phong ? throughput * phong->evaluate(n, wo, l) : lambertian;
    }
    float pdf(const glm::vec3& n, const glm::vec3& l) const {
      return phong ? phong->pdf(n, wo, l) : glm::dot(n, l) * float(1.0 / M_PI);
    }
  };
  // Queues next-event estimation at x, which reflects what `brdf` says of the irradiance it
  // receives towards the camera (area lights and sky MIS-weighted).
  void queueNextEvents(const SurfacePoint& x, const VertexBrdf& brdf, int lane, int scatterings,
                       SampleRandom& random, std::vector<ShadowQuery>& shadows) const;
  // scatter()'s next events and continuation at a glossy vertex ([reference] brdf = "phong").
  bool scatterGlossy(const SurfacePoint& x, const PhongBrdf& phong, int lane, PathState& path,
                     SampleRandom& random, std::vector<ShadowQuery>& shadows) const;
  // MIS weight of emission found by a BRDF-sampled ray with direction density `brdfPdf`.
  float emissionWeight(const SurfacePoint& x, const RayHit& hit, const glm::vec3& direction,
                       float brdfPdf) const;
  // Traces the queued shadow rays as packets and adds the unblocked ones' radiance.
  void resolveShadows(const std::vector<ShadowQuery>& shadows, PathSample* samples) const;

  const EmbreeScene& scene_;
  const LightSampler& lights_;
  const CameraRays* camera_;
  glm::vec3 sky_;
  bool hasSky_;
  bool emission_;  // emitters light the scene (TracerSettings::emission)
  bool glossy_;    // materials' Phong lobes are rendered (TracerSettings::glossy)
  int maxBounces_, rouletteAfter_;
};

}  // namespace lpvlab

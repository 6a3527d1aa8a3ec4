#pragma once
// Rays traced together, 16 at a time. Embree tests a BVH node or a triangle against all active
// rays of a packet at once, so even incoherent rays cost less per ray than one by one (measured
// in the Cornell box on AVX-512: about 20% less for nearest hits, 40% less for shadow rays).
// Which rays share a packet is fixed by pixel and sample index (see PathTracer::render), so it
// never depends on the thread count or on how samples are split over calls. EmbreeScene hands a
// packet to Embree in queries of the width the instruction set traces natively (16, 8, 4 or 1).
//
// Every lane always holds a well-defined ray: an inactive lane holds an empty one (tfar < tnear,
// finite origin and direction), not stale or uninitialised memory. Embree's narrower kernels
// split a 16-wide packet and check lanes themselves; with undefined lanes they assert or trace
// garbage (seen on AVX2 machines).

#include <algorithm>
#include <limits>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

namespace lpvlab {

constexpr int kPacketWidth = 16;
// The tfar of an inactive lane's ray (its tnear is 1): never written by Embree.
constexpr float kInactiveTFar = 0.0f;

struct RayHit {
  float distance;  // ray parameter of the hit (rays have unit directions: metres)
  float u, v;      // barycentrics: point = (1 - u - v) p0 + u p1 + v p2
  unsigned geomID, primID;
};

namespace packet_detail {

// Writes one lane of an Embree ray packet (RTCRay16 layout).
inline void setLane(RTCRay16& rays, int lane, const glm::vec3& origin, const glm::vec3& direction,
                    float tNear, float tFar, unsigned id = 0) {
  rays.org_x[lane] = origin.x, rays.org_y[lane] = origin.y, rays.org_z[lane] = origin.z;
  rays.dir_x[lane] = direction.x, rays.dir_y[lane] = direction.y, rays.dir_z[lane] = direction.z;
  rays.tnear[lane] = tNear;
  rays.tfar[lane] = tFar;
  rays.time[lane] = 0.0f;
  rays.mask[lane] = std::numeric_limits<unsigned>::max();
  rays.id[lane] = id;
  rays.flags[lane] = 0;
}

// An empty ray: no t satisfies tnear < t < tfar, so it hits nothing whoever traces it, and its
// tfar is neither a hit distance nor the -inf an occlusion hit writes.
inline void setInactive(RTCRay16& rays, int lane) {
  setLane(rays, lane, glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f), 1.0f, kInactiveTFar);
}

}  // namespace packet_detail

// Nearest-hit queries.
struct RayPacket {
  alignas(64) int valid[kPacketWidth];  // -1: lane active, 0: inactive (Embree's convention)
  alignas(64) RTCRayHit16 query;

  RayPacket() { clear(); }
  void clear() {
    for (int lane = 0; lane < kPacketWidth; ++lane) deactivate(lane);
  }
  void deactivate(int lane) {
    packet_detail::setInactive(query.ray, lane);
    query.hit.geomID[lane] = query.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
    valid[lane] = 0;
  }
  bool any() const {
    return std::any_of(valid, valid + kPacketWidth, [](int v) { return v != 0; });
  }
  // `id`: the caller's number for the ray (an AlphaLookup reads it: embree_scene.h).
  void set(int lane, const glm::vec3& origin, const glm::vec3& direction, float tNear, float tFar,
           unsigned id = 0) {
    packet_detail::setLane(query.ray, lane, origin, direction, tNear, tFar, id);
    query.hit.geomID[lane] = query.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
    valid[lane] = -1;
  }
  bool active(int lane) const { return valid[lane] != 0; }
  bool hit(int lane) const { return query.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID; }
  // After the query, where hit(lane).
  RayHit hitAt(int lane) const {
    return {query.ray.tfar[lane], query.hit.u[lane], query.hit.v[lane], query.hit.geomID[lane],
            query.hit.primID[lane]};
  }
};

// Occlusion queries.
struct ShadowPacket {
  alignas(64) int valid[kPacketWidth];
  alignas(64) RTCRay16 query;

  ShadowPacket() { clear(); }
  void clear() {
    for (int lane = 0; lane < kPacketWidth; ++lane) {
      packet_detail::setInactive(query, lane);
      valid[lane] = 0;
    }
  }
  void set(int lane, const glm::vec3& origin, const glm::vec3& direction, float tNear, float tFar,
           unsigned id = 0) {
    packet_detail::setLane(query, lane, origin, direction, tNear, tFar, id);
    valid[lane] = -1;
  }
  // Embree marks an occluded ray by setting its tfar to -inf.
  bool occluded(int lane) const { return query.tfar[lane] < 0.0f; }
};

}  // namespace lpvlab

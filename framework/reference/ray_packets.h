#pragma once
// Rays traced together through Embree's 16-wide packet queries (rtcIntersect16, rtcOccluded16).
// Embree tests a BVH node or a triangle against all active rays of a packet at once, so even
// incoherent rays cost less per ray than one by one (measured in the Cornell box on AVX-512:
// about 20% less for nearest hits, 40% less for shadow rays). Unset lanes are inactive. Which
// rays share a packet is fixed by pixel and sample index (see PathTracer::render), so it never
// depends on the thread count or on how samples are split over calls.

#include <algorithm>
#include <limits>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

namespace lpvlab {

constexpr int kPacketWidth = 16;

struct RayHit {
  float distance;  // ray parameter of the hit (rays have unit directions: metres)
  float u, v;      // barycentrics: point = (1 - u - v) p0 + u p1 + v p2
  unsigned geomID, primID;
};

namespace packet_detail {

// Writes one lane of an Embree ray packet (RTCRay16 layout).
inline void setLane(RTCRay16& rays, int lane, const glm::vec3& origin, const glm::vec3& direction,
                    float tNear, float tFar) {
  rays.org_x[lane] = origin.x, rays.org_y[lane] = origin.y, rays.org_z[lane] = origin.z;
  rays.dir_x[lane] = direction.x, rays.dir_y[lane] = direction.y, rays.dir_z[lane] = direction.z;
  rays.tnear[lane] = tNear;
  rays.tfar[lane] = tFar;
  rays.time[lane] = 0.0f;
  rays.mask[lane] = std::numeric_limits<unsigned>::max();
  rays.id[lane] = 0;
  rays.flags[lane] = 0;
}

}  // namespace packet_detail

// Nearest-hit queries.
struct RayPacket {
  alignas(64) int valid[kPacketWidth];  // -1: lane active, 0: inactive (Embree's convention)
  alignas(64) RTCRayHit16 query;

  RayPacket() { clear(); }
  void clear() { std::fill(valid, valid + kPacketWidth, 0); }
  bool any() const {
    return std::any_of(valid, valid + kPacketWidth, [](int v) { return v != 0; });
  }
  void set(int lane, const glm::vec3& origin, const glm::vec3& direction, float tNear, float tFar) {
    packet_detail::setLane(query.ray, lane, origin, direction, tNear, tFar);
    query.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
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
  void clear() { std::fill(valid, valid + kPacketWidth, 0); }
  void set(int lane, const glm::vec3& origin, const glm::vec3& direction, float tNear, float tFar) {
    packet_detail::setLane(query, lane, origin, direction, tNear, tFar);
    valid[lane] = -1;
  }
  // Embree marks an occluded ray by setting its tfar to -inf.
  bool occluded(int lane) const { return query.tfar[lane] < 0.0f; }
};

}  // namespace lpvlab

#include "framework/reference/embree_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <string>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

// What every query of an EmbreeScene hands Embree: its context, and the alpha lookup the alpha
// masks' filter reads (null: the texture's level 0). Embree passes the context to filters as
// given, so the filter can read the member after it (standard layout, context first).
struct QueryContext {
  RTCIntersectContext embree;
  const AlphaLookup* alpha;
};
static_assert(std::is_standard_layout_v<QueryContext>);

// Intersection and occlusion filter of alpha-masked geometry: rejects each candidate hit whose
// interpolated uv falls where the base colour texture's alpha is below the material's cutoff.
void alphaMaskFilter(const RTCFilterFunctionNArguments* args) {
  const auto& record = *static_cast<const GeometryRecord*>(args->geometryUserPtr);
  const AlphaLookup* lookup = reinterpret_cast<const QueryContext*>(args->context)->alpha;
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const float u = RTCHitN_u(args->hit, args->N, i);
    const float v = RTCHitN_v(args->hit, args->N, i);
    const unsigned primID = RTCHitN_primID(args->hit, args->N, i);
    bool cut;
    if (lookup) {
      cut = lookup->alpha(record, primID, u, v, RTCRayN_id(args->ray, args->N, i)) <
            record.material->alphaCutoff;
    } else {
      const std::uint32_t* corner = record.indices + 3 * std::size_t(primID);
      cut = cutOut(*record.material, atBarycentrics(record.uvs, corner, u, v));
    }
    if (cut) args->valid[i] = 0;
  }
}

// A vertex normal within this cosine of the face normal (or its opposite) counts as equal.
constexpr float kFlatCosine = 1.0f - 1e-6f;

std::vector<TriangleFrame> triangleFrames(const Mesh& mesh) {
  std::vector<TriangleFrame> frames;
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
    const std::uint32_t* corner = &mesh.indices[i];
    const glm::vec3 p0 = mesh.positions[corner[0]];
    const glm::vec3 crossEdges =
        glm::cross(mesh.positions[corner[1]] - p0, mesh.positions[corner[2]] - p0);
    const float length = glm::length(crossEdges);
    // A degenerate triangle is never hit; any unit normal keeps the arithmetic finite.
    const glm::vec3 unitNormal = length > 0.0f ? crossEdges / length : glm::vec3(0, 1, 0);
    bool flat = true;
    for (int k = 0; k < 3; ++k)
      flat = flat && std::abs(glm::dot(mesh.normals[corner[k]], unitNormal)) >= kFlatCosine;
    frames.push_back({unitNormal, flat});
  }
  return frames;
}

void checkMesh(const Mesh& mesh, std::size_t materialCount) {
  const std::string where = "path tracer: mesh '" + mesh.name + "'";
  if (mesh.normals.size() != mesh.positions.size() || mesh.uvs.size() != mesh.positions.size())
    throwAt(where, "needs one normal and one uv per position");
  if (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size())
    throwAt(where, "has " + std::to_string(mesh.colors.size()) + " vertex colours for " +
                       std::to_string(mesh.positions.size()) + " positions (none, or one each)");
  for (const glm::vec3& c : mesh.colors)
    if (!(glm::all(glm::greaterThanEqual(c, glm::vec3(0.0f))) && glm::all(glm::lessThanEqual(c, glm::vec3(1.0f)))))
      throwAt(where, "has a vertex colour outside [0, 1] (or not a number)");
  if (mesh.indices.size() % 3 != 0) throwAt(where, "index count is not a multiple of 3");
  for (std::uint32_t index : mesh.indices)
    if (index >= mesh.positions.size())
      throwAt(where, "index " + std::to_string(index) + " is beyond its " +
                         std::to_string(mesh.positions.size()) + " positions");
  if (mesh.material < 0 || std::size_t(mesh.material) >= materialCount)
    throwAt(where, "material " + std::to_string(mesh.material) + " does not exist");
  for (const glm::vec3& p : mesh.positions)
    if (!std::isfinite(p.x + p.y + p.z)) throwAt(where, "has a non-finite position");
}

void throwOnDeviceError(RTCDevice device, const char* step) {
  const RTCError error = rtcGetDeviceError(device);
  if (error != RTC_ERROR_NONE)
    throw Error(std::string("path tracer: Embree failed to ") + step + " (error " +
                std::to_string(int(error)) + ")");
}

}  // namespace

EmbreeScene::EmbreeScene(const Scene& scene, const std::vector<SurfaceMaterial>& materials,
                         const RayEngineSettings& engine,
                         const std::function<bool(const Mesh&)>& include)
    : device_(makeEmbreeDevice(engine)) {
  std::size_t triangles = 0;
  for (const Mesh& mesh : scene.meshes)
    if (!include || include(mesh)) triangles += mesh.indices.size() / 3;
  if (triangles == 0) throw Error("Embree: scene '" + scene.source + "' has no triangles to trace");
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    checkMesh(mesh, materials.size());
    if (mesh.indices.empty() || (include && !include(mesh))) continue;
    triangles_.push_back(triangleFrames(mesh));
    records_.push_back({mesh.normals.data(), mesh.uvs.data(),
                        mesh.colors.empty() ? nullptr : mesh.colors.data(), mesh.indices.data(), triangles_.back().data(), &materials[mesh.material],
                        int(m)});
  }

  const Bounds bounds = scene.bounds();
  const glm::vec3 largest = glm::max(glm::abs(bounds.min), glm::abs(bounds.max));
  epsilon_ = 1e-4f * std::max({largest.x, largest.y, largest.z, glm::length(bounds.extent())});

  RTCDevice device = device_.device.get();
  scene_.reset(rtcNewScene(device));
  rtcSetSceneBuildQuality(scene_.get(), RTC_BUILD_QUALITY_HIGH);
  for (const GeometryRecord& record : records_) {
    const Mesh& mesh = scene.meshes[record.meshIndex];
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // The scene holds the geometry from here on (so nothing leaks if a step below throws); ids
    // count up from 0 in attach order, which is records_'s order.
    rtcAttachGeometry(scene_.get(), geometry);
    rtcReleaseGeometry(geometry);
    // Copied into Embree's buffers, which carry the padding its vector loads read past the end.
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                sizeof(glm::vec3), mesh.positions.size()));
    auto* triangles = static_cast<std::uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(std::uint32_t), mesh.indices.size() / 3));
    throwOnDeviceError(device, "allocate geometry buffers");
    std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
    std::memcpy(triangles, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
    if (record.material->alphaCutoff >= 0.0f) {
      rtcSetGeometryUserData(geometry, const_cast<GeometryRecord*>(&record));
      rtcSetGeometryIntersectFilterFunction(geometry, alphaMaskFilter);
      rtcSetGeometryOccludedFilterFunction(geometry, alphaMaskFilter);
    }
    rtcCommitGeometry(geometry);
  }
  rtcCommitScene(scene_.get());
  throwOnDeviceError(device, "build the scene");
}

namespace {

// A 16-ray packet goes to Embree in slices of N rays (N = the query width): each slice with an
// active lane is copied into an N-wide packet, traced, and its results copied back. The copies
// cost a few hundred bytes per slice, far below a traversal.

template <class To, class From>
void copyRay(To& to, int i, const From& from, int j) {
  to.org_x[i] = from.org_x[j], to.org_y[i] = from.org_y[j], to.org_z[i] = from.org_z[j];
  to.dir_x[i] = from.dir_x[j], to.dir_y[i] = from.dir_y[j], to.dir_z[i] = from.dir_z[j];
  to.tnear[i] = from.tnear[j], to.tfar[i] = from.tfar[j], to.time[i] = from.time[j];
  to.mask[i] = from.mask[j], to.id[i] = from.id[j], to.flags[i] = from.flags[j];
}

template <class To, class From>
void copyHit(To& to, int i, const From& from, int j) {
  to.u[i] = from.u[j], to.v[i] = from.v[j];
  to.primID[i] = from.primID[j], to.geomID[i] = from.geomID[j];
  to.instID[0][i] = from.instID[0][j];
}

// Embree's query of width N on an N-wide packet; width 1 goes through rtcIntersect1/rtcOccluded1,
// whose RTCRayHit/RTCRay have the layout of a 1-wide packet.
template <int N>
void intersectN(const int* valid, RTCScene scene, RTCIntersectContext* context,
                RTCRayHitNt<N>& query) {
  if constexpr (N == 1) {
    static_assert(sizeof(RTCRayHit) == sizeof(RTCRayHitNt<1>) &&
                  std::is_trivially_copyable_v<RTCRayHit>);
    alignas(16) RTCRayHit single;
    std::memcpy(&single, &query, sizeof single);
    rtcIntersect1(scene, context, &single);
    std::memcpy(&query, &single, sizeof single);
  } else if constexpr (N == 4) {
    rtcIntersect4(valid, scene, context, reinterpret_cast<RTCRayHit4*>(&query));
  } else if constexpr (N == 8) {
    rtcIntersect8(valid, scene, context, reinterpret_cast<RTCRayHit8*>(&query));
  }
}

template <int N>
void occludedN(const int* valid, RTCScene scene, RTCIntersectContext* context, RTCRayNt<N>& query) {
  if constexpr (N == 1) {
    static_assert(sizeof(RTCRay) == sizeof(RTCRayNt<1>) && std::is_trivially_copyable_v<RTCRay>);
    alignas(16) RTCRay single;
    std::memcpy(&single, &query, sizeof single);
    rtcOccluded1(scene, context, &single);
    std::memcpy(&query, &single, sizeof single);
  } else if constexpr (N == 4) {
    rtcOccluded4(valid, scene, context, reinterpret_cast<RTCRay4*>(&query));
  } else if constexpr (N == 8) {
    rtcOccluded8(valid, scene, context, reinterpret_cast<RTCRay8*>(&query));
  }
}

bool anyActive(const int* valid, int count) {
  return std::any_of(valid, valid + count, [](int v) { return v != 0; });
}

template <int N>
void intersectSlices(RTCScene scene, RTCIntersectContext* context, RayPacket& packet) {
  for (int first = 0; first < kPacketWidth; first += N) {
    if (!anyActive(packet.valid + first, N)) continue;
    alignas(64) RTCRayHitNt<N> slice;
    for (int i = 0; i < N; ++i) {
      copyRay(slice.ray, i, packet.query.ray, first + i);
      copyHit(slice.hit, i, packet.query.hit, first + i);
    }
    intersectN<N>(packet.valid + first, scene, context, slice);
    for (int i = 0; i < N; ++i) {
      packet.query.ray.tfar[first + i] = slice.ray.tfar[i];
      copyHit(packet.query.hit, first + i, slice.hit, i);
    }
  }
}

template <int N>
void occludedSlices(RTCScene scene, RTCIntersectContext* context, ShadowPacket& packet) {
  for (int first = 0; first < kPacketWidth; first += N) {
    if (!anyActive(packet.valid + first, N)) continue;
    alignas(64) RTCRayNt<N> slice;
    for (int i = 0; i < N; ++i) copyRay(slice, i, packet.query, first + i);
    occludedN<N>(packet.valid + first, scene, context, slice);
    for (int i = 0; i < N; ++i) packet.query.tfar[first + i] = slice.tfar[i];
  }
}

}  // namespace

void EmbreeScene::intersect(RayPacket& packet, bool coherent, const AlphaLookup* alpha) const {
  QueryContext query;
  rtcInitIntersectContext(&query.embree);
  query.alpha = alpha;
  RTCIntersectContext& context = query.embree;
  if (coherent) context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  switch (device_.packetWidth) {
    case 16: rtcIntersect16(packet.valid, scene_.get(), &context, &packet.query); break;
    case 8: intersectSlices<8>(scene_.get(), &context, packet); break;
    case 4: intersectSlices<4>(scene_.get(), &context, packet); break;
    default: intersectSlices<1>(scene_.get(), &context, packet); break;
  }
}

void EmbreeScene::occluded(ShadowPacket& packet, const AlphaLookup* alpha) const {
  QueryContext query;
  rtcInitIntersectContext(&query.embree);
  query.alpha = alpha;
  RTCIntersectContext& context = query.embree;
  switch (device_.packetWidth) {
    case 16: rtcOccluded16(packet.valid, scene_.get(), &context, &packet.query); break;
    case 8: occludedSlices<8>(scene_.get(), &context, packet); break;
    case 4: occludedSlices<4>(scene_.get(), &context, packet); break;
    default: occludedSlices<1>(scene_.get(), &context, packet); break;
  }
}

SurfacePoint surfaceAt(const EmbreeScene& scene, const RayHit& hit, const glm::vec3& origin,
                          const glm::vec3& direction) {
  const GeometryRecord& geometry = scene.geometry(hit.geomID);
  const TriangleFrame& frame = geometry.triangles[hit.primID];
  SurfacePoint x;
  x.geometry = &geometry;
  // Along the ray: its rounding (~1e-7 of the distance) is far below the offsets of new rays.
  x.position = origin + hit.distance * direction;
  x.geometricNormal = frame.unitNormal;
  x.shadingNormal = frame.unitNormal;
  x.uv = glm::vec2(0.0f);  // never read for untextured materials
  if (!frame.flat || geometry.material->texture || geometry.colors) {
    const std::uint32_t* corner = geometry.indices + 3 * std::size_t(hit.primID);
    if (!frame.flat) {
      const glm::vec3 interpolated = atBarycentrics(geometry.normals, corner, hit.u, hit.v);
      const float length2 = glm::dot(interpolated, interpolated);
      // Vertex normals that cancel out (or are missing as zeros) leave the geometric normal.
      if (length2 > 1e-12f && std::isfinite(length2))
        x.shadingNormal = interpolated / std::sqrt(length2);
    }
    if (geometry.material->texture) x.uv = atBarycentrics(geometry.uvs, corner, hit.u, hit.v);
    if (geometry.colors) x.color = atBarycentrics(geometry.colors, corner, hit.u, hit.v);
  }
  if (glm::dot(x.shadingNormal, direction) > 0.0f) x.shadingNormal = -x.shadingNormal;
  return x;
}

}  // namespace lpvlab

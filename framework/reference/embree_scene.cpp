#include "framework/reference/embree_scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

// Intersection and occlusion filter of alpha-masked geometry: rejects each candidate hit whose
// interpolated uv falls where the base colour texture's alpha is below the material's cutoff.
void alphaMaskFilter(const RTCFilterFunctionNArguments* args) {
  const auto& record = *static_cast<const GeometryRecord*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const float u = RTCHitN_u(args->hit, args->N, i);
    const float v = RTCHitN_v(args->hit, args->N, i);
    const std::uint32_t* corner =
        record.indices + 3 * std::size_t(RTCHitN_primID(args->hit, args->N, i));
    const glm::vec2 uv = (1.0f - u - v) * record.uvs[corner[0]] + u * record.uvs[corner[1]] +
                         v * record.uvs[corner[2]];
    if (cutOut(*record.material, uv)) args->valid[i] = 0;
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

EmbreeScene::EmbreeScene(const Scene& scene, const std::vector<SurfaceMaterial>& materials) {
  if (scene.triangleCount() == 0)
    throw Error("path tracer: scene '" + scene.source + "' has no triangles");
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    checkMesh(mesh, materials.size());
    if (mesh.indices.empty()) continue;
    triangles_.push_back(triangleFrames(mesh));
    records_.push_back({mesh.normals.data(), mesh.uvs.data(),
                        mesh.indices.data(), triangles_.back().data(), &materials[mesh.material],
                        int(m)});
  }

  const Bounds bounds = scene.bounds();
  const glm::vec3 largest = glm::max(glm::abs(bounds.min), glm::abs(bounds.max));
  epsilon_ = 1e-4f * std::max({largest.x, largest.y, largest.z, glm::length(bounds.extent())});

  device_.reset(rtcNewDevice(nullptr));
  if (!device_) throw Error("path tracer: Embree could not create a device");
  scene_.reset(rtcNewScene(device_.get()));
  rtcSetSceneBuildQuality(scene_.get(), RTC_BUILD_QUALITY_HIGH);
  for (const GeometryRecord& record : records_) {
    const Mesh& mesh = scene.meshes[record.meshIndex];
    RTCGeometry geometry = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
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
    throwOnDeviceError(device_.get(), "allocate geometry buffers");
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
  throwOnDeviceError(device_.get(), "build the scene");
}

}  // namespace lpvlab

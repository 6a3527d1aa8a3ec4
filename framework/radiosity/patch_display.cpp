#include "framework/radiosity/patch_display.h"

#include <atomic>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace lpvlab {

PatchDisplay::PatchDisplay(const PatchMesh& mesh, const PatchRayScene& scene) : mesh_(mesh), scene_(scene) {
  // Patches around each welded vertex.
  std::vector<std::uint32_t> start(mesh.vertexCount + 1, 0), around;
  for (const Patch& p : mesh.patches)
    for (std::uint32_t v : p.vertex) ++start[v + 1];
  for (std::size_t v = 0; v < mesh.vertexCount; ++v) start[v + 1] += start[v];
  around.resize(start.back());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t p = 0; p < mesh.patches.size(); ++p)
    for (std::uint32_t v : mesh.patches[p].vertex) around[fill[v]++] = std::uint32_t(p);
  const float creaseCos = std::cos(float(M_PI) / 6.0f);
  shareStart_.reserve(3 * mesh.sides() + 1);
  shareStart_.push_back(0);
  for (std::size_t side = 0; side < mesh.sides(); ++side) {
    const glm::vec3 n = sideNormal(mesh, side);
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = mesh.patches[side / 2].vertex[c];
      for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
        const Patch& other = mesh.patches[around[k]];
        const float facing = glm::dot(n, other.normal);
        // The other patch's side that faces the way this side does, if either does.
        if (facing >= creaseCos) shares_.push_back({2 * around[k], other.area});
        else if (-facing >= creaseCos) shares_.push_back({2 * around[k] + 1, other.area});
      }
      shareStart_.push_back(std::uint32_t(shares_.size()));
    }
  }
}

std::vector<glm::vec3> PatchDisplay::cornerValues(const std::vector<glm::dvec3>& perSide) const {
  std::vector<glm::vec3> out(3 * mesh_.sides());
  tbb::parallel_for(std::size_t(0), out.size(), [&](std::size_t q) {
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (std::uint32_t k = shareStart_[q]; k < shareStart_[q + 1]; ++k) {
      sum += double(shares_[k].weight) * perSide[shares_[k].side];
      weight += shares_[k].weight;
    }
    out[q] = weight > 0.0 ? glm::vec3(sum / weight) : glm::vec3(perSide[q / 3]);
  });
  return out;
}

std::size_t PatchDisplay::render(const Camera& camera, const HostImage& position, const HostImage& normal,
                                 const HostImage& albedo, const std::vector<glm::dvec3>& irradiance,
                                 PatchInterpolation interpolation, HostImage& out) const {
  const std::vector<glm::vec3> corners =
      interpolation == PatchInterpolation::Gouraud ? cornerValues(irradiance) : std::vector<glm::vec3>();
  const EmbreeScene& embree = scene_.embree();
  const float epsilon = embree.epsilon();
  const int width = position.width, height = position.height;
  std::atomic<std::size_t> traced{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& range) {
    std::size_t rays = 0;
    for (int y = range.begin(); y != range.end(); ++y) {
      // A row's pixels in packets: the camera's rays to their surface points, and for the rare
      // one that misses (a pixel at a silhouette), a short ray into its surface along the normal.
      for (int x0 = 0; x0 < width; x0 += kPacketWidth) {
        RayPacket packet;
        std::size_t pixel[kPacketWidth];
        glm::vec3 toSurface[kPacketWidth];
        int lanes = 0;
        for (int x = x0; x < std::min(width, x0 + kPacketWidth); ++x) {
          const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
          if (!(position.texels[i].w > 0.0f)) continue;
          const glm::vec3 p(position.texels[i]);
          const glm::vec3 span = p - camera.position;
          const float length = glm::length(span);
          if (!(length > 0.0f)) continue;
          toSurface[lanes] = span / length;
          packet.set(lanes, camera.position, toSurface[lanes], 0.0f, length * 1.001f + 8.0f * epsilon);
          pixel[lanes++] = i;
        }
        if (lanes == 0) continue;
        embree.intersect(packet, true);
        rays += std::size_t(lanes);
        RayPacket retry;
        bool retrying = false;
        for (int l = 0; l < lanes; ++l)
          if (!packet.hit(l)) {
            const glm::vec3 p(position.texels[pixel[l]]), n(normal.texels[pixel[l]]);
            retry.set(l, p + 4.0f * epsilon * n, -n, 0.0f, 8.0f * epsilon);
            toSurface[l] = -n;
            retrying = true;
          }
        if (retrying) embree.intersect(retry, false), rays += std::size_t(lanes);
        for (int l = 0; l < lanes; ++l) {
          const RayPacket& from = packet.hit(l) ? packet : retry;
          if (!from.hit(l)) continue;
          const RayHit hit = from.hitAt(l);
          const std::size_t patch = scene_.patchOf(hit);
          const std::size_t side = 2 * patch + (glm::dot(toSurface[l], mesh_.patches[patch].normal) < 0.0f ? 0 : 1);
          glm::vec3 h;
          if (interpolation == PatchInterpolation::Flat) {
            h = glm::vec3(irradiance[side]);
          } else {
            const float b1 = hit.u, b2 = hit.v;
            h = (1.0f - b1 - b2) * corners[3 * side] + b1 * corners[3 * side + 1] + b2 * corners[3 * side + 2];
          }
          const glm::vec3 rho(albedo.texels[pixel[l]]);
          out.texels[pixel[l]] += glm::vec4(rho * glm::max(h, glm::vec3(0.0f)) * float(1.0 / M_PI), 0.0f);
        }
      }
    }
    traced += rays;
  });
  return traced;
}

std::size_t PatchDisplay::memoryBytes() const {
  return shareStart_.capacity() * sizeof(std::uint32_t) + shares_.capacity() * sizeof(Share);
}

}  // namespace lpvlab

#include "framework/many_lights/vpl_depth_maps.h"

#include <algorithm>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/error.h"
#include "framework/many_lights/pull_push.h"
#include "framework/reference/embree_scene.h"
#include "framework/reference/random.h"

namespace lpvlab {

namespace {

constexpr float kNothing = std::numeric_limits<float>::infinity();
constexpr float kHole = -1.0f;  // pull-push's undefined texel (depths are never negative)

bool inDisk(int column, int row, int size) {
  const glm::vec2 uv = paraboloidTexelCentre(column, row, size);
  return glm::dot(uv, uv) <= 1.0f;
}

void keepFrames(std::span<const Vpl> vpls, VplDepthMaps& maps) {
  maps.frames.clear();
  for (const Vpl& vpl : vpls) maps.frames.emplace_back(vpl.normal);
}

}  // namespace

bool VplDepthMaps::visible(std::size_t index, const Vpl& vpl, const glm::vec3& x,
                           const glm::vec3& n) const {
  const int size = settings.size;
  const float distance = glm::length(x - vpl.position);
  const glm::vec3 moved = x + n * (distance * (4.0f / float(size)) * settings.normalOffsetTexels);
  const glm::vec3 toMoved = moved - vpl.position;
  const float movedDistance = glm::length(toMoved);
  if (!(movedDistance > 0.0f)) return true;
  glm::vec2 uv;
  if (!frames[index].project(toMoved / movedDistance, uv)) return false;
  const glm::ivec2 t = paraboloidTexel(uv, size);
  const float depth = map(index)[std::size_t(t.y) * size + t.x];
  return movedDistance <= depth * (1.0f + settings.relativeBias);
}

std::size_t renderDepthMapsByRays(const EmbreeScene& scene, std::span<const Vpl> vpls,
                                  const DepthMapSettings& settings, VplDepthMaps& maps) {
  const int size = settings.size;
  const std::size_t texels = std::size_t(size) * size;
  maps.settings = settings;
  maps.depths.assign(vpls.size() * texels, kNothing);
  keepFrames(vpls, maps);
  std::vector<std::size_t> rays(vpls.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vpls.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
    RayPacket packet;
    int lanes = 0;
    std::size_t slots[kPacketWidth];
    const auto flush = [&](std::size_t vpl) {
      if (lanes == 0) return;
      scene.intersect(packet, true);
      for (int lane = 0; lane < lanes; ++lane)
        if (packet.hit(lane)) maps.depths[slots[lane]] = packet.hitAt(lane).distance;
      rays[vpl] += std::size_t(lanes);
      packet.clear();
      lanes = 0;
    };
    for (std::size_t v = range.begin(); v != range.end(); ++v) {
      const Vpl& vpl = vpls[v];
      const ParaboloidFrame& frame = maps.frames[v];
      const glm::vec3 origin = vpl.position + scene.epsilon() * vpl.normal;
      for (int row = 0; row < size; ++row)
        for (int column = 0; column < size; ++column) {
          if (!inDisk(column, row, size)) continue;
          const glm::vec3 d = frame.direction(paraboloidTexelCentre(column, row, size));
          packet.set(lanes, origin, glm::normalize(d), 0.0f, kNothing);
          slots[lanes] = v * texels + std::size_t(row) * size + column;
          if (++lanes == kPacketWidth) flush(v);
        }
      flush(v);
    }
  });
  std::size_t total = 0;
  for (std::size_t r : rays) total += r;
  return total;
}

SurfacePointSampler::SurfacePointSampler(const Scene& scene) {
  double sum = 0.0;
  for (int m = 0; m < int(scene.meshes.size()); ++m) {
    const Mesh& mesh = scene.meshes[std::size_t(m)];
    for (std::uint32_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const glm::dvec3 a(mesh.positions[mesh.indices[i]]), b(mesh.positions[mesh.indices[i + 1]]),
          c(mesh.positions[mesh.indices[i + 2]]);
      const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
      if (!(area > 0.0) || !std::isfinite(area)) continue;
      sum += area;
      triangles_.push_back({m, i});
      cumulative_.push_back(sum);
    }
  }
  if (!(sum > 0.0)) throw Error("imperfect shadow maps: the scene has no surface to sample points on");
  for (double& c : cumulative_) c /= sum;
  totalArea_ = sum;
}

void SurfacePointSampler::sample(const Scene& scene, std::uint64_t seed, std::size_t vpl, int count,
                                 std::vector<glm::vec3>& points) const {
  points.clear();
  SampleRandom random(seed, vpl, 0);
  for (int j = 0; j < count; ++j) {
    const double pick = random.uniform();
    const std::size_t t = std::min<std::size_t>(
        std::upper_bound(cumulative_.begin(), cumulative_.end(), pick) - cumulative_.begin(),
        triangles_.size() - 1);
    const Mesh& mesh = scene.meshes[std::size_t(triangles_[t].mesh)];
    const std::uint32_t i = triangles_[t].firstIndex;
    float s = random.uniform(), r = random.uniform();
    if (s + r > 1.0f) s = 1.0f - s, r = 1.0f - r;  // fold the square onto the triangle
    const glm::vec3 a = mesh.positions[mesh.indices[i]];
    points.push_back(a + s * (mesh.positions[mesh.indices[i + 1]] - a) +
                     r * (mesh.positions[mesh.indices[i + 2]] - a));
  }
}

void splatImperfectShadowMaps(const Scene& scene, const SurfacePointSampler& sampler,
                              std::span<const Vpl> vpls, const DepthMapSettings& settings,
                              const ImperfectSettings& imperfect, VplDepthMaps& maps,
                              ImperfectCounts* counts) {
  const int size = settings.size;
  const std::size_t texels = std::size_t(size) * size;
  maps.settings = settings;
  maps.depths.assign(vpls.size() * texels, kHole);
  keepFrames(vpls, maps);
  std::vector<ImperfectCounts> perVpl(vpls.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vpls.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
    std::vector<glm::vec3> points;
    std::vector<float> scratch;
    for (std::size_t v = range.begin(); v != range.end(); ++v) {
      const Vpl& vpl = vpls[v];
      const ParaboloidFrame& frame = maps.frames[v];
      float* map = maps.depths.data() + v * texels;
      ImperfectCounts& c = perVpl[v];
      sampler.sample(scene, imperfect.seed, v, imperfect.pointsPerVpl, points);
      for (const glm::vec3& p : points) {
        const glm::vec3 d = p - vpl.position;
        const float distance = glm::length(d);
        glm::vec2 uv;
        if (!(distance > 0.0f) || !frame.project(d / distance, uv)) continue;
        const glm::ivec2 t = paraboloidTexel(uv, size);
        float& texel = map[std::size_t(t.y) * size + t.x];
        texel = texel == kHole ? distance : std::min(texel, distance);
        ++c.splats;
      }
      for (int row = 0; row < size; ++row)
        for (int column = 0; column < size; ++column)
          if (inDisk(column, row, size)) {
            ++c.diskTexels;
            if (map[std::size_t(row) * size + column] == kHole) ++c.holesBefore;
          }
      pullPush(map, size, imperfect.pullPushLevels, kHole, scratch);
      for (int row = 0; row < size; ++row)
        for (int column = 0; column < size; ++column) {
          float& texel = map[std::size_t(row) * size + column];
          if (texel == kHole) {
            if (inDisk(column, row, size)) ++c.holesAfter;
            texel = kNothing;  // nothing known there: seen through
          }
        }
    }
  });
  if (!counts) return;
  *counts = {};
  for (const ImperfectCounts& c : perVpl) {
    counts->splats += c.splats;
    counts->holesBefore += c.holesBefore;
    counts->holesAfter += c.holesAfter;
    counts->diskTexels += c.diskTexels;
  }
}

}  // namespace lpvlab

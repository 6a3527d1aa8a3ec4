#pragma once
// Shadow maps of VPLs (seed 001, 2.4): per VPL a paraboloid depth map of its hemisphere
// (paraboloid.h), all in one atlas, and the shadow-map test of a receiver against it. Two ways to
// make them:
//   - exact: one Embree ray from the VPL through each texel's centre (the depth a rasteriser
//     would store at the texel's centre), renderDepthMapsByRays;
//   - imperfect (Ritschel et al. 2008; seed 001, 3.3): points sampled uniformly over the scene's
//     surfaces, each VPL's own set splatted into its map (the nearest depth per texel wins), the
//     holes filled by pull-push (pull_push.h), splatImperfectShadowMaps.
// Depths are distances from the VPL (m); +inf where a texel sees nothing.
//
// The test: a receiver x (unit normal n facing the VPL's side) is moved along n by
// normalOffsetTexels texel footprints at its distance D (a texel near the map's centre subtends
// 4 / size radians), and is lit when its distance D' is within relativeBias of the depth stored
// in its texel: D' <= depth * (1 + relativeBias). The offset keeps a surface from shadowing
// itself where it is seen at a slant; the bias covers depth's variation inside a texel.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "framework/many_lights/paraboloid.h"
#include "framework/many_lights/vpl.h"

namespace lpvlab {

class EmbreeScene;
struct Scene;

struct DepthMapSettings {
  int size = 32;                    // texels per side per VPL (a power of two for pull-push)
  float normalOffsetTexels = 1.5f;  // receiver moved along its normal, in texel footprints
  float relativeBias = 0.02f;       // depth tolerance, a fraction of the depth
};

struct VplDepthMaps {
  DepthMapSettings settings;
  std::vector<float> depths;  // per VPL, size * size row by row (row 0: v = -1)
  std::vector<ParaboloidFrame> frames;  // per VPL, made with its map (not per lookup)

  const float* map(std::size_t vpl) const {
    return depths.data() + vpl * std::size_t(settings.size) * settings.size;
  }
  std::size_t memoryBytes() const {
    return depths.capacity() * sizeof(float) + frames.capacity() * sizeof(ParaboloidFrame);
  }
  // Whether `vpl` (the index-th) lights receiver x with unit normal n.
  bool visible(std::size_t index, const Vpl& vpl, const glm::vec3& x, const glm::vec3& n) const;
};

// Exact maps of every VPL. Returns the rays traced.
std::size_t renderDepthMapsByRays(const EmbreeScene& scene, std::span<const Vpl> vpls,
                                  const DepthMapSettings& settings, VplDepthMaps& maps);

// Points on a scene's surfaces for imperfect shadow maps, each VPL's own: VPL i's point j is the
// triangle chosen with probability proportional to its area and a uniform point on it, from the
// stream (seed, i, j). Drawn from the scene's current vertices, so they follow moving geometry.
class SurfacePointSampler {
public:
  explicit SurfacePointSampler(const Scene& scene);
  // VPL `vpl`'s `count` points, into `points`.
  void sample(const Scene& scene, std::uint64_t seed, std::size_t vpl, int count,
              std::vector<glm::vec3>& points) const;
  double area() const { return totalArea_; }

private:
  struct TriangleRef {
    int mesh;
    std::uint32_t firstIndex;
  };
  std::vector<TriangleRef> triangles_;
  std::vector<double> cumulative_;  // of area, normalised to end at 1
  double totalArea_ = 0.0;
};

struct ImperfectSettings {
  int pointsPerVpl = 1024;
  int pullPushLevels = 4;  // coarser levels pull-push may make (0: holes stay holes, seen through)
  std::uint64_t seed = 1;
};

struct ImperfectCounts {
  std::size_t splats = 0;        // points splatted into a map
  std::size_t holesBefore = 0;   // texels in the disk no point reached
  std::size_t holesAfter = 0;    // texels in the disk pull-push could not fill
  std::size_t diskTexels = 0;    // texels in the disk, over every map
};

// Imperfect maps of every VPL (the scene's current vertices).
void splatImperfectShadowMaps(const Scene& scene, const SurfacePointSampler& sampler,
                              std::span<const Vpl> vpls, const DepthMapSettings& settings,
                              const ImperfectSettings& imperfect, VplDepthMaps& maps,
                              ImperfectCounts* counts = nullptr);

}  // namespace lpvlab

// [indirect] method = "incremental_instant_radiosity": Laine et al.'s incremental instant
// radiosity (2007; seed 001, 3.2) for lights that move over a static scene. One-bounce VPLs are
// kept from frame to frame in each light's projection; those the moved light no longer reaches
// are removed, then a few from where the set is densest (the shortest Delaunay edges, CGAL), and
// new ones are inserted where coverage is poorest (the largest empty circle, at a Voronoi
// vertex), each within a per-frame limit (framework/many_lights/incremental_vpls.h). Each VPL
// carries the light's power over its Voronoi cell. The gather and its visibility are instant
// radiosity's (framework/many_lights/vpl_method.h). Parameters (docs/methods.md):
//   vpls            the target over every light
//   max_removals    valid VPLs removed per frame (invalid ones always are)
//   max_insertions  VPLs inserted per frame after the first (which fills the set)
//   flux_grid       cells per side of the grid that measures the Voronoi cells' power
//   placement       "projection": VPLs spread evenly in the light's paraboloid projection (the
//                   notes' 3.2.2); "power": evenly in a disk whose area is the light's power, so
//                   each VPL's cell carries about the same power (light_charts.h)
//   visibility      "rays" (default), "shadow_maps" (with shadow_map_size, normal_offset,
//                   depth_bias) or "none"; clamp, clamp_compensation, compensation_samples,
//                   specular_albedo, exponent and sphere_radius as
//                   instant radiosity's
// The manifest reports each frame's removals, insertions and coverage. Moving geometry starts the
// set anew (the method assumes a static scene).

#include "framework/many_lights/incremental_vpls.h"
#include "framework/many_lights/vpl_method.h"

namespace lpvlab {

namespace {

IncrementalSettings readIncremental(Params& p) {
  IncrementalSettings s;
  s.vpls = p.get<int>("vpls", 256, {.min = 1, .max = 1 << 20});
  s.maxRemovals = p.get<int>("max_removals", 16, {.min = 0, .max = 1 << 20});
  s.maxInsertions = p.get<int>("max_insertions", 16, {.min = 0, .max = 1 << 20});
  s.fluxGrid = p.get<int>("flux_grid", 128, {.min = 2, .max = 4096});
  s.placement = p.getChoice("placement", "projection", {"projection", "power"}) == "power"
                    ? ChartPlacement::Power
                    : ChartPlacement::Projection;
  return s;
}

class IncrementalInstantRadiosity : public VplMethod {
public:
  explicit IncrementalInstantRadiosity(Params& p)
      : VplMethod(p, readExactOrMappedVisibility(p)), incremental_(readIncremental(p)) {}

  bool keepsStateBetweenFrames() const override { return true; }

  void moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved) override {
    VplMethod::moveScene(scene, lightsMoved, geometryMoved);
    if (geometryMoved) incremental_.reset();
  }

protected:
  void makeVpls(const RayScene& scene, std::vector<Vpl>& vpls) override {
    vpls = incremental_.update(scene, counts_);
  }

  int vplBounces() const override { return 1; }  // VPLs where the light first lands

  std::vector<WorkCount> sourceWork() const override {
    // Each kept VPL's validity ray; each insertion's ray (the Delaunay updates are CGAL's).
    return {{"validity ray", double(counts_.kept - counts_.inserted + counts_.removedInvalid), 0.0, 0.0},
            {"inserted VPL", double(counts_.inserted), 0.0, 0.0}};
  }

  nlohmann::json sourceStatistics() const override {
    return {{"removed_invalid", counts_.removedInvalid},
            {"removed_dense", counts_.removedDense},
            {"inserted", counts_.inserted},
            {"kept", counts_.kept},
            {"placeholders", counts_.placeholders},
            {"coverage", counts_.coverage},
            {"placement", incremental_.settings().placement == ChartPlacement::Power ? "power" : "projection"}};
  }

private:
  IncrementalVpls incremental_;
  IncrementalCounts counts_;
};

}  // namespace

LPVLAB_REGISTER(IndirectMethod, "incremental_instant_radiosity",
                "one-bounce VPLs kept between frames as lights move: invalid ones removed, the "
                "densest thinned (Delaunay, CGAL), new ones at the largest empty circle, within "
                "per-frame limits (Laine et al. 2007; seed 001, 3.2)",
                IncrementalInstantRadiosity);

}  // namespace lpvlab

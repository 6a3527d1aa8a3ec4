#pragma once
// Incremental instant radiosity's VPL set (Laine et al. 2007; seed 001, 3.2): one-bounce VPLs
// kept from frame to frame while a light moves over a static scene, each placed in its light's
// projection (a chart, light_charts.h). Per frame and chart:
//   1. validity: a VPL is kept while it lies inside the chart, faces the light and nothing blocks
//      the light's ray to it (an Embree shadow ray); a VPL whose ray met nothing (a placeholder
//      for light lost to the sky, kept so that its place counts as covered) while its ray still
//      meets nothing;
//   2. removal of the invalid ones, then greedily from the densest place (3.2.1: the shorter end
//      of the shortest edge of the VPLs' Delaunay triangulation in the chart) while there are more
//      than the chart's share of the target, or while that edge is shorter than half the radius
//      of the largest empty circle (the set has become uneven: its VPLs crowd one place and leave
//      another bare), at most maxRemovals a frame;
//   3. insertion at the centre of the largest empty circle (3.2.2: a Voronoi vertex, or a point of
//      the rim) while there are fewer than the share, at most maxInsertions a frame (unlimited in
//      the first frame, which fills the set from nothing);
//   4. flux: each VPL carries the light's power over its Voronoi cell of the disk (the disk's
//      power density summed over a fluxGrid x fluxGrid grid of cells, each given to its nearest
//      VPL), times its albedo.
// A chart's share of the target is proportional to its light's power (at least one). Evenly means
// in the chart's disk: the light's projection, or (placement Power) a disk whose area is the light's
// power, so that the VPLs' cells carry equal power. With the
// light still, nothing is invalid, the set is even (farthest-point insertion leaves no edge shorter
// than the largest empty radius), so the set and the image stay what the first frame made.
//
// Coverage, reported per frame: the largest empty circle's radius over sqrt(1 / n), the radius a
// disk's n VPLs would each have if they shared its area evenly (a hexagonal packing has 1.10).

#include <cstdint>
#include <vector>

#include "framework/many_lights/disk_triangulation.h"
#include "framework/many_lights/light_charts.h"
#include "framework/many_lights/ray_scene.h"
#include "framework/many_lights/vpl.h"

namespace lpvlab {

struct IncrementalSettings {
  int vpls = 256;            // the target over every chart
  int maxRemovals = 16;      // a frame (invalid ones are always removed)
  int maxInsertions = 16;    // a frame, after the first
  int fluxGrid = 128;        // cells per side of the flux's grid over each disk
  // Where "evenly" is measured: the light's projection (seed 001, 3.2.2) or its power
  // (light_charts.h: every VPL's cell then carries about the same power).
  ChartPlacement placement = ChartPlacement::Projection;
};

struct IncrementalCounts {
  int removedInvalid = 0, removedDense = 0, inserted = 0;
  int kept = 0;              // VPLs (placeholders included) at the frame's end
  int placeholders = 0;      // of them, rays that met nothing
  double coverage = 0.0;     // the worst chart's largest empty radius over sqrt(1 / n)
};

class IncrementalVpls {
public:
  explicit IncrementalVpls(const IncrementalSettings& settings) : settings_(settings) {}

  // One frame against `scene`'s current lights (`scene` updated). Returns the VPLs on surfaces.
  const std::vector<Vpl>& update(const RayScene& scene, IncrementalCounts& counts);
  const std::vector<Vpl>& vpls() const { return vpls_; }
  const IncrementalSettings& settings() const { return settings_; }

  // Whether a surface VPL would be kept by step 1 under `scene`'s current lights (for tests).
  bool valid(const RayScene& scene, const Vpl& vpl) const;
  // Forgets every VPL: the next update fills the set anew (after the geometry moved, which the
  // method assumes does not happen: the kept VPLs would float where surfaces were).
  void reset() { charts_.clear(); }

private:
  struct Kept {
    int id;
    glm::vec2 uv;          // in its chart, as of the last update
    bool onSurface;
    glm::vec3 position, normal, albedo;
  };
  struct ChartState {
    LightChart chart;
    std::vector<Kept> kept;
  };

  // Step 1 for one VPL; `reproject`: its disk point follows its surface point (the light moved).
  bool stillValid(const RayScene& scene, const LightChart& chart, Kept& vpl, bool reproject) const;
  Kept place(const RayScene& scene, const LightChart& chart, const glm::vec2& uv);
  // Steps 1-4 for one chart towards `share` VPLs (`moved`: its light moved since the last
  // update); appends its VPLs on surfaces to vpls_.
  void updateChart(const RayScene& scene, ChartState& state, bool moved, int share,
                   IncrementalCounts& counts);

  IncrementalSettings settings_;
  std::vector<ChartState> charts_;
  std::vector<Vpl> vpls_;
  int nextId_ = 0;
  bool first_ = true;
};

}  // namespace lpvlab

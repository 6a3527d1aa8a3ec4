#pragma once
// A frame's propagation by the standard CPU kernels (standard_cpu.h) on the light grid's host
// side, for every strategy built on them (standard; directed, which adds its reprojected cells):
// the face table, the ping-pong partner of the grid's host side, and, per cascade level, what
// its geometry volume does to the faces, found again only when the GV (or its albedo) differs
// from the last frame's bit for bit, so that in a static scene the warm-up frame pays for it.

#include <cstddef>
#include <map>
#include <vector>

#include "framework/math/dual.h"
#include "variants/propagation/standard_cpu.h"
#include "variants/resources/geometry_volume.h"

namespace lpvlab {

struct DualFrame;
struct Frame;
struct GeometryVolume;
struct LightGrid;

class StandardCpuFrame {
public:
  StandardCpuFrame() = default;
  // The transfer's face solid angles (already scaled by any damping; an Error for a bad one) and
  // the light grid's floats (LightGrid::floatsPerGrid).
  StandardCpuFrame(int shOrder, double farSolidAngle, double sideSolidAngle,
                   std::size_t floatsPerGrid);

  struct Iterations {
    int count = 0;
    bool scatter = false;  // six scattering passes instead of one gathering pass
    bool bounces = false;  // the GV's surfaces re-emit what it blocks (reads kSurfaceAlbedo)
    const ReprojectedCells<float>* reprojected = nullptr;  // gathering only
    // With `reprojected`: the light in two grids, attached (reprojected) and free (standard),
    // released into the free grid cell by cell as this says; the grid's current light is their
    // sum after the last iteration. Null: one grid, every cell reprojecting from its iteration on.
    const ReleasedCells* released = nullptr;
  };
  // `iterations` steps of frame.lightGrid on its host side (read back only if a GL kernel wrote
  // it last), iterations paired (pairedAccumulation). The accumulated grid is added to as it is
  // (the pipeline starts it as the injected grid; a caller stepping propagation by hand keeps
  // summing), as the GL kernels add to it. The GV, if the frame has one, attenuates from its
  // first occluded iteration on.
  void propagate(Frame& frame, const Iterations& iterations);
  // The same on a grid of a strategy's own (the subsurface LPV's), without a GV.
  void propagate(LightGrid& grid, const Iterations& iterations);

  // On dual numbers (dual_frame.h): frame.accumulated from frame.injected, with the face solid
  // angles (damping included) as Duals, the GV's derivatives if frame.gvBlocking has them and
  // `reprojected` made on Dual. The same iterations as propagate (gathering: scattering's grid).
  struct DualIterations {
    int count = 0;
    bool bounces = false;
    const ReprojectedCells<Dual>* reprojected = nullptr;
    const ReleasedCells* released = nullptr;  // as Iterations::released
  };
  static void propagateDual(DualFrame& frame, int shOrder, Dual farSolidAngle,
                            Dual sideSolidAngle, const DualIterations& iterations);

  const StandardFaceTable<float>& table() const { return table_; }
  std::size_t memoryBytes() const;

private:
  // What a level's GV does to the faces, and the GV and albedo it was found from.
  struct OcclusionCache {
    StandardOcclusion<float> faces;
    std::vector<float> gv, albedo;
    std::size_t bytes() const;
  };
  const StandardOcclusion<float>& occlusionOf(Frame& frame, const GeometryVolume& gv, bool bounces);
  void iterate(LightGrid& grid, const GeometryVolume* gv, const StandardOcclusion<float>* occlusion,
               const Iterations& iterations);

  StandardFaceTable<float> table_{};
  std::vector<float> next_;         // the host side's ping-pong partner
  std::vector<float> free_, freeNext_;  // the free light and its partner (Iterations::released)
  std::vector<float> gv_, albedo_;  // this frame's GV and albedo, read back
  std::map<const GeometryVolume*, OcclusionCache> occlusion_;
};

}  // namespace lpvlab

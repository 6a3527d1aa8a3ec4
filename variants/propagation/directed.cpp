// Propagation "directed": standard propagation (standard.cpp) with the thesis' fix for light
// flowing back behind the VPLs' own surfaces (thesis 5.2, 6.9.4, alg. 6.3). Injection also
// stores the VPLs' flux-weighted normals (it consumes kNormalGrid); before every iteration the
// normals are dilated into cells that have none (by gathering, in two ping-pong buffers of this
// strategy, starting from the injected normal grid, which stays untouched), and the light each
// face passes into a cell is reprojected a second time about the cell's dilated normal, which
// removes what travels against it. The mathematics and the normalisation (a gain G(n) per
// cell, so that light travelling along agreeing normals keeps its flux) are in
// shaders/propagation/directed_faces.glsl and docs/variants/directed.md#directed, at SH orders 1-3 (the
// gain derived for the grid's order). A geometry volume, if the occlusion strategy provides one,
// attenuates the light crossing each shared face as in thesis alg. 6.2.
// On the CPU backend the standard CPU kernel runs it, finishing each cell with a normal by the
// second reprojection (directed_cpu.h, standard_cpu_frame.h): the dilation only decides from which
// iteration a cell has its normal, so it and every cell's gain are found once per frame, and kept
// while the injected normals stay the same.
//
// | parameter  | type | default | meaning                                                       |
// |------------|------|---------|---------------------------------------------------------------|
// | iterations | int  | 32      | propagation steps; light travels one cell per step (0..4096)  |
// | dilation   | bool | true    | dilate the normals before each iteration; false reprojects    |
// |            |      |         | only in cells that received VPLs (the rest propagate as       |
// |            |      |         | standard), to see what the dilation contributes               |
// | release    | bool | true    | light leaves the reprojection where the normal field changes  |
// |            |      |         | and propagates on as standard (directed_faces.glsl); false:   |
// |            |      |         | alg. 6.3 read literally, every cell reprojects all it         |
// |            |      |         | receives (light arriving at a lit surface is turned back, so  |
// |            |      |         | a room whose every wall sends VPLs goes dark: issue 42)       |
// | region_angle_deg | float | 10 | normals further apart than this are different regions:  |
// |            |      |         | perpendicular walls' cells differ by 90, the averaged normals |
// |            |      |         | where they meet by 45 from each; 10 keeps a curved surface of |
// |            |      |         | radius 6 cells or more one region (0..90)                     |
// | gpu_kernel | text | "simple" | GL gathers' layout: "simple" or "tiled" (tiled_walk.glsl); the |
// |            |      |         | same grid; the CPU backend ignores it                         |
// | method     | text | "gather" | "gather" or "scatter" (directed_scatter.comp: each cell pushes|
// |            |      |         | into its neighbours, reprojected about theirs normals, with   |
// |            |      |         | float atomics): the same grid up to the order of additions. GL|
// |            |      |         | only: the CPU backend refuses "scatter" (its gather gives the |
// |            |      |         | same grid)                                                    |

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "framework/core/error.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"
#include "framework/math/solid_angle.h"
#include "framework/pipeline/dual_frame.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"
#include "variants/propagation/directed_cpu.h"
#include "variants/propagation/standard_cpu_frame.h"
#include "variants/propagation/directed_gl.h"
#include "variants/propagation/standard_work.h"
#include "variants/resources/geometry_volume.h"

namespace lpvlab {
namespace {

class DirectedPropagation final : public PropagationStrategy {
public:
  explicit DirectedPropagation(Params& params)
      : iterations_(params.get<int>("iterations", 32, {.min = 0, .max = 4096})),
        dilation_(params.get<bool>("dilation", true)),
        release_(params.get<bool>("release", true)),
        tiled_(params.getChoice("gpu_kernel", "simple", {"simple", "tiled"}) == "tiled"),
        cosRegionAngle_(std::cos(params.get<double>("region_angle_deg", 10.0, {.min = 0.0, .max = 90.0}) *
                                 M_PI / 180.0)),
        scatter_(params.getChoice("method", "gather", {"gather", "scatter"}) == "scatter") {
    if (tiled_ && scatter_)
      throw Error(params.where("gpu_kernel") +
                  ": \"tiled\" is a layout of the gather; method = \"scatter\" has only the simple one");
  }

  void declare(ResourceUses& uses) const override {
    uses.consumes(kNormalGrid);
    uses.reads(kGeometryVolume);
  }
  int maxShOrder() const override { return 3; }
  std::string cpuRefusal(const Requirements&) const override {
    return scatter_ ? "directed propagation's method = \"scatter\" runs on GL only (the CPU kernel "
                      "gathers, which gives the same grid: use method = \"gather\")"
                    : std::string();
  }

  void prepare(const StrategySetup& setup) override {
    ShaderCompiler& shaders = setup.shaders;
    const GridGeometry& grid = setup.grid;
    const Requirements& requirements = setup.requirements;
    const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
    shOrder_ = requirements.shOrder;
    if (runsOnCpu(requirements)) {
      cpu_ = StandardCpuFrame(requirements.shOrder, angles.farFace, angles.sideFace,
                              LightGrid::bytesPerGrid(grid, requirements.shOrder) / sizeof(float));
      onCpu_ = true;
      return;
    }
    gl_ = DirectedGlKernel(shaders, glSettings(requirements), grid.resolution);
  }

  void propagate(Frame& frame) override {
    if (onCpu_) return propagateOnCpu(frame);
    LightGrid& grid = frame.lightGrid;
    const GeometryVolume* gv = frame.find(kGeometryVolume);
    gl_.propagate(grid.geometry.resolution, iterations_, grid.current, grid.accumulated,
                  frame.get(kNormalGrid).normals, gv ? &gv->blocking : nullptr,
                  gv ? gv->firstOccludedIteration : 0);
  }

  int iterations() const override { return iterations_; }

  // Per cell-iteration: on GL directed_gl.h's count. On the CPU the standard transfer's
  // (standard_work.h) and the second reprojection: per channel the six normals' weighted flux sum
  // and the lobe (6 + min(N, 9)), the weights and lobe read per cell; the dilation and gains, once
  // per frame, not counted; with release, a second standard transfer (the free light) and the
  // release: the cell's attached and free light read and written.
  std::vector<WorkCount> work(const FrameShape& shape,
                              const Requirements& requirements) const override {
    KernelWork w = directedGlWork(glSettings(requirements));
    if (runsOnCpu(requirements)) {
      const double n = shape.coefficients, lobe = std::min(n, 9.0);
      const bool withGv = requirements.has(kGeometryVolume);
      w = standardCpuTransferWork(shape.coefficients, false, withGv);
      w.multiplyAdds += 3 * (6 + lobe);
      w.bytes += 4 * (1 + 6 + lobe);
      if (release_) {
        const KernelWork free = standardCpuTransferWork(shape.coefficients, false, withGv);
        w.multiplyAdds += free.multiplyAdds;
        w.bytes += free.bytes + 4 * 4 * 3 * n;
      }
    }
    return {{"cell-iteration", shape.cells * shape.levels * iterations_, w.multiplyAdds, w.bytes}};
  }
  std::size_t memoryBytes() const override {
    std::size_t bytes = gl_.memoryBytes() + cpu_.memoryBytes() + cpuNormals_.size() * sizeof(float);
    for (const auto& [grid, cache] : cpuCells_) {
      const ReprojectedCells<float>& r = cache.cells.reprojected;
      const ReleasedCells& released = cache.cells.released;
      bytes += (cache.normals.size() + r.since.size() + r.faceWeight.size() + r.lobe.size()) *
                   sizeof(float) +
               (released.keepFrom.size() + released.keepUntil.size()) * sizeof(int);
    }
    return bytes;
  }

  // Derivatives of what comes before it (the GV's): the standard CPU kernel on dual numbers with
  // the reprojected cells on Dual (their weights are constants: the geometric solid angles).
  bool differentiates() const override { return true; }
  void propagateDual(DualFrame& dual) override {
    const LightGrid& grid = dual.frame.lightGrid;
    downloadFloats(dual.frame.get(kNormalGrid).normals, std::size_t(4) * grid.geometry.cellCount(),
                   cpuNormals_);
    const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
    const StandardFaceTable<Dual> table =
        makeStandardFaceTable<Dual, Dual>(shOrder_, Dual(angles.farFace), Dual(angles.sideFace));
    const DirectedCells<Dual> cells = makeDirectedAndReleasedCells(
        table, grid.geometry.resolution, cpuNormals_, iterations_, dilation_, angles.farFace,
        angles.sideFace, regionAngle());
    StandardCpuFrame::propagateDual(dual, shOrder_, Dual(angles.farFace), Dual(angles.sideFace),
                                    {.count = iterations_,
                                     .reprojected = &cells.reprojected,
                                     .released = release_ ? &cells.released : nullptr});
  }

private:
  // The reprojected cells of this level are found again only when its injected normals (or its
  // grid) changed; in a static scene the warm-up frame pays for them.
  void propagateOnCpu(Frame& frame) {
    const LightGrid& grid = frame.lightGrid;
    downloadFloats(frame.get(kNormalGrid).normals, std::size_t(4) * grid.geometry.cellCount(),
                   cpuNormals_);
    CellsCache& cache = cpuCells_[&grid];
    if (cache.cells.reprojected.resolution != grid.geometry.resolution || cache.normals != cpuNormals_) {
      const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
      cache.cells = makeDirectedAndReleasedCells(cpu_.table(), grid.geometry.resolution,
                                                 cpuNormals_, iterations_, dilation_,
                                                 angles.farFace, angles.sideFace, regionAngle());
      cache.normals = cpuNormals_;
    }
    cpu_.propagate(frame, {.count = iterations_,
                           .reprojected = &cache.cells.reprojected,
                           .released = release_ ? &cache.cells.released : nullptr});
  }

  // The region angle's cosine with release, none without.
  std::optional<double> regionAngle() const {
    return release_ ? std::optional<double>(cosRegionAngle_) : std::nullopt;
  }

  DirectedGlSettings glSettings(const Requirements& requirements) const {
    return {.coefficients = shared::shCoefficientCount(requirements.shOrder),
            .withGv = requirements.has(kGeometryVolume),
            .dilation = dilation_,
            .release = release_,
            .cosRegionAngle = cosRegionAngle_,
            .tiled = tiled_,
            .scatter = scatter_};
  }

  int iterations_;
  bool dilation_;
  bool release_;
  bool tiled_;
  double cosRegionAngle_;
  bool scatter_;
  int shOrder_ = 1;
  DirectedGlKernel gl_;             // on GL
  bool onCpu_ = false;
  StandardCpuFrame cpu_;           // on the CPU backend
  std::vector<float> cpuNormals_;  // the injected normals, read back
  struct CellsCache {
    std::vector<float> normals;  // the injected normals they were found from
    DirectedCells<float> cells;  // released: empty without release
  };
  std::map<const LightGrid*, CellsCache> cpuCells_;  // per cascade level
};

LPVLAB_REGISTER(PropagationStrategy, "directed",
                "standard propagation reprojected about dilated VPL normals (thesis 5.2, alg. 6.3)",
                DirectedPropagation);

}  // namespace
}  // namespace lpvlab

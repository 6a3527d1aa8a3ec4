// Propagation "standard": light flows from each cell into its six face neighbours through the
// five faces not shared with the source, with the face solid angles derived in
// framework/math/solid_angle.cpp (thesis 4.4, alg. 6.2; Kaplanyan and Dachsbacher 2010).
// Two implementations of the same transfer (thesis 7.4.3): gathering
// (shaders/propagation/standard_gather.comp: each cell pulls from its neighbours, plain writes)
// and scattering (standard_scatter.comp: each cell pushes into its neighbours with float
// atomics). Both call the one face loop of standard_transfer.glsl; the per-face mathematics,
// its normalisation and the geometry volume's attenuation are in standard_faces.glsl.
// When an occlusion strategy produces a geometry volume (this strategy reads kGeometryVolume),
// each face's flux is multiplied by the GV's transmittance from iteration
// GeometryVolume::firstOccludedIteration on (alg. 6.2 lines 11-14). With `bounces` (which
// consume the GV and its surfaces' albedo, kSurfaceAlbedo), the light a face crossing blocks is
// re-emitted by the GV's surfaces there (albedo times a clamped cosine lobe about their normal)
// into the cell it came from, every occluded iteration, so light bounces as often as iterations
// allow (standard_faces.glsl has the mathematics). On the CPU backend ([compute] backend,
// strategy.h) gathering and scattering run the CPU kernels of standard_cpu.h, with the GV and its
// bounces, on the light grid's host side (standard_cpu_frame.h: read back only if a GL kernel wrote
// it last; the GV is read back from GL), with iterations paired so the accumulated grid is updated
// every other one.
//
// Its kernels on GL come in two layouts of the same gather ([propagation] gpu_kernel): "simple"
// (standard_gather.comp, one invocation per cell, every neighbour read from memory) and "tiled"
// (standard_gather_tiled.comp: x-long tiles of a plane staged in shared memory, walking up z);
// both call standard_transfer.glsl, so they give the same grid. The CPU backend ignores the key.
//
// | parameter             | type   | default    | meaning                                       |
// |-----------------------|--------|------------|-----------------------------------------------|
// | iterations            | int    | 32         | propagation steps (0..4096); light travels one |
// |                       |        |            | cell per step: a 32-cell grid needs about 32  |
// | method                | string | "gather"   | "gather" or "scatter": the same grid (up to   |
// |                       |        |            | float rounding), other memory traffic         |
// | gpu_kernel            | string | "simple"   | GL gather layout: "simple" or "tiled"         |
// | bounces               | bool   | false      | re-emit the light the GV blocks with its      |
// |                       |        |            | surfaces' albedo; needs a geometry volume     |
// | far_face_solid_angle  | real   | 0.40066968 | Omega of the far face (solid_angle.h)         |
// | side_face_solid_angle | real   | 0.42343135 | a side face's; both for `lpvlab fit` to vary  |
// | damping               | real   | 1          | every step's transfer times this (0..2)       |

#include <cmath>
#include <iomanip>
#include <sstream>
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
#include "variants/propagation/standard_cpu_frame.h"
#include "variants/propagation/standard_gl.h"
#include "variants/propagation/standard_work.h"
#include "variants/resources/geometry_volume.h"

namespace lpvlab {
namespace {

class StandardPropagation final : public PropagationStrategy {
public:
  explicit StandardPropagation(Params& params)
      : iterations_(params.get<int>("iterations", 32, {.min = 0, .max = 4096})),
        scatter_(params.getChoice("method", "gather", {"gather", "scatter"}) == "scatter"),
        tiled_(params.getChoice("gpu_kernel", "simple", {"simple", "tiled"}) == "tiled"),
        bounces_(params.get<bool>("bounces", false)),
        farFace_(params.get<double>("far_face_solid_angle", cubeFaceSolidAngles().farFace,
                                    {.min = 0.0, .max = 4.0 * M_PI})),
        sideFace_(params.get<double>("side_face_solid_angle", cubeFaceSolidAngles().sideFace,
                                     {.min = 0.0, .max = 4.0 * M_PI})),
        damping_(params.get<double>("damping", 1.0, {.min = 0.0, .max = 2.0})) {
    if (tiled_ && scatter_)
      throw Error(params.where("gpu_kernel") +
                  ": \"tiled\" is a layout of the gather; method = \"scatter\" has only the simple one");
  }

  int maxShOrder() const override { return 3; }
  // Bounces re-emit what the GV blocks with its surfaces' albedo: they cannot run without both.
  void declare(ResourceUses& uses) const override {
    if (bounces_) {
      uses.consumes(kGeometryVolume, "bounces = true (they re-emit the light it blocks)");
      uses.consumes(kSurfaceAlbedo, "bounces = true (they re-emit with it)");
    } else {
      uses.reads(kGeometryVolume);
    }
  }
  std::string cpuRefusal(const Requirements&) const override { return {}; }

  void prepare(const StrategySetup& setup) override {
    const Requirements& requirements = setup.requirements;
    const GridGeometry& grid = setup.grid;
    shOrder_ = requirements.shOrder;
    if (runsOnCpu(requirements)) {
      cpu_ = StandardCpuFrame(requirements.shOrder, damping_ * farFace_, damping_ * sideFace_,
                              LightGrid::bytesPerGrid(grid, requirements.shOrder) / sizeof(float));
      onCpu_ = true;
      return;
    }
    gl_ = StandardGlKernel(setup.shaders, glSettings(requirements));
    scratch_ = DualBuffer(LightGrid::bytesPerGrid(grid, requirements.shOrder),
                          "light grid (propagation scratch)");
  }

  void propagate(Frame& frame) override {
    if (onCpu_)
      return cpu_.propagate(frame,
                            {.count = iterations_, .scatter = scatter_, .bounces = bounces_});
    LightGrid& grid = frame.lightGrid;
    StandardGlOcclusion occlusion;
    if (const GeometryVolume* gv = frame.find(kGeometryVolume)) {
      occlusion = {.blocking = &gv->blocking, .firstOccludedIteration = gv->firstOccludedIteration};
      if (bounces_) occlusion.albedo = &frame.get(kSurfaceAlbedo).albedo;
    }
    gl_.propagate(grid.geometry.resolution, iterations_, grid.current, scratch_, grid.accumulated,
                  occlusion);
  }

  int iterations() const override { return iterations_; }

  // A source cell sends its light through the 5 faces (1 far, 4 side) of each of its 6
  // neighbours: for an isotropic cell, the fraction of its flux sent on per iteration is
  // 6 (far + 4 side) / (4 pi), times the damping. The geometric solid angles make it exactly 1
  // (solid_angle.h); above 1 each iteration multiplies the light, up to gain^iterations (a fit or
  // a tune exploring the constants can get there: 1.5 over 34 iterations gave an image 1e5 times
  // too bright).
  double fluxGainPerIteration() const { return damping_ * 6.0 * (farFace_ + 4.0 * sideFace_) / (4.0 * M_PI); }

  std::vector<std::string> warnings() const override {
    const double gain = fluxGainPerIteration();
    if (iterations_ == 0 || gain <= 1.0 + 1e-6) return {};
    std::ostringstream out;
    out << std::setprecision(4) << "damping x 6 (far_face_solid_angle + 4 side_face_solid_angle) = "
        << gain * 4.0 * M_PI << " sr exceeds a cell's 4 pi: each iteration multiplies an isotropic cell's "
        << "light by up to " << gain << ", " << std::pow(gain, iterations_) << " over " << iterations_
        << " iterations (propagation gains energy)";
    return {out.str()};
  }

  // Derivatives: the standard CPU kernel on dual numbers (scattering gives gathering's grid).
  std::vector<std::string> differentiableParameters() const override {
    return {"far_face_solid_angle", "side_face_solid_angle", "damping"};
  }
  bool differentiates() const override { return true; }
  void propagateDual(DualFrame& frame) override {
    const Dual damping = frame.parameter("damping", damping_);
    StandardCpuFrame::propagateDual(frame, shOrder_,
                                    damping * frame.parameter("far_face_solid_angle", farFace_),
                                    damping * frame.parameter("side_face_solid_angle", sideFace_),
                                    {.count = iterations_, .bounces = bounces_});
  }

  // Per cell-iteration: on GL the kernel's (standard_gl.h: bounces run every face twice, the tiled
  // layout reads less), on the CPU standard_work.h's (bounces only on the blocked faces, not
  // counted).
  std::vector<WorkCount> work(const FrameShape& shape,
                              const Requirements& requirements) const override {
    const KernelWork w =
        runsOnCpu(requirements)
            ? standardCpuTransferWork(shape.coefficients, scatter_, requirements.has(kGeometryVolume))
            : standardGlKernelWork(glSettings(requirements));
    return {{"cell-iteration", shape.cells * shape.levels * iterations_, w.multiplyAdds, w.bytes}};
  }

  std::size_t memoryBytes() const override { return scratch_.size() + cpu_.memoryBytes(); }

private:
  StandardGlSettings glSettings(const Requirements& requirements) const {
    return {.coefficients = shared::shCoefficientCount(requirements.shOrder),
            .farFace = damping_ * farFace_,
            .sideFace = damping_ * sideFace_,
            .withGv = requirements.has(kGeometryVolume),
            .bounces = bounces_,
            .scatter = scatter_,
            .tiled = tiled_};
  }

  int iterations_;
  bool scatter_;
  bool tiled_;
  bool bounces_;
  double farFace_, sideFace_, damping_;
  int shOrder_ = 1;
  StandardGlKernel gl_;   // on GL
  DualBuffer scratch_;    // swapped with the grid's current buffer
  bool onCpu_ = false;
  StandardCpuFrame cpu_;  // on the CPU backend
};

LPVLAB_REGISTER(PropagationStrategy, "standard",
                "six-neighbour propagation through five faces each, by gathering or scattering, "
                "attenuated by the geometry volume when there is one (thesis 4.4, 7.4.3)",
                StandardPropagation);

}  // namespace
}  // namespace lpvlab

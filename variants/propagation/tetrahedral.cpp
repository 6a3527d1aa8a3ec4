// Propagation "tetrahedral": light propagates on the tetrahedral lattice of the body-centred
// cubic points (cube corners and centres; 12 congruent disphenoids per cube, four face
// neighbours each) instead of the cubes, with the standard method's face logic and
// normalisation (docs/variants/tetrahedral.md#tetrahedral; geometry and face solid angles in
// shaders/propagation/tetrahedral_lattice.glsl and framework/math/tetrahedral_solid_angles.h).
// Injection and rendering stay on the cubic light grid, so each frame:
//   1. split (tetrahedral_split.comp): the cubic `current` -> lattice, flux conserving;
//   2. `iterations` gather steps on the lattice (tetrahedral_gather.comp), summing every step;
//   3. merge (tetrahedral_merge.comp): the sum is added to the cubic `accumulated`, and the last
//      step, resampled, becomes the cubic `current`.
// Each far face's flux is the exact integral of the neighbour's SH intensity over the face
// (`face_flux = "integral"`, precomputed per face: framework/math/tetrahedral_face_integrals.h),
// which conserves flux for every SH function; "centre" is the standard method's one-point
// quadrature (solid angle times the intensity towards the face's centroid), which gains light
// through the clamp at every step.
// A step moves light sqrt(2)/4 = 0.354 cube edges (the distance between neighbouring centroids),
// so crossing a grid takes about 2.8 times the standard method's iterations.
// Any SH order up to 3 (the lattice holds as many coefficients per cell as the grid). When an
// occlusion strategy provides a geometry volume, each face's flux is multiplied by the GV's
// transmittance where its direction crosses the shared face (thesis alg. 6.2 lines 11-14 on the
// lattice), from the lattice step at which light has travelled the GV's firstOccludedIteration
// cube edges on (tetFirstOccludedStep).
// On the CPU backend the three steps run tetrahedral_cpu.h's kernels on the light grid's host
// side, the lattice in the CPU's own layout; what the GV does to every face is found once per GV
// (again only when it changes, so a static scene's warm-up frame pays for it).
//
// | parameter  | type | default | meaning                                                     |
// |------------|------|---------|-------------------------------------------------------------|
// | iterations | int  | 90      | lattice steps (0..16384); 90 moves light about 32 cube edges |
// | face_flux  | text | integral | "integral": exact SH integral over each face; "centre": solid
// angle x intensity towards its centroid |

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"
#include "framework/pipeline/dual_frame.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"
#include "variants/propagation/tetrahedral_cpu.h"
#include "variants/propagation/tetrahedral_gl.h"
#include "variants/resources/geometry_volume.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

class TetrahedralPropagation final : public PropagationStrategy {
public:
  explicit TetrahedralPropagation(Params& params)
      : iterations_(params.get<int>("iterations", 90, {.min = 0, .max = 16384})),
        faceIntegrals_(params.getChoice("face_flux", "integral", {"integral", "centre"}) == "integral") {}

  int maxShOrder() const override { return 3; }
  void declare(ResourceUses& uses) const override { uses.reads(kGeometryVolume); }
  std::string cpuRefusal(const Requirements&) const override { return {}; }

  void prepare(const StrategySetup& setup) override {
    ShaderCompiler& shaders = setup.shaders;
    const GridGeometry& grid = setup.grid;
    const Requirements& requirements = setup.requirements;
    shOrder_ = requirements.shOrder;
    if (runsOnCpu(requirements)) {
      cpuTable_ = makeTetrahedralTable<float>(requirements.shOrder, faceIntegrals_);
      onCpu_ = true;
      return;
    }
    gl_ = TetrahedralGlKernel(shaders, glSettings(requirements), grid.resolution);
  }

  void propagate(Frame& frame) override {
    if (onCpu_) return propagateOnCpu(frame);
    LightGrid& grid = frame.lightGrid;
    const GeometryVolume* gv = frame.find(kGeometryVolume);
    gl_.propagate(grid.geometry.resolution, iterations_, grid.current, grid.accumulated,
                  gv ? &gv->blocking : nullptr, gv ? gv->firstOccludedIteration : 0);
  }

  int iterations() const override { return iterations_; }

  // Per cube and step (a cell-iteration of the cubic grid, as the other propagations count) and
  // per cube and frame (the split and the merge): on GL tetrahedral_gl.h's counts; the CPU sums
  // the fluxes per face (16N per cell and channel: tetrahedralStepMultiplyAdds) and reads each
  // face's transmittance, found once per GV.
  std::vector<WorkCount> work(const FrameShape& shape,
                              const Requirements& requirements) const override {
    TetrahedralGlWork w = tetrahedralGlWork(glSettings(requirements));
    if (runsOnCpu(requirements)) {
      const double n = shape.coefficients, cells = double(kTetrahedralCellsPerCube);
      w.step.multiplyAdds = cells * 3 * tetrahedralStepMultiplyAdds(shape.coefficients);
      w.step.bytes = cells * 4 * (4 * 3 * n + 3 * n + 2 * 3 * n);
      if (requirements.has(kGeometryVolume)) {
        w.step.multiplyAdds += cells * 12 * 3;
        w.step.bytes += cells * 12 * 4;
      }
    }
    const double cubes = shape.cells * shape.levels;
    return {{"cell-iteration", cubes * iterations_, w.step.multiplyAdds, w.step.bytes},
            {"cell", cubes, w.frame.multiplyAdds, w.frame.bytes}};
  }

  std::size_t memoryBytes() const override {
    std::size_t bytes = gl_.memoryBytes() + cpuGv_.size() * sizeof(float);
    for (const auto& [grid, level] : cpuLevels_)
      bytes += level.lattice.bytes() +
               (level.occlusion.transmittance.size() + level.gv.size()) * sizeof(float);
    return bytes;
  }

private:
  // Per cascade level: its lattice, and what its GV does to the faces with the GV it was found from.
  struct CpuLevel {
    TetrahedralLattice<float> lattice;
    TetrahedralOcclusion<float> occlusion;
    std::vector<float> gv;
  };

  void propagateOnCpu(Frame& frame) {
    LightGrid& grid = frame.lightGrid;
    const glm::ivec3 res = grid.geometry.resolution;
    CpuLevel& level = cpuLevels_[&grid];
    if (level.lattice.resolution != res)
      level.lattice = TetrahedralLattice<float>(res, cpuTable_.coefficients);
    const GeometryVolume* gv = frame.find(kGeometryVolume);
    if (gv) {
      downloadFloats(gv->blocking,
                     std::size_t(gv->geometry.cellCount()) * GeometryVolume::kCoefficients, cpuGv_);
      if (level.occlusion.resolution != res || cpuGv_ != level.gv) {
        level.occlusion = makeTetrahedralOcclusion(level.lattice, cpuGv_.data());
        level.gv = cpuGv_;
      }
    }
    step(cpuTable_, level.lattice, gv ? &level.occlusion : nullptr, gv, grid.current.host(),
         grid.accumulated.host());
  }

  // Split `current` onto the lattice, the steps, merge back into `current` (the last step) and
  // `accumulated` (added to): float frames and dual ones alike.
  template <class Real>
  void step(const TetrahedralTable<Real>& table, TetrahedralLattice<Real>& lattice,
            const TetrahedralOcclusion<Real>* occlusion, const GeometryVolume* gv,
            std::vector<Real>& current, std::vector<Real>& accumulated) const {
    tetrahedralSplitCpu(current.data(), lattice);
    const int firstOccluded = gv ? shared::tetFirstOccludedStep(gv->firstOccludedIteration) : 0;
    const CpuKernelLevel instructions = widestCpuKernelLevel();
    for (int i = 0; i < iterations_; ++i)
      tetrahedralStepCpu(table, lattice, occlusion && i >= firstOccluded ? occlusion : nullptr,
                         instructions, pairedAccumulation(i, iterations_));
    tetrahedralMergeCpu(lattice, current.data(), accumulated.data());
  }

public:
  // Derivatives of what comes before it (the GV's): the same kernels on dual numbers.
  bool differentiates() const override { return true; }
  void propagateDual(DualFrame& dual) override {
    const LightGrid& grid = dual.frame.lightGrid;
    const glm::ivec3 res = grid.geometry.resolution;
    const TetrahedralTable<Dual> table = makeTetrahedralTable<Dual>(shOrder_, faceIntegrals_);
    TetrahedralLattice<Dual> lattice(res, table.coefficients);
    const GeometryVolume* gv = dual.frame.find(kGeometryVolume);
    TetrahedralOcclusion<Dual> occlusion;
    if (gv) {
      std::vector<float> values;
      downloadFloats(gv->blocking,
                     std::size_t(gv->geometry.cellCount()) * GeometryVolume::kCoefficients, values);
      const std::vector<Dual> blocking =
          dual.gvBlocking.empty() ? constantDuals(values) : dual.gvBlocking;
      occlusion = makeTetrahedralOcclusion<Dual, Dual>(lattice, blocking.data());
    }
    std::vector<Dual> current = dual.injected;
    dual.accumulated = dual.injected;  // the accumulated light starts as the injected light
    step(table, lattice, gv ? &occlusion : nullptr, gv, current, dual.accumulated);
  }

private:
  TetrahedralGlSettings glSettings(const Requirements& requirements) const {
    return {.coefficients = shared::shCoefficientCount(requirements.shOrder),
            .withGv = requirements.has(kGeometryVolume),
            .faceIntegrals = faceIntegrals_};
  }

  int iterations_;
  bool faceIntegrals_;
  int shOrder_ = 1;
  TetrahedralGlKernel gl_;  // on GL
  bool onCpu_ = false;
  TetrahedralTable<float> cpuTable_{};
  std::vector<float> cpuGv_;  // this frame's GV, read back
  std::map<const LightGrid*, CpuLevel> cpuLevels_;
};

LPVLAB_REGISTER(PropagationStrategy, "tetrahedral",
                "propagation on the BCC lattice's tetrahedra, four face neighbours each, "
                "resampled from and to the cubic grid, attenuated by the geometry volume when "
                "there is one",
                TetrahedralPropagation);

}  // namespace
}  // namespace lpvlab

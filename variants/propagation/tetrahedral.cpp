// Propagation "tetrahedral": light propagates on the tetrahedral lattice of the body-centred
// cubic points (cube corners and centres; 12 congruent disphenoids per cube, four face
// neighbours each) instead of the cubes, with the standard method's face logic and
// normalisation (docs/variants.md#tetrahedral; geometry and face solid angles in
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
//
// | parameter  | type | default | meaning                                                     |
// |------------|------|---------|-------------------------------------------------------------|
// | iterations | int  | 90      | lattice steps (0..16384); 90 moves light about 32 cube edges |
// | face_flux  | text | integral | "integral": exact SH integral over each face; "centre": solid angle x intensity towards its centroid |

#include <utility>
#include <vector>

#include "framework/gl/dispatch.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"
#include "framework/math/tetrahedral_face_integrals.h"
#include "framework/math/tetrahedral_solid_angles.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

constexpr int kCellsPerCube = 12;

namespace split_kernel {
#include "shaders/propagation/tetrahedral_split_interface.glsl"
}
namespace gather_kernel {
#include "shaders/propagation/tetrahedral_gather_interface.glsl"
}
namespace merge_kernel {
#include "shaders/propagation/tetrahedral_merge_interface.glsl"
}

class TetrahedralPropagation final : public PropagationStrategy {
public:
  explicit TetrahedralPropagation(Params& params)
      : iterations_(params.get<int>("iterations", 90, {.min = 0, .max = 16384})),
        faceIntegrals_(params.getChoice("face_flux", "integral", {"integral", "centre"}) == "integral") {}

  int maxShOrder() const override { return 3; }
  void declare(ResourceUses& uses) const override { uses.reads(kGeometryVolume); }

  void prepare(const StrategySetup& setup) override {
    ShaderCompiler& shaders = setup.shaders;
    const GridGeometry& grid = setup.grid;
    const Requirements& requirements = setup.requirements;
    const TetrahedralFaceSolidAngles angles = tetrahedralFaceSolidAngles();
    const int coefficients = shared::shCoefficientCount(requirements.shOrder);
    split_ = shaders.compute("propagation/tetrahedral_split.comp", {SpecConstant::i(0, coefficients)});
    gather_ = shaders.compute("propagation/tetrahedral_gather.comp",
                              {SpecConstant::f(0, float(angles.smallFace)),
                               SpecConstant::f(1, float(angles.largeFace)),
                               SpecConstant::i(2, coefficients),
                               SpecConstant::b(3, requirements.has(kGeometryVolume)),
                               SpecConstant::b(4, faceIntegrals_)});
    if (faceIntegrals_) {
      const std::vector<double>& table = tetrahedralFaceIntegrals();
      const std::vector<float> values(table.begin(), table.end());
      faceIntegralTable_ = gl::Buffer(values.size() * sizeof(float), "tetrahedral face integrals",
                                      values.data());
    }
    merge_ = shaders.compute("propagation/tetrahedral_merge.comp", {SpecConstant::i(0, coefficients)});
    // The lattice holds 12 cells per cube, each with the light grid's coefficients.
    const std::size_t bytes = std::size_t(kCellsPerCube) * LightGrid::bytesPerGrid(grid, requirements.shOrder);
    current_ = gl::Buffer(bytes, "tetrahedral lattice (current)");
    scratch_ = gl::Buffer(bytes, "tetrahedral lattice (propagation scratch)");
    sum_ = gl::Buffer(bytes, "tetrahedral lattice (sum of steps)");
  }

  void propagate(Frame& frame) override {
    LightGrid& grid = frame.lightGrid;
    const glm::ivec3 res = grid.geometry.resolution;
    const glm::ivec3 cellDomain{kCellsPerCube * res.x, res.y, res.z};
    {
      using namespace split_kernel;
      split_.use();
      glUniform3iv(LOCATION_RESOLUTION, 1, &res[0]);
      grid.current.bindStorage(BUFFER_CUBES);
      current_.bindStorage(BUFFER_CELLS);
      dispatchCovering(cellDomain, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                       GL_SHADER_STORAGE_BARRIER_BIT);
    }
    {
      using namespace gather_kernel;
      sum_.zero();
      gather_.use();
      glUniform3iv(LOCATION_RESOLUTION, 1, &res[0]);
      sum_.bindStorage(BUFFER_SUM);
      // Without a GV the kernel was compiled without its reads, and the uniform doesn't exist.
      const GeometryVolume* gv = frame.find(kGeometryVolume);
      if (gv) gv->blocking.bindStorage(BUFFER_GEOMETRY_VOLUME);
      if (faceIntegrals_) faceIntegralTable_.bindStorage(BUFFER_FACE_INTEGRALS);
      const int firstOccluded = gv ? shared::tetFirstOccludedStep(gv->firstOccludedIteration) : 0;
      for (int i = 0; i < iterations_; ++i) {
        if (gv) glUniform1i(LOCATION_OCCLUDED_STEP, i >= firstOccluded);
        current_.bindStorage(BUFFER_SOURCE);
        scratch_.bindStorage(BUFFER_TARGET);
        dispatchCovering(cellDomain, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z},
                         GL_SHADER_STORAGE_BARRIER_BIT);
        std::swap(current_, scratch_);
      }
    }
    using namespace merge_kernel;
    merge_.use();
    glUniform3iv(LOCATION_RESOLUTION, 1, &res[0]);
    current_.bindStorage(BUFFER_LAST);
    sum_.bindStorage(BUFFER_SUM);
    grid.current.bindStorage(BUFFER_CURRENT);
    grid.accumulated.bindStorage(BUFFER_ACCUMULATED);
    dispatchCovering(res, {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z}, GL_SHADER_STORAGE_BARRIER_BIT);
  }

  int iterations() const override { return iterations_; }
  std::size_t memoryBytes() const override {
    return current_.size() + scratch_.size() + sum_.size() + faceIntegralTable_.size();
  }

private:
  int iterations_;
  bool faceIntegrals_;
  Program split_, gather_, merge_;
  gl::Buffer current_, scratch_, sum_, faceIntegralTable_;
};

LPVLAB_REGISTER(PropagationStrategy, "tetrahedral",
                "propagation on the BCC lattice's tetrahedra, four face neighbours each, "
                "resampled from and to the cubic grid, attenuated by the geometry volume when "
                "there is one",
                TetrahedralPropagation);

}  // namespace
}  // namespace lpvlab

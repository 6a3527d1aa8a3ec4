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
// A step moves light sqrt(2)/4 = 0.354 cube edges (the distance between neighbouring centroids),
// so crossing a grid takes about 2.8 times the standard method's iterations.
//
// | parameter  | type | default | meaning                                                     |
// |------------|------|---------|-------------------------------------------------------------|
// | iterations | int  | 90      | lattice steps (0..16384); 90 moves light about 32 cube edges |

#include <utility>

#include "framework/gl/dispatch.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/tetrahedral_solid_angles.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"

namespace lpvlab {
namespace {

constexpr int kCellsPerCube = 12;
constexpr int kFloatsPerCell = 3 * 4;  // RGB, SH order 1

class TetrahedralPropagation final : public PropagationStrategy {
public:
  explicit TetrahedralPropagation(Params& params)
      : iterations_(params.get<int>("iterations", 90, {.min = 0, .max = 16384})) {}

  void prepare(ShaderCompiler& shaders, const GridGeometry& grid,
               const Requirements& requirements) override {
    (void)requirements;  // order 1 only: maxShOrder() refuses the rest
    const TetrahedralFaceSolidAngles angles = tetrahedralFaceSolidAngles();
    split_ = shaders.compute("propagation/tetrahedral_split.comp", {});
    gather_ = shaders.compute("propagation/tetrahedral_gather.comp",
                              {SpecConstant::f(0, float(angles.smallFace)),
                               SpecConstant::f(1, float(angles.largeFace))});
    merge_ = shaders.compute("propagation/tetrahedral_merge.comp", {});
    const std::size_t bytes =
        std::size_t(kCellsPerCube) * kFloatsPerCell * grid.cellCount() * sizeof(float);
    current_ = gl::Buffer(bytes, "tetrahedral lattice (current)");
    scratch_ = gl::Buffer(bytes, "tetrahedral lattice (propagation scratch)");
    sum_ = gl::Buffer(bytes, "tetrahedral lattice (sum of steps)");
  }

  void propagate(Frame& frame) override {
    LightGrid& grid = frame.lightGrid;
    const glm::ivec3 res = grid.geometry.resolution;
    const glm::ivec3 cellDomain{kCellsPerCube * res.x, res.y, res.z};
    const glm::ivec3 group{4};

    split_.use();
    glUniform3iv(0, 1, &res[0]);
    grid.current.bindStorage(0);
    current_.bindStorage(1);
    dispatchCovering(cellDomain, group, GL_SHADER_STORAGE_BARRIER_BIT);

    sum_.zero();
    gather_.use();
    glUniform3iv(0, 1, &res[0]);
    sum_.bindStorage(2);
    for (int i = 0; i < iterations_; ++i) {
      current_.bindStorage(0);
      scratch_.bindStorage(1);
      dispatchCovering(cellDomain, group, GL_SHADER_STORAGE_BARRIER_BIT);
      std::swap(current_, scratch_);
    }

    merge_.use();
    glUniform3iv(0, 1, &res[0]);
    current_.bindStorage(0);
    sum_.bindStorage(1);
    grid.current.bindStorage(2);
    grid.accumulated.bindStorage(3);
    dispatchCovering(res, group, GL_SHADER_STORAGE_BARRIER_BIT);
  }

  int iterations() const override { return iterations_; }
  std::size_t memoryBytes() const override {
    return current_.size() + scratch_.size() + sum_.size();
  }

private:
  int iterations_;
  Program split_, gather_, merge_;
  gl::Buffer current_, scratch_, sum_;
};

LPVLAB_REGISTER(PropagationStrategy, "tetrahedral",
                "propagation on the BCC lattice's tetrahedra, four face neighbours each, "
                "resampled from and to the cubic grid",
                TetrahedralPropagation);

}  // namespace
}  // namespace lpvlab

// Propagation "standard": light flows from each cell into its six face neighbours through the
// five faces not shared with the source, with the face solid angles derived in
// framework/math/solid_angle.cpp (thesis 4.4, alg. 6.2; Kaplanyan and Dachsbacher 2010).
// Implemented by gathering (shaders/propagation/standard_gather.comp); the per-face mathematics
// and its normalisation are in shaders/propagation/standard_faces.glsl.
//
// | parameter  | type | default | meaning                                                     |
// |------------|------|---------|-------------------------------------------------------------|
// | iterations | int  | 32      | propagation steps; light travels one cell per step (0..4096): |
// |            |      |         | a 32-cell grid needs about 32 for light to cross it           |

#include <utility>

#include "framework/gl/dispatch.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"
#include "framework/math/solid_angle.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"

namespace lpvlab {
namespace {

class StandardPropagation final : public PropagationStrategy {
public:
  explicit StandardPropagation(Params& params)
      : iterations_(params.get<int>("iterations", 32, {.min = 0, .max = 4096})) {}

  int maxShOrder() const override { return 3; }

  void prepare(ShaderCompiler& shaders, const GridGeometry& grid,
               const Requirements& requirements) override {
    const CubeFaceSolidAngles angles = cubeFaceSolidAngles();
    const int coefficients = shared::shCoefficientCount(requirements.shOrder);
    program_ = shaders.compute("propagation/standard_gather.comp",
                               {SpecConstant::f(0, float(angles.farFace)),
                                SpecConstant::f(1, float(angles.sideFace)),
                                SpecConstant::i(2, coefficients)});
    const std::size_t bytes = std::size_t(3) * coefficients * grid.cellCount() * sizeof(float);
    scratch_ = gl::Buffer(bytes, "light grid (propagation scratch)");
  }

  void propagate(Frame& frame) override {
    LightGrid& grid = frame.lightGrid;
    program_.use();
    glUniform3iv(0, 1, &grid.geometry.resolution[0]);
    grid.accumulated.bindStorage(2);
    for (int i = 0; i < iterations_; ++i) {
      grid.current.bindStorage(0);
      scratch_.bindStorage(1);
      dispatchCovering(grid.geometry.resolution, glm::ivec3(4), GL_SHADER_STORAGE_BARRIER_BIT);
      std::swap(grid.current, scratch_);  // the new light becomes the next step's source
    }
  }

  int iterations() const override { return iterations_; }
  std::size_t memoryBytes() const override { return scratch_.size(); }

private:
  int iterations_;
  Program program_;
  gl::Buffer scratch_;
};

LPVLAB_REGISTER(PropagationStrategy, "standard",
                "six-neighbour propagation through five faces each, by gathering (thesis 4.4)",
                StandardPropagation);

}  // namespace
}  // namespace lpvlab

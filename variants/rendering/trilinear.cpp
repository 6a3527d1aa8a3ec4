// Rendering "trilinear": indirect light read from one light grid, trilinearly interpolated, at
// each visible surface point (thesis 4.5, 6.9.3; kernel shaders/rendering/trilinear.comp).
//
// | parameter     | type  | default | meaning                                                  |
// |---------------|-------|---------|----------------------------------------------------------|
// | normal_offset | float | 0.0     | read the grid this many cells along the surface normal   |

#include "framework/gl/dispatch.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"
#include "framework/pipeline/frame.h"
#include "framework/pipeline/strategy.h"

namespace lpvlab {
namespace {

class TrilinearRendering final : public RenderingStrategy {
public:
  explicit TrilinearRendering(Params& params)
      : normalOffsetCells_(params.get<float>("normal_offset", 0.0f, {.min = -2.0f, .max = 2.0f})) {}

  int maxShOrder() const override { return 3; }

  void prepare(ShaderCompiler& shaders, const GridGeometry&,
               const Requirements& requirements) override {
    program_ = shaders.compute("rendering/trilinear.comp",
                               {SpecConstant::i(0, shared::shCoefficientCount(requirements.shOrder))});
  }

  void render(Frame& frame) override {
    const GridGeometry& grid = frame.lightGrid.geometry;
    program_.use();
    glBindTextureUnit(0, frame.gbuffer.position.id());
    glBindTextureUnit(1, frame.gbuffer.normal.id());
    glBindTextureUnit(2, frame.gbuffer.albedo.id());
    frame.lightGrid.accumulated.bindStorage(0);
    glBindImageTexture(0, frame.indirect.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glUniform3fv(0, 1, &grid.origin[0]);
    glUniform1f(1, grid.cellSize);
    glUniform3iv(2, 1, &grid.resolution[0]);
    glUniform1f(3, normalOffsetCells_);
    dispatchCovering({frame.gbuffer.width, frame.gbuffer.height, 1}, {8, 8, 1}, GL_ALL_BARRIER_BITS);
  }

private:
  float normalOffsetCells_;
  Program program_;
};

LPVLAB_REGISTER(RenderingStrategy, "trilinear",
                "one grid, trilinear interpolation, Lambertian surfaces (thesis 4.5)",
                TrilinearRendering);

}  // namespace
}  // namespace lpvlab

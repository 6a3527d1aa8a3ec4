// Rendering "trilinear": indirect light read from one light grid, trilinearly interpolated, at
// each visible surface point (thesis 4.5, 6.9.3; kernel shaders/rendering/trilinear.comp), with
// optional leak damping (thesis 4.5, fig. 4.3 right; docs/variants/trilinear.md#leak_damping): where the
// light read grows towards the surface along its normal, it probably came through the wall
// behind, and is damped. Damping is a parameter, not a strategy of its own, because it changes
// only one factor of the same read, and combines with "glossy" (glossy.cpp), which shares this
// kernel. docs/variants/trilinear.md#trilinear.
//
// | parameter     | type  | default | meaning                                                  |
// |---------------|-------|---------|----------------------------------------------------------|
// | normal_offset | float | 0.0     | read the grid this many cells along the surface normal   |
// |               |       |         | (-2..2)                                                  |
// | leak_damping  | float | 0.0     | strength k of the damping exp(-k g), g = the light's     |
// |               |       |         | relative growth per cell towards the surface (0..16);    |
// |               |       |         | 0 = off                                                  |
// | scale         | float | 1.0     | the indirect light times this (0..100): a constant for   |
// |               |       |         | `lpvlab fit` (docs/fitting.md)                           |

#include "variants/rendering/trilinear_kernel.h"

#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/gl/dispatch.h"
#include "framework/math/grid_geometry.h"
#include "framework/math/shared.h"
#include "framework/pipeline/cascade.h"
#include "framework/pipeline/dual_frame.h"
#include "framework/pipeline/frame.h"
#include "framework/scene/scene.h"
#include "variants/rendering/trilinear_cpu.h"

namespace lpvlab {

TrilinearKernelOptions TrilinearKernelOptions::readDiffuse(Params& params) {
  TrilinearKernelOptions options;
  options.normalOffsetCells = params.get<float>("normal_offset", 0.0f, {.min = -2.0f, .max = 2.0f});
  options.leakDamping = params.get<float>("leak_damping", 0.0f, {.min = 0.0f, .max = 16.0f});
  options.scale = params.get<float>("scale", 1.0f, {.min = 0.0f, .max = 100.0f});
  return options;
}

std::string TrilinearKernelRendering::cpuRefusal(const Requirements&) const { return {}; }

void TrilinearKernelRendering::prepare(const StrategySetup& setup) {
  const Requirements& requirements = setup.requirements;
  coefficients_ = shared::shCoefficientCount(requirements.shOrder);
  onCpu_ = runsOnCpu(requirements);
  if (onCpu_) return;
  program_ = setup.shaders.compute("rendering/trilinear.comp",
                             {SpecConstant::i(0, shared::shCoefficientCount(requirements.shOrder)),
                              SpecConstant::b(1, options_.leakDamping > 0.0f),
                              SpecConstant::b(2, options_.specularAlbedo > 0.0f)});
}

namespace {
namespace kernel {
#include "shaders/rendering/trilinear_interface.glsl"
}
}  // namespace

// The G-buffer comes from the frame's host copies (read back once per frame), each level's
// accumulated grid from its host side (read back only if GL wrote it last), and the indirect
// image from its host side, added to, so that strategies before and after this one (on either
// backend) keep their shares; it goes to GL only if a GL strategy after this one asks for it.
void TrilinearKernelRendering::renderOnCpu(Frame& frame) {
  if (!frame.host) throw Error("rendering \"trilinear\" (CPU): the frame has no host images");
  const std::span<const LightGrid> levels = frame.renderedLevels();
  std::vector<TrilinearCpuLevel> cpuLevels;
  for (const LightGrid& level : levels)
    cpuLevels.push_back({level.accumulated.hostRead().data(), level.geometry});
  trilinearDiffuseCpu(frame.host->image(frame.gbuffer.position), frame.host->image(frame.gbuffer.normal),
                      frame.host->image(frame.gbuffer.albedo), cpuLevels,
                      settings<float>(frame, [](const char*, float value) { return value; }),
                      frame.indirect.host());
}

// The same on dual numbers: the grid's derivatives and those of the seeded constants.
void TrilinearKernelRendering::renderDual(DualFrame& dual) {
  Frame& frame = dual.frame;
  if (!frame.host) throw Error("rendering \"trilinear\" (CPU): the frame has no host images");
  const TrilinearLevelOf<Dual> level{dual.accumulated.data(), frame.lightGrid.geometry};
  trilinearDiffuseDual(frame.host->image(frame.gbuffer.position),
                       frame.host->image(frame.gbuffer.normal),
                       frame.host->image(frame.gbuffer.albedo), {&level, 1},
                       settings<Dual>(frame, [&](const char* name, float value) {
                         return dual.parameter(name, value);
                       }),
                       *dual.indirect);
}

template <class Real, class Constant>
TrilinearSettingsOf<Real> TrilinearKernelRendering::settings(const Frame& frame,
                                                             const Constant& constant) const {
  return {.coefficients = coefficients_,
          .normalOffsetCells = constant("normal_offset", options_.normalOffsetCells),
          .leakDamping = constant("leak_damping", options_.leakDamping),
          .scale = constant("scale", options_.scale),
          .blendCells = frame.cascadeBlendCells,
          .specularAlbedo = options_.specularAlbedo,
          .phongExponent = options_.phongExponent,
          .marchStepCells = options_.marchStepCells,
          .marchSamples = options_.marchSamples,
          .cameraPosition = frame.camera ? frame.camera->position : glm::vec3(0.0f)};
}

void TrilinearKernelRendering::render(Frame& frame) {
  if (onCpu_) return renderOnCpu(frame);
  using namespace kernel;
  // The camera is needed only by the glossy march (the view direction).
  const glm::vec3 cameraPosition = frame.camera ? frame.camera->position : glm::vec3(0.0f);
  program_.use();
  glBindTextureUnit(UNIT_G_POSITION, frame.gbuffer.position.id());
  glBindTextureUnit(UNIT_G_NORMAL, frame.gbuffer.normal.id());
  glBindTextureUnit(UNIT_G_ALBEDO, frame.gbuffer.albedo.id());
  glBindImageTexture(IMAGE_OUT_INDIRECT, frame.indirect.texture().id(), 0, GL_FALSE, 0, GL_READ_WRITE,
                     GL_RGBA32F);
  glUniform1f(LOCATION_NORMAL_OFFSET_CELLS, options_.normalOffsetCells);
  glUniform1f(LOCATION_INDIRECT_SCALE, options_.scale);
  // An option that is off is compiled out with its uniforms, which then must not be set.
  if (options_.leakDamping > 0.0f) glUniform1f(LOCATION_LEAK_DAMPING_STRENGTH, options_.leakDamping);
  if (options_.specularAlbedo > 0.0f) {
    glUniform3fv(LOCATION_CAMERA_POSITION, 1, &cameraPosition[0]);
    glUniform1f(LOCATION_SPECULAR_ALBEDO, options_.specularAlbedo);
    glUniform1f(LOCATION_PHONG_EXPONENT, options_.phongExponent);
    glUniform1f(LOCATION_MARCH_STEP_CELLS, options_.marchStepCells);
    glUniform1i(LOCATION_MARCH_SAMPLES, options_.marchSamples);
  }
  // One dispatch per cascade level, each adding its weighted share.
  const std::span<const LightGrid> levels = frame.renderedLevels();
  for (std::size_t level = 0; level < levels.size(); ++level) {
    const GridGeometry& grid = levels[level].geometry;
    levels[level].accumulated.bindStorage(BUFFER_ACCUMULATED);
    glUniform3fv(LOCATION_GRID_ORIGIN, 1, &grid.origin[0]);
    glUniform1f(LOCATION_CELL_SIZE, grid.cellSize);
    glUniform3iv(LOCATION_RESOLUTION, 1, &grid.resolution[0]);
    setCascadeBlendUniforms(frame, int(level));
    dispatchCovering({frame.gbuffer.width, frame.gbuffer.height, 1},
                     {GROUP_SIZE_X, GROUP_SIZE_Y, GROUP_SIZE_Z}, GL_ALL_BARRIER_BITS);
  }
}

std::vector<WorkCount> TrilinearKernelRendering::work(const FrameShape& shape,
                                                     const Requirements& requirements) const {
  const double n = shape.coefficients;
  const double reads = options_.leakDamping > 0.0f ? 2.0 : 1.0;
  // Per read (two with leak damping: the value and its slope): 8 corner weights, 24 n
  // multiply-adds interpolating the coefficients, 3 n projecting them; n lobe coefficients.
  std::vector<WorkCount> work = {{"pixel", shape.pixels * shape.levels,
                                  reads * (24 * n + 8 + 3 * n) + n, 3 * 16 + 2 * 16 + reads * 96 * n}};
  // The glossy march: every sample counted (an upper bound: a march stops where it leaves the
  // coarsest level), each one read as above without the slope (8 n-float runs of 3 channels);
  // the Phong lobe's n coefficients once per pixel are counted with the pixel.
  if (options_.specularAlbedo > 0.0f) {
    work.front().multiplyAddsPerUnit += n;
    work.push_back({"march-sample", shape.pixels * shape.levels * options_.marchSamples,
                    24 * n + 8 + 3 * n, 96 * n});
  }
  return work;
}

namespace {

class TrilinearRendering final : public TrilinearKernelRendering {
public:
  explicit TrilinearRendering(Params& params)
      : TrilinearKernelRendering(TrilinearKernelOptions::readDiffuse(params)) {}
};

LPVLAB_REGISTER(RenderingStrategy, "trilinear",
                "one grid, trilinear interpolation, Lambertian surfaces, optional leak damping "
                "(thesis 4.5)",
                TrilinearRendering);

}  // namespace
}  // namespace lpvlab

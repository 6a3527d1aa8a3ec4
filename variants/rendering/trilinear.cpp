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
  gl_ = TrilinearGlKernel(setup.shaders, options_, coefficients_);
}

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
  std::vector<TrilinearGlLevel> levels;
  for (const LightGrid& level : frame.renderedLevels())
    levels.push_back({&level.accumulated, level.geometry});
  // The camera is needed only by the glossy march (the view direction).
  gl_.render({.position = frame.gbuffer.position.id(),
              .normal = frame.gbuffer.normal.id(),
              .albedo = frame.gbuffer.albedo.id(),
              .indirect = frame.indirect.texture().id(),
              .width = frame.gbuffer.width,
              .height = frame.gbuffer.height},
             levels, frame.cascadeBlendCells,
             frame.camera ? frame.camera->position : glm::vec3(0.0f));
}

std::vector<WorkCount> TrilinearKernelRendering::work(const FrameShape& shape,
                                                     const Requirements&) const {
  const TrilinearGlWork w = trilinearGlWork(options_, shape.coefficients);
  std::vector<WorkCount> work = {
      {"pixel", shape.pixels * shape.levels, w.pixelMultiplyAdds, w.pixelBytes}};
  if (options_.specularAlbedo > 0.0f)
    work.push_back({"march-sample", shape.pixels * shape.levels * options_.marchSamples,
                    w.sampleMultiplyAdds, w.sampleBytes});
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

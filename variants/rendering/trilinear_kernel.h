#pragma once
// The rendering kernel shaders/rendering/trilinear.comp behind the strategies "trilinear" and
// "glossy": one kernel whose options (leak damping, the glossy march) are specialisation
// constants, so the trilinear sampling code exists once and a disabled option costs nothing.
// On the CPU backend the diffuse light (without the glossy march) runs trilinear_cpu.h, which
// calls the kernel's shared functions (shaders/rendering/trilinear_diffuse.glsl).

#include <vector>

#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/strategy.h"
#include "variants/rendering/trilinear_cpu.h"
#include "variants/rendering/trilinear_gl.h"

namespace lpvlab {

class TrilinearKernelRendering : public RenderingStrategy {
public:
  explicit TrilinearKernelRendering(const TrilinearKernelOptions& options) : options_(options) {}

  int maxShOrder() const override { return 3; }
  std::string cpuRefusal(const Requirements& requirements) const override;
  void prepare(const StrategySetup& setup) override;
  void render(Frame& frame) override;
  // Per pixel and level, and per march sample of the glossy march: trilinear_gl.h's counts.
  std::vector<WorkCount> work(const FrameShape& shape,
                              const Requirements& requirements) const override;

  // Derivatives: its CPU kernel on dual numbers (trilinear_cpu.h), with respect to the grid's
  // light and its own constants (the glossy ones are constants there).
  std::vector<std::string> differentiableParameters() const override {
    return {"normal_offset", "leak_damping", "scale"};
  }
  bool differentiates() const override { return true; }
  void renderDual(DualFrame& frame) override;

private:
  void renderOnCpu(Frame& frame);
  // The CPU kernel's settings for `frame`, the three constants as `constant(name, value)` gives
  // them (the values, or the dual frame's parameters).
  template <class Real, class Constant>
  TrilinearSettingsOf<Real> settings(const Frame& frame, const Constant& constant) const;

  TrilinearKernelOptions options_;
  TrilinearGlKernel gl_;  // on GL
  bool onCpu_ = false;
  int coefficients_ = 4;
};

}  // namespace lpvlab

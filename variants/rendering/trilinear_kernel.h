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

namespace lpvlab {

class Params;

// What the kernel is asked to do, read from a [rendering] table.
struct TrilinearKernelOptions {
  float normalOffsetCells = 0.0f;   // normal_offset
  float leakDamping = 0.0f;         // leak_damping: 0 disables it (the kernel skips the slope)
  float scale = 1.0f;               // scale: the indirect light times this (for lpvlab fit)
  float specularAlbedo = 0.0f;      // glossy only; 0 disables the march
  float phongExponent = 1.0f;
  float marchStepCells = 1.0f;
  int marchSamples = 0;

  // normal_offset, leak_damping and scale (both strategies).
  static TrilinearKernelOptions readDiffuse(Params& params);
  // The diffuse keys plus specular_albedo, exponent, step and max_distance ("glossy").
  static TrilinearKernelOptions readGlossy(Params& params);
};

class TrilinearKernelRendering : public RenderingStrategy {
public:
  explicit TrilinearKernelRendering(const TrilinearKernelOptions& options) : options_(options) {}

  int maxShOrder() const override { return 3; }
  std::string cpuRefusal(const Requirements& requirements) const override;
  void prepare(const StrategySetup& setup) override;
  void render(Frame& frame) override;
  // Per pixel and level: the G-buffer's 3 texels (16 B each) and the output's read and write;
  // the lobe (N), and per channel the 8 corner cells' N coefficients against it plus the 8
  // trilinear weights (24N + 8, its 96N bytes). Leak damping reads the corners once more for
  // the slope. The glossy march (specular_albedo > 0) is not modelled: then nothing is counted.
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
  Program program_;
  bool onCpu_ = false;
  int coefficients_ = 4;
};

}  // namespace lpvlab

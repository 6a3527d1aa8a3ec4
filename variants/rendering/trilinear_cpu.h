#pragma once
// "trilinear" and "glossy" rendering on the CPU (the CPU backend, strategy.h): per G-buffer pixel
// the functions of shaders/rendering/trilinear_diffuse.glsl (and, with specular_albedo > 0,
// glossy_march.glsl) compiled as C++ in single precision (framework/math/shared.h), as GL runs
// them, the very text the GL kernel runs, the diffuse part times the pixel's cascade weight
// (cascade_weight.glsl), added to the indirect image as the GL kernel adds: rgb += scale *
// radiance, a += weight. Rows of pixels are shared out by oneTBB and each pixel is written by one
// task, so the image does not depend on the thread count.

#include <span>
#include <vector>

#include "framework/core/cpu_dispatch.h"
#include "framework/math/dual.h"
#include "framework/pipeline/dual_frame.h"
#include "framework/math/grid_geometry.h"
#include "framework/pipeline/host_readback.h"

namespace lpvlab {

// One cascade level (the only one without cascades): its accumulated grid (grid.glsl layout,
// `coefficients` per channel) and its placement. `Real`: float, or Dual for derivatives.
template <class Real>
struct TrilinearLevelOf {
  const Real* accumulated = nullptr;
  GridGeometry geometry;
};
using TrilinearCpuLevel = TrilinearLevelOf<float>;

// The strategy's constants are `Real`, so that on dual numbers they carry derivatives too.
template <class Real>
struct TrilinearSettingsOf {
  int coefficients = 4;          // SH coefficients per channel
  Real normalOffsetCells = 0.0f;
  Real leakDamping = 0.0f;       // 0: off
  Real scale = 1.0f;             // [rendering] scale
  float blendCells = 0.0f;       // [cascades] blend_cells
  // "glossy" (glossy_march.glsl): off with specularAlbedo = 0.
  float specularAlbedo = 0.0f;
  float phongExponent = 32.0f;
  float marchStepCells = 1.0f;   // in cells of the coarsest level
  int marchSamples = 16;
  glm::vec3 cameraPosition{0.0f};
  CpuKernelLevel instructions = pixelKernelLevel();  // cpu_dispatch.h
};
using TrilinearCpuSettings = TrilinearSettingsOf<float>;

// Adds every level's light to `indirect` at the pixels whose G-buffer `position` has w = 1.
// Throws an Error for images of different sizes or more cascade levels than rendering blends.
void trilinearDiffuseCpu(const HostImage& position, const HostImage& normal,
                         const HostImage& albedo, std::span<const TrilinearCpuLevel> levels,
                         const TrilinearCpuSettings& settings, HostImage& indirect);

// The same on dual numbers (framework/math/dual.h): the indirect light and its derivatives with
// respect to what the grid and the settings depend on, from the same text
// (trilinear_cpu_body.h), in double precision.
void trilinearDiffuseDual(const HostImage& position, const HostImage& normal,
                          const HostImage& albedo, std::span<const TrilinearLevelOf<Dual>> levels,
                          const TrilinearSettingsOf<Dual>& settings, DualTexelImage& indirect);

// What both check: an Error for images of different sizes or too many levels.
void checkTrilinearInputs(const HostImage& position, const HostImage& normal,
                          const HostImage& albedo, int indirectWidth, int indirectHeight,
                          std::size_t levels);

}  // namespace lpvlab

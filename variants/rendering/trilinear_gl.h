#pragma once
// The GL kernel shaders/rendering/trilinear.comp behind the rendering strategies "trilinear" and
// "glossy", and how it is dispatched: one dispatch per cascade level over the G-buffer, each adding
// its weighted share to the indirect image. The strategies (trilinear.cpp, glossy.cpp) and
// lpvlab-gpubench (trilinear_gpubench.cpp) both run it through this class. Also its work model.

#include <span>
#include <vector>

#include <glad/gl.h>
#include <glm/glm.hpp>

#include "framework/gl/dual_buffer.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/grid_geometry.h"

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

  // normal_offset, leak_damping and scale (both strategies; trilinear.cpp).
  static TrilinearKernelOptions readDiffuse(Params& params);
  // The diffuse keys plus specular_albedo, exponent, step and max_distance ("glossy"; glossy.cpp).
  static TrilinearKernelOptions readGlossy(Params& params);
};

// What the kernel reads and writes: the G-buffer's position, normal and albedo textures (RGBA32F)
// and the indirect image (RGBA32F, added to), `width` x `height` pixels.
struct TrilinearGlTarget {
  GLuint position = 0, normal = 0, albedo = 0, indirect = 0;
  int width = 0, height = 0;
};

// A cascade level as the kernel reads it: its accumulated light and its placement.
struct TrilinearGlLevel {
  const DualBuffer* accumulated = nullptr;
  GridGeometry geometry;
};

// Per pixel and level, with N coefficients per channel: the G-buffer's 3 texels (16 B each) and
// the output's read and write; per read (two with leak damping: the value and its slope) 8 corner
// weights, 24 N multiply-adds interpolating the coefficients and 3 N projecting them (96 N bytes);
// the lobe's N. The glossy march (specular_albedo > 0): every sample (an upper bound: a march
// stops where it leaves the coarsest level), each read as above without the slope, and the Phong
// lobe's N once per pixel.
struct TrilinearGlWork {
  double pixelMultiplyAdds = 0.0, pixelBytes = 0.0;
  double sampleMultiplyAdds = 0.0, sampleBytes = 0.0;  // per march sample
};
TrilinearGlWork trilinearGlWork(const TrilinearKernelOptions& options, int coefficients);

class TrilinearGlKernel {
public:
  TrilinearGlKernel() = default;
  TrilinearGlKernel(ShaderCompiler& shaders, const TrilinearKernelOptions& options,
                    int coefficients);

  // Adds each level's share of the indirect light to target.indirect (the glossy march views
  // from `cameraPosition`).
  void render(const TrilinearGlTarget& target, std::span<const TrilinearGlLevel> levels,
              float blendCells, const glm::vec3& cameraPosition) const;

private:
  TrilinearKernelOptions options_;
  Program program_;
};

}  // namespace lpvlab

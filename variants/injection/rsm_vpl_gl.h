#pragma once
// The GL kernel of RSM injection (shaders/injection/rsm_vpl.comp) and how it is dispatched: every
// texel of every view's reflective shadow map adds its VPL to the light grid (float atomics). The
// strategy (rsm_vpl.cpp) and lpvlab-gpubench (rsm_vpl_gpubench.cpp) both run it through this
// class. Also its work model.

#include <glad/gl.h>

#include "framework/gl/dual_buffer.h"
#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "framework/math/grid_geometry.h"
#include "framework/pipeline/kernel_work.h"

namespace lpvlab {

// The RSMs as the kernel reads them: 2D array textures (RGBA32F, one layer per view) of
// position (w = 1 where covered), normal and reflected flux, `resolution` texels square.
struct RsmVplGlMaps {
  GLuint position = 0, normal = 0, flux = 0;
  int resolution = 0, views = 0;
};

// Per VPL (RSM texel), with N coefficients per channel: 3 texel fetches (16 B each); the lobe (N,
// about a multiply-add each) and 3N products; the cell from the shifted position (about 10); with
// the normal grid 4 more sums. Each product is added atomically (read and write, 8 B each).
KernelWork rsmVplGlWork(int coefficients, bool withNormals);

class RsmVplGlKernel {
public:
  RsmVplGlKernel() = default;
  // withNormals: the VPLs' flux-weighted normals go to a normal grid too.
  RsmVplGlKernel(ShaderCompiler& shaders, int coefficients, bool withNormals, float shiftCells);

  // Adds every VPL of `maps` to `grid` (placed by `geometry`), and its normal to `normals`.
  void inject(const RsmVplGlMaps& maps, const GridGeometry& geometry, DualBuffer& grid,
              const gl::Buffer* normals) const;

private:
  bool withNormals_ = false;
  float shiftCells_ = 1.0f;
  Program program_;
};

}  // namespace lpvlab

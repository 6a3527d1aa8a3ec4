#pragma once
// The subsurface LPV's shading on the CPU (rendering "subsurface", step 4; subsurface.h): at every
// pixel its camera mask marks translucent, the light leaving the surface, from the same shared
// GLSL as shaders/subsurface/render.comp (subsurface_exit.glsl, in single precision as GL runs
// it), added to the indirect image. Rows in parallel, at the per-pixel kernels' instruction set
// (cpu_dispatch.h).

#include "framework/core/cpu_dispatch.h"
#include "framework/math/grid_geometry.h"
#include "framework/pipeline/host_readback.h"

namespace lpvlab {

struct SubsurfaceShadingInputs {
  const HostImage* position = nullptr;  // the G-buffer's: world position, w = 1 where covered
  const HostImage* normal = nullptr;    // the G-buffer's: unit normal facing the camera
  const HostImage* mask = nullptr;      // the strategy's camera mask: r >= 0.5 where translucent
  const float* accumulated = nullptr;   // the SSLPV's accumulated grid (grid.glsl's layout)
  GridGeometry geometry;                // the SSLPV's placement
  int coefficients = 4;                 // per channel
  CpuKernelLevel instructions = pixelKernelLevel();
};

// Adds the exiting light to `indirect` (the same size as the inputs' images).
void addSubsurfaceLightCpu(const SubsurfaceShadingInputs& in, HostImage& indirect);

}  // namespace lpvlab

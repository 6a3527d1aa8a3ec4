#pragma once
// The GL kernels of standard propagation and how they are dispatched: gathering
// (shaders/propagation/standard_gather.comp, or its tiled layout standard_gather_tiled.comp) and
// scattering (standard_scatter.comp). The strategy (standard.cpp) and lpvlab-gpubench
// (standard_gpubench.cpp) both run them through this class, so the benchmark times what a frame
// runs. Also the GL kernels' work model per cell-iteration, which directed propagation's builds
// on (directed_gl.h); the CPU kernels' is standard_work.h.

#include <glm/glm.hpp>

#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "framework/pipeline/kernel_work.h"
#include "framework/gl/dual_buffer.h"

namespace lpvlab {

// One cell-iteration of the GL kernels (docs/variants/standard.md#operations-per-cell-per-iteration),
// with N = coefficients per channel and 3 channels. Reads: the six neighbours' 3N floats; writes:
// the cell's 3N; the accumulated grid's 3N read and written; scattering adds into its 6
// neighbours atomically (6 x 3N read-modify-writes instead of 3N writes). Multiply-adds: 30 faces
// x 2N per channel (the SH evaluations per face not counted). The GV: its 8 corners (vec4) read
// per cell, 8 x 4 interpolated per face.
inline KernelWork standardGlTransferWork(int coefficients, bool scatter, bool withGv) {
  const double n = coefficients;
  KernelWork w;
  w.multiplyAdds = 3 * 30 * 2 * n;
  w.bytes = 4 * (6 * 3 * n + (scatter ? 2 * 6 * 3 * n : 3 * n) + 2 * 3 * n);
  if (withGv) {
    w.multiplyAdds += 30 * 8 * 4;
    w.bytes += 8 * 16;
  }
  return w;
}

struct StandardGlSettings {
  int coefficients = 4;           // per channel: (SH order + 1)^2
  double farFace = 0.0;           // the far face's solid angle, damping applied
  double sideFace = 0.0;          // a side face's
  bool withGv = false;            // a GV is bound (the kernels are compiled with its reads)
  bool bounces = false;           // re-emit the light the GV blocks (needs the GV's albedo)
  bool scatter = false;           // scatter with float atomics instead of gathering
  bool tiled = false;             // the tiled gather (standard_gather_tiled.comp)
};

// The GV as the kernels read it (variants/resources/geometry_volume.h): its blocking
// coefficients, its albedo (with bounces) and the first iteration it attenuates.
struct StandardGlOcclusion {
  const gl::Buffer* blocking = nullptr;
  const gl::Buffer* albedo = nullptr;
  int firstOccludedIteration = 0;
};

// Per cell-iteration, as the kernel of `settings` runs: bounces run every face twice; the tiled
// layout reads each source cell once and its tile's halo again (tiled_walk.h).
KernelWork standardGlKernelWork(const StandardGlSettings& settings);

class StandardGlKernel {
public:
  StandardGlKernel() = default;
  // Compiles the kernel the settings name, specialised for them.
  StandardGlKernel(ShaderCompiler& shaders, const StandardGlSettings& settings);

  // `iterations` steps, numbered from `firstIteration` (the GV attenuates from its
  // firstOccludedIteration on): each writes the next light into `scratch`, adds it to
  // `accumulated` and swaps `current` and `scratch`, so `current` holds the last step's light.
  void propagate(const glm::ivec3& resolution, int iterations, DualBuffer& current,
                 DualBuffer& scratch, DualBuffer& accumulated,
                 const StandardGlOcclusion& occlusion, int firstIteration = 0) const;

private:
  void dispatch(const glm::ivec3& resolution) const;

  StandardGlSettings settings_;
  glm::ivec2 tile_{1, 1};  // the tiled kernel's work group (x, y)
  Program program_;
};

}  // namespace lpvlab

#pragma once
// The GL kernels of directed propagation and how they are dispatched: the dilation of the VPLs'
// normals (shaders/propagation/directed_dilate.comp), the reprojecting gather
// (directed_gather.comp) and, with release, the release (directed_release.comp) and the free
// light's standard gather (standard_gl.h). The strategy (directed.cpp) and lpvlab-gpubench
// (directed_gpubench.cpp) both run them through this class. Also their work model.

#include <glm/glm.hpp>

#include "framework/gl/dual_buffer.h"
#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "variants/propagation/standard_gl.h"

namespace lpvlab {

struct DirectedGlSettings {
  int coefficients = 4;         // per channel: (SH order + 1)^2
  bool withGv = false;          // a GV is bound (the kernels are compiled with its reads)
  bool dilation = true;         // dilate the normals before every iteration
  bool release = true;          // light leaves the reprojection where the normals change
  double cosRegionAngle = 1.0;  // release: normals further apart are different regions
  bool tiled = false;           // the tiled gathers (directed_gather_tiled.comp, tiled_walk.h)
  bool scatter = false;         // scatter with float atomics (directed_scatter.comp) instead
};

// Per cell-iteration on GL: the standard transfer's (standard_gl.h) and the second reprojection:
// per face and channel the reprojection factor (about 8), per cell the gain G(n) (60 lobe values
// of about 8 each) and the lobe (N), the dilation's reads of six neighbours' normals (vec4) and
// its write, and the gather's read of the cell's normal; with release, a second standard transfer
// (the free light) and the release: the cell's attached and free light read and written, and the
// seven normals it compares. The tiled gathers read each source cell once and their tiles' halos
// again (tiled_walk.h).
KernelWork directedGlWork(const DirectedGlSettings& settings);

class DirectedGlKernel {
public:
  DirectedGlKernel() = default;
  // Compiles the kernels and allocates the scratch grids for grids of `resolution`.
  DirectedGlKernel(ShaderCompiler& shaders, const DirectedGlSettings& settings,
                   const glm::ivec3& resolution);

  // `iterations` steps of `current` into `accumulated`, reprojected about the dilated `normals`
  // (the injected normal grid: vec4 per cell, flux-weighted normal and flux; left untouched),
  // attenuated by `gv` (when the settings have one) from firstOccludedIteration on.
  void propagate(const glm::ivec3& resolution, int iterations, DualBuffer& current,
                 DualBuffer& accumulated, const gl::Buffer& normals, const gl::Buffer* gv,
                 int firstOccludedIteration);

  std::size_t memoryBytes() const;

private:
  // directed_release.comp over `current` (the attached light) and the free light (free_[0]).
  void releaseLight(const glm::ivec3& resolution, DualBuffer& current, const gl::Buffer& normals,
                    bool all);

  DirectedGlSettings settings_;
  glm::ivec2 tile_{1, 1};     // the tiled gather's work group (x, y)
  Program gather_, dilate_, release_;
  StandardGlKernel free_;     // the free light's standard gathering
  DualBuffer scratch_;        // swapped with the grid's current buffer
  DualBuffer freeLight_[2];   // with release: the free light and its ping-pong partner
  gl::Buffer normals_[2];     // dilation ping-pong
};

}  // namespace lpvlab

#pragma once
// The GL kernels of tetrahedral propagation and how they are dispatched: the split of the cubic
// grid onto the lattice (shaders/propagation/tetrahedral_split.comp), the lattice's gather steps
// (tetrahedral_gather.comp) and the merge back (tetrahedral_merge.comp). The strategy
// (tetrahedral.cpp) and lpvlab-gpubench (tetrahedral_gpubench.cpp) both run them through this
// class. Also their work model.

#include <glm/glm.hpp>

#include "framework/gl/dual_buffer.h"
#include "framework/gl/resources.h"
#include "framework/gl/shader_compiler.h"
#include "variants/propagation/standard_gl.h"

namespace lpvlab {

constexpr int kTetrahedralCellsPerCube = 12;

struct TetrahedralGlSettings {
  int coefficients = 4;        // per channel: (SH order + 1)^2
  bool withGv = false;         // a GV is bound (the gather is compiled with its reads)
  bool faceIntegrals = true;   // face_flux = "integral" (else "centre")
};

// The GL kernels' work (docs/variants/tetrahedral.md), with N coefficients per channel and 3
// channels. `step`: per cube and step, for its 12 lattice cells: each reads its four neighbours'
// 3N floats, writes its 3N and adds them to the sum (read and written); per far face (12 per cell)
// and channel N multiply-adds of the weights and N of the lobe (the lobe's and, with "centre",
// the basis's evaluations per face not counted); the GV reads 8 corners (vec4) per crossing and
// interpolates 8 x 4. `frame`: per cube and frame, the split (24 cell values of 3N from two
// cubes) and the merge (24 cells' two grids into one cube's), 2 multiply-adds each.
struct TetrahedralGlWork {
  KernelWork step, frame;
};
TetrahedralGlWork tetrahedralGlWork(const TetrahedralGlSettings& settings);

class TetrahedralGlKernel {
public:
  TetrahedralGlKernel() = default;
  // Compiles the three kernels and allocates the lattice for grids of `resolution`.
  TetrahedralGlKernel(ShaderCompiler& shaders, const TetrahedralGlSettings& settings,
                      const glm::ivec3& resolution);

  // Split `current` onto the lattice, `iterations` steps (the GV, when `gv` is given, from the
  // step at which light has crossed firstOccludedIteration cubes on), merge: the last step
  // becomes `current`, the sum of the steps is added to `accumulated`.
  void propagate(const glm::ivec3& resolution, int iterations, DualBuffer& current,
                 DualBuffer& accumulated, const gl::Buffer* gv, int firstOccludedIteration);

  std::size_t memoryBytes() const;

private:
  TetrahedralGlSettings settings_;
  Program split_, gather_, merge_;
  gl::Buffer current_, scratch_, sum_, faceIntegralTable_;
};

}  // namespace lpvlab

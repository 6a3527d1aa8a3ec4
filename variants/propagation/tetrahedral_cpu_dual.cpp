// What the geometry volume does to the tetrahedral lattice's faces, on dual numbers: the GV's
// derivatives (with respect to its blocking_scale, say) carried into the transmittances
// (tetrahedral_occlusion_body.h, the text tetrahedral_cpu.cpp compiles in double precision).
#include "variants/propagation/dual_gv_lookup.h"

#include <vector>

#include "variants/propagation/tetrahedral_cpu.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

#include "variants/propagation/tetrahedral_occlusion_body.h"

template TetrahedralOcclusion<Dual> makeTetrahedralOcclusion<Dual, Dual>(
    const TetrahedralLattice<Dual>&, const Dual*);

}  // namespace lpvlab

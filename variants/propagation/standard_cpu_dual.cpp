// What the geometry volume does to standard propagation's faces, on dual numbers: the GV's
// derivatives (with respect to its blocking_scale, say) carried into the transmittances and
// bounces (standard_occlusion_body.h, the text standard_cpu.cpp compiles in double precision).
#include "variants/propagation/dual_gv_lookup.h"

#include <vector>

#include "variants/propagation/standard_cpu.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/standard_faces.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

#include "variants/propagation/standard_occlusion_body.h"

template StandardOcclusion<Dual> makeStandardOcclusion<Dual, Dual>(const StandardFaceTable<Dual>&,
                                                                   const glm::ivec3&, const Dual*,
                                                                   const Dual*);

}  // namespace lpvlab

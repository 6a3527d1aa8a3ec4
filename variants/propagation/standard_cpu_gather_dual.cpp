// Standard propagation's CPU kernel on dual numbers (standard_cpu_kernels.h): the frames whose
// derivatives a fit asks for (framework/math/dual.h).
#include "variants/propagation/standard_cpu_kernels.h"

namespace lpvlab {

// Derivatives (framework/math/dual.h): gathering only, which gives scattering's grid too.
template void standardGatherCpu<Dual>(const StandardFaceTable<Dual>&, const glm::ivec3&,
                                      const Dual*, Dual*, Dual*, const std::string&, int,
                                      const StandardOcclusion<Dual>*, StepAccumulation,
                                      const ReprojectedCells<Dual>*, int);

}  // namespace lpvlab

// Standard propagation's CPU kernel in double precision: the tests' reference (standard_cpu_kernels.h).
#include "variants/propagation/standard_cpu_kernels.h"

namespace lpvlab {

template void standardScatterCpu<double>(const StandardFaceTable<double>&, const glm::ivec3&,
                                         const double*, double*, double*, const std::string&, int,
                                         const StandardOcclusion<double>*, StepAccumulation);
template void standardGatherCpu<double>(const StandardFaceTable<double>&, const glm::ivec3&,
                                        const double*, double*, double*, const std::string&, int,
                                        const StandardOcclusion<double>*, StepAccumulation,
                                        const ReprojectedCells<double>*, int);

}  // namespace lpvlab

// Standard propagation's row kernels on dual numbers for SH order 1 (4 coefficients), on every
// instruction set: one of three translation units (standard_cpu_kernels.h says why).
#include "variants/propagation/standard_cpu_kernels.h"

namespace lpvlab {

RowsFunction<Dual> standardDualRows4(const std::string& isa) { return rowsFor<4, Dual>(isa); }

}  // namespace lpvlab

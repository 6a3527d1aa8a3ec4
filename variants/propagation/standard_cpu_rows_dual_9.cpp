// Standard propagation's row kernels on dual numbers for SH order 2 (9 coefficients), on every
// instruction set: one of three translation units (standard_cpu_kernels.h says why).
#include "variants/propagation/standard_cpu_kernels.h"

namespace lpvlab {

RowsFunction<Dual> standardDualRows9(const std::string& isa) { return rowsFor<9, Dual>(isa); }

}  // namespace lpvlab

#pragma once
// The work of one cell-iteration of the standard transfer's CPU kernels (WorkCount, strategy.h),
// for the strategies built on it (standard, directed); the GL kernels' is standard_gl.h's.
//
// With N coefficients per channel and 3 channels. Reads: the six neighbours' 3N floats; writes:
// the cell's 3N; the accumulated grid's 3N read and written. The CPU kernel sums fluxes per face
// normal and skips the SH terms that vanish on axis-aligned faces (standardGatherMultiplyAdds: 96
// of 30 x 4 + 6 x 4 at order 1; scattering adds the lobes in each of its six passes, six
// read-modify-write passes: 6 x 3N instead of 3N writes). With the GV it reads each face's
// transmittance, found once per frame, and multiplies by it.

#include "framework/pipeline/kernel_work.h"
#include "variants/propagation/standard_cpu.h"

namespace lpvlab {

inline KernelWork standardCpuTransferWork(int coefficients, bool scatter, bool withGv) {
  KernelWork w;
  w.multiplyAdds = 3.0 * (scatter ? standardScatterMultiplyAdds(coefficients)
                                  : standardGatherMultiplyAdds(coefficients));
  w.bytes = 4.0 * coefficients * (6 * 3 + (scatter ? 2 * 6 * 3 : 3) + 2 * 3);
  if (withGv) {
    w.multiplyAdds += 3 * 30;
    w.bytes += 30 * 4;
  }
  return w;
}

}  // namespace lpvlab

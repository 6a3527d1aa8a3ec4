#pragma once
// The work of one cell-iteration of the standard transfer (WorkCount, strategy.h), for the
// strategies built on it (standard, directed), on either backend.
//
// With N coefficients per channel and 3 channels. Reads: the six neighbours' 3N floats; writes:
// the cell's 3N; the accumulated grid's 3N read and written. Transfers: the CPU kernel sums
// fluxes per face normal and skips the SH terms that vanish on axis-aligned faces
// (standardGatherMultiplyAdds: 96 of 30 x 4 + 6 x 4 at order 1; scattering adds the lobes in each
// of its six passes); the GL kernels do 30 faces x 2N per channel (their SH evaluations per face
// not counted). Scattering adds into its 6 neighbours (atomically on GL; in six
// read-modify-write passes on the CPU): 6 x 3N read-modify-writes instead of 3N writes. The GV
// reads its 8 corners (vec4) per cell and interpolates 8 x 4 per face on GL; the CPU reads each
// face's transmittance, found once per frame, and multiplies by it.

#include "framework/pipeline/strategy.h"
#include "variants/propagation/standard_cpu.h"
#include "variants/propagation/standard_gl.h"

namespace lpvlab {

// On GL, the kernels' count (standard_gl.h); on the CPU, the CPU kernels'.
inline KernelWork standardTransferWork(int coefficients, bool onCpu, bool scatter,
                                                 bool withGv) {
  if (!onCpu) return standardGlTransferWork(coefficients, scatter, withGv);
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

#pragma once
// Exact face fluxes of tetrahedral propagation (docs/variants/tetrahedral.md#tetrahedral, "Face flux"):
// the integral of every real SH basis function Y_i (orders up to 3, i < 16) over each far face of
// a lattice cell, seen from the centroid of the neighbour it receives from:
//     M[code][j][k][i] = integral over the spherical triangle of face k of cell `code`, seen from
//                        the centroid of its neighbour across face j, of Y_i(w) dw      (k != j)
// A neighbour's intensity I(w) = sum_i c_i Y_i(w) then sends exactly sum_i c_i M[..][i] (W)
// through face k, and because the 12 far faces of a cell's four neighbours tile the sphere, the
// 12 fluxes sum to the whole integral of I: a step conserves flux for every SH function, not only
// for an isotropic one as the point-sampled Omega_k I(w_k) does.
//
// Layout: index shared::tetFaceIntegralIndex(code, j, k, i) (tetrahedral_lattice.glsl), entries
// with k == j are 0; TET_FACE_INTEGRAL_COUNT doubles in all.
//
// Quadrature: the planar face is split into 4^5 similar triangles, each integrated with
// Radon's 7-point rule (exact for polynomials of degree 5 on the plane) of Y_i(x/|x|) d/|x|^3,
// d the plane's distance from the viewpoint (dw = d/|x|^3 dA): a smooth integrand, absolute
// error about 1e-11 per face, far below the float32 kernels' rounding
// (tests/math/tetrahedral_face_integrals_test.cpp checks band 0 against the exact solid angle,
// band 1 against Arvo's closed form, bands 2-3 against a direct sum over the sphere).

#include <vector>

namespace lpvlab {

// Computed once per process (a few milliseconds), then returned by reference.
const std::vector<double>& tetrahedralFaceIntegrals();

}  // namespace lpvlab

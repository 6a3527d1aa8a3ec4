// Trilinear interpolation between the 8 cell centres around a point, and the directional
// derivative of the interpolant, shared by the rendering kernels and the C++ tests.
//
// A point at grid coordinates g lies between the cell centres base + 0.5 and base + 1.5 per axis,
// base = floor(g - 0.5), at fraction f = g - 0.5 - base. Corner o (each component 0 or 1) gets
//   w_o(f) = prod_a (o_a ? f_a : 1 - f_a),
// and the interpolant is F(g) = sum_o w_o(f) F_o. Its derivative along a unit direction d, per
// cell (grid units), is sum_o (grad_f w_o . d) F_o with
//   d w_o / d f_a = (o_a ? 1 : -1) prod_{b != a} (o_b ? f_b : 1 - f_b),
// so a kernel gets the value and the slope from the same 8 reads. Corners clamped at the grid's
// edge repeat a cell; their weights' slopes cancel, so the slope is 0 across the clamped edge,
// as it is for the clamped interpolant.
#ifndef LPVLAB_TRILINEAR_WEIGHTS_GLSL
#define LPVLAB_TRILINEAR_WEIGHTS_GLSL
#include "../common/prelude.glsl"

real trilinearAxisWeight(int o, real f) {
  return o == 1 ? f : real(1.0) - f;
}

real trilinearAxisSign(int o) {
  return o == 1 ? real(1.0) : real(-1.0);
}

real trilinearWeight(ivec3 o, vec3 f) {
  return trilinearAxisWeight(o.x, f.x) * trilinearAxisWeight(o.y, f.y) *
         trilinearAxisWeight(o.z, f.z);
}

// The derivative of trilinearWeight(o, f) along the unit direction d, per cell.
real trilinearWeightSlope(ivec3 o, vec3 f, vec3 d) {
  real wx = trilinearAxisWeight(o.x, f.x);
  real wy = trilinearAxisWeight(o.y, f.y);
  real wz = trilinearAxisWeight(o.z, f.z);
  return trilinearAxisSign(o.x) * wy * wz * d.x + wx * trilinearAxisSign(o.y) * wz * d.y +
         wx * wy * trilinearAxisSign(o.z) * d.z;
}

#endif

// Directed propagation (thesis 5.2, 6.9.4, alg. 6.3), shared by the GLSL kernels and the
// double-precision C++ reference. SH orders 1-3.
//
// Normal dilation: injection stores per cell the flux-weighted sum of its VPLs' normals (xyz) and
// their flux (w). Before every iteration a cell whose xyz is zero takes the normalised mean of its
// six face neighbours' unit normals (if it is still zero, e.g. opposite normals cancel, it has
// none); cells that have a normal keep it. So normals spread one cell per iteration, as light
// does, and every cell light reaches has a direction to prefer.
//
// Second reprojection (alg. 6.3), at SH order L (any of 1-3: `coefficients` = (L + 1)^2): the
// light that face f passes into the receiving cell, the lobe L_f = Phi_f / pi * cosLobe_L(n_f) of
// the standard transfer (standard_faces.glsl), is evaluated in the receiving cell's dilated
// normal n_d, clamped, and re-emitted as a cosine lobe about n_d:
//     L'_f = G(n_d) * max(0, L_f(n_d)) * cosLobe_L(n_d)
// By the addition theorem an order-L cosine lobe about a, evaluated at b, is
//     l_L(a . b) = sum_k cosLobe_k(a) Y_k(b) = sum_{l <= L} z_l sqrt((2l + 1) / (4 pi)) P_l(a . b)
//     l_1(t) = 1/4 + t/2,   l_2(t) = l_3(t) = 1/4 + t/2 + 5/16 P_2(t),   P_2(t) = (3t^2 - 1)/2
// (z_3 = 0: band 3 of the clamped cosine vanishes, so orders 2 and 3 reproject alike), and a lobe
// a * cosLobe_L(n) holds the flux pi * a at every order (only Y00 integrates), so face f's flux
// becomes
//     Phi'_f = G(n_d) * Phi_f * max(0, l_L(n_f . n_d)).
// Without G the reprojection does not conserve flux: at order 1 it keeps 3/4 of a face looking
// along n_d, 1/4 of one across it and nothing of one against it; at orders 2-3, 17/16, 3/32 and
// 1/16: the order-2 projection of the clamped cosine rings (l_2(-1) = 1/16 > 0), so a little of
// the light against the normal is kept, re-emitted along n_d but one cell behind. Summed
// over the 30 faces, a cell holding a unit-flux lobe about n (as every reprojected cell does),
// whose intensity towards face f is l_L(w_f . n) / pi, keeps only r_L(n) of its flux per step:
//     r_L(n) = sum_f Omega_f / pi * max(0, l_L(w_f . n)) * max(0, l_L(n_f . n))
// (r_1 = 0.4565, r_2 = r_3 = 0.4413 for an axis normal), so after 32 iterations almost nothing would be
// left, and the method would mainly darken. lpvlab renormalises with G(n) = 1 / r_L(n): where the
// normals agree, light travelling along them is propagated with its flux conserved, as in
// standard propagation, and what the reprojection removes from faces against the normal goes to
// faces along it. The back-propagation is removed; the light is redirected, not lost. (Where
// neighbouring normals differ, or a cell holds light that is not a lobe about its normal, the
// step is not exactly conserving; see docs/variants/directed.md#directed.)
// A cell without a normal (none reached it, or a normal-less injection such as sky light) gets
// the standard transfer unchanged.
#ifndef LPVLAB_DIRECTED_FACES_GLSL
#define LPVLAB_DIRECTED_FACES_GLSL
#include "standard_faces.glsl"

// The stored normals are flux-weighted sums, as small or large as the light: at a light of 1e-30
// their squares underflow float (so dot(n, n) > 0 and normalize() would call a lit cell
// normal-less, or divide by zero), at 1e12 they could overflow. Tests and normalisation therefore
// never square the raw sum: it is first scaled by its largest component.
bool directedHasNormal(vec4 stored) {
  return stored.x != 0.0 || stored.y != 0.0 || stored.z != 0.0;
}

// v / |v| for a non-zero v of any magnitude float holds.
vec3 directedDirection(vec3 v) {
  real largest = max(abs(v.x), max(abs(v.y), abs(v.z)));
  return normalize(v / largest);
}

// A cell's unit normal (its contribution to a normal-less neighbour's mean), or zero.
vec3 directedUnitNormal(vec4 stored) {
  if (!directedHasNormal(stored)) return vec3(0.0);
  return directedDirection(vec3(stored.x, stored.y, stored.z));
}

// The dilated value of a cell: its own if it has a normal, else the normalised sum of its
// neighbours' unit normals (w = 0 marks it as dilated), or nothing.
vec4 directedDilated(vec4 own, vec3 neighbourUnitNormalSum) {
  if (directedHasNormal(own)) return own;
  if (!directedHasNormal(vec4(neighbourUnitNormalSum, 0.0))) return vec4(0.0);
  vec3 n = directedDirection(neighbourUnitNormalSum);
  return vec4(n.x, n.y, n.z, 0.0);
}

// Release of the light from its surface's region (directed.cpp's `release`). Alg. 6.3 read
// literally reprojects everything a cell receives about the cell's dilated normal. Dilation fills
// the space between the surfaces with the normal of the nearest one, so every cell next to a lit
// surface re-emits only light leaving that surface: light arriving from other surfaces is turned
// back before it reaches it, and a scene whose every surface sends VPLs (a closed room under a
// point light) is left almost black (issue 42; docs/variants/directed.md#directed). With release, the
// light is kept in two grids: "attached" light, still in the region of cells whose normals agree
// with the surface it left, is reprojected as alg. 6.3 says; where the normal field changes (a
// neighbour's normal differs by more than the region angle, or the cell has no normal) a cell
// releases its attached light into the "free" grid, which propagates as standard propagation
// does. So a surface receives none of its own light while that light stays in its region (the
// physics agrees: two surfaces of one normal exchange no light), and every other surface's.

// Whether two stored normals belong to one region: both have a normal, within the region angle
// (its cosine given).
bool directedSameRegion(vec4 a, vec4 b, real cosRegionAngle) {
  if (!directedHasNormal(a) || !directedHasNormal(b)) return false;
  return dot(directedUnitNormal(a), directedUnitNormal(b)) >= cosRegionAngle;
}

// Whether a neighbour makes a cell (normal `own`) release its attached light: it has a normal of
// another region. (A neighbour without a normal does not: light passing into it gets the
// standard transfer there, and the neighbour releases it the step after.)
bool directedNeighbourReleases(vec4 own, vec4 neighbour, real cosRegionAngle) {
  return directedHasNormal(neighbour) && !directedSameRegion(own, neighbour, cosRegionAngle);
}

// l_L(a . b): the order-L clamped cosine lobe about unit a, evaluated at unit b, by the
// addition theorem (Legendre polynomials of a . b: a few flops instead of 2 (L + 1)^2 basis
// functions; the tests check it against sum_k cosLobe_k(a) Y_k(b)).
real directedLobeValue(vec3 a, vec3 b, int coefficients) {
  real t = dot(a, b);
  int order = shBand(coefficients - 1);
  real sum = shZonalCosine(0) * sqrt(1.0 / (4.0 * PI));
  if (order >= 1) sum += shZonalCosine(1) * sqrt(3.0 / (4.0 * PI)) * t;
  if (order >= 2) sum += shZonalCosine(2) * sqrt(5.0 / (4.0 * PI)) * 0.5 * (3.0 * t * t - 1.0);
  if (order >= 3) sum += shZonalCosine(3) * sqrt(7.0 / (4.0 * PI)) * 0.5 * t * (5.0 * t * t - 3.0);
  return sum;
}

// Alg. 6.3 lines 2-5 for one face: the light face f (normal n_f) passes, Phi_f / pi *
// cosLobe(n_f), reprojected about the unit normal n with gain G, is
//     Phi_f * directedReprojection(n_f, n, G, coefficients) * cosLobe(n)
// (Phi_f >= 0, so the clamp acts on l_L alone).
real directedReprojection(vec3 faceNormal, vec3 n, real gain, int coefficients) {
  return gain * max(0.0, directedLobeValue(faceNormal, n, coefficients)) / PI;
}

// The unit axis number `axis` (0..5: +x, -x, +y, -y, +z, -z).
vec3 directedAxis(int axis) {
  real s = (axis % 2 == 0) ? 1.0 : -1.0;
  if (axis < 2) return vec3(s, 0.0, 0.0);
  if (axis < 4) return vec3(0.0, s, 0.0);
  return vec3(0.0, 0.0, s);
}

// G(n) = 1 / r_L(n): r_L(n) is what one unnormalised directed step keeps of a unit-flux lobe
// about n when every receiving cell's normal is n. Once per receiving cell.
real directedGain(vec3 n, real farSolidAngle, real sideSolidAngle, int coefficients) {
  real kept = 0.0;
  for (int axis = 0; axis < 6; ++axis) {
    vec3 d = directedAxis(axis);
    for (int f = 0; f < STANDARD_FACES; ++f) {
      real solidAngle = standardFaceSolidAngle(f, farSolidAngle, sideSolidAngle);
      real intensity = directedLobeValue(n, standardFaceDirection(d, f), coefficients) / PI;
      kept += standardFaceFlux(intensity, solidAngle, 1.0) *
              max(0.0, directedLobeValue(standardFaceNormal(d, f), n, coefficients));
    }
  }
  return 1.0 / kept;
}

// A stored normal's gain: G(n), or 0 without a normal (the cell gets the standard transfer).
real directedGainOf(vec4 stored, real farSolidAngle, real sideSolidAngle, int coefficients) {
  if (!directedHasNormal(stored)) return 0.0;
  return directedGain(directedUnitNormal(stored), farSolidAngle, sideSolidAngle, coefficients);
}

#endif

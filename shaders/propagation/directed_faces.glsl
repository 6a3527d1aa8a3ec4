// Directed propagation (thesis 5.2, 6.9.4, alg. 6.3), shared by the GLSL kernels and the
// double-precision C++ reference. Order 1 only.
//
// Normal dilation: injection stores per cell the flux-weighted sum of its VPLs' normals (xyz) and
// their flux (w). Before every iteration a cell whose xyz is zero takes the normalised mean of its
// six face neighbours' unit normals (if it is still zero, e.g. opposite normals cancel, it has
// none); cells that have a normal keep it. So normals spread one cell per iteration, as light
// does, and every cell light reaches has a direction to prefer.
//
// Second reprojection (alg. 6.3): the light that face f passes into the receiving cell, the lobe
// L_f = Phi_f / pi * cosLobe(n_f) of the standard transfer (standard_faces.glsl), is evaluated in
// the receiving cell's dilated normal n_d, clamped, and re-emitted as a cosine lobe about n_d:
//     L'_f = G(n_d) * max(0, L_f(n_d)) * cosLobe(n_d)
// With order-1 SH, L_f(n_d) = Phi_f / pi * (1/4 + (n_f . n_d) / 2) and a lobe a * cosLobe(n)
// holds the flux pi * a, so face f's flux becomes
//     Phi'_f = G(n_d) * Phi_f * max(0, 1/4 + (n_f . n_d) / 2).
// Without G the reprojection does not conserve flux: it keeps 3/4 of a face looking along n_d,
// 1/4 of one across it and nothing of one against it. Summed over the 30 faces, a cell holding a
// lobe about n (as every reprojected cell does) keeps only r(n) of its flux per step, with
//     r(n) = sum_f Omega_f / pi * max(0, 1/4 + (w_f . n) / 2) * max(0, 1/4 + (n_f . n) / 2)
// (r = 0.456 for an axis normal), so after 32 iterations almost nothing would be left, and the
// method would mainly darken. lpvlab renormalises with G(n) = 1 / r(n): where the normals agree,
// light travelling along them is propagated with its flux conserved, as in standard propagation,
// and what the reprojection removes from faces against the normal goes to faces along it. The
// back-propagation is removed; the light is redirected, not lost. (Where neighbouring normals
// differ, or a cell holds light that is not a lobe about its normal, the step is not exactly
// conserving; see docs/variants.md#directed.)
// A cell without a normal (none reached it, or a normal-less injection such as sky light) gets
// the standard transfer unchanged.
#ifndef LPVLAB_DIRECTED_FACES_GLSL
#define LPVLAB_DIRECTED_FACES_GLSL
#include "standard_faces.glsl"

bool directedHasNormal(vec4 stored) {
  return dot(vec3(stored.x, stored.y, stored.z), vec3(stored.x, stored.y, stored.z)) > 0.0;
}

// A cell's unit normal (its contribution to a normal-less neighbour's mean), or zero.
vec3 directedUnitNormal(vec4 stored) {
  if (!directedHasNormal(stored)) return vec3(0.0);
  return normalize(vec3(stored.x, stored.y, stored.z));
}

// The dilated value of a cell: its own if it has a normal, else the normalised sum of its
// neighbours' unit normals (w = 0 marks it as dilated), or nothing.
vec4 directedDilated(vec4 own, vec3 neighbourUnitNormalSum) {
  if (directedHasNormal(own)) return own;
  if (dot(neighbourUnitNormalSum, neighbourUnitNormalSum) <= 0.0) return vec4(0.0);
  vec3 n = normalize(neighbourUnitNormalSum);
  return vec4(n.x, n.y, n.z, 0.0);
}

// Alg. 6.3 lines 2-5 without the gain: transferred light `c` re-emitted about the unit normal n.
vec4 directedReprojectUnnormalised(vec4 c, vec3 n) {
  return max(0.0, shEvaluate(c, n)) * shCosineLobe(n);
}

// The unit axis number `axis` (0..5: +x, -x, +y, -y, +z, -z).
vec3 directedAxis(int axis) {
  real s = (axis % 2 == 0) ? 1.0 : -1.0;
  if (axis < 2) return vec3(s, 0.0, 0.0);
  if (axis < 4) return vec3(0.0, s, 0.0);
  return vec3(0.0, 0.0, s);
}

// G(n) = 1 / r(n): r(n) is what one unnormalised directed step keeps of a unit-flux lobe about n
// when every receiving cell's normal is n. Once per receiving cell.
real directedGain(vec3 n, real farSolidAngle, real sideSolidAngle) {
  vec4 lobe = shCosineLobe(n) / PI;
  real kept = 0.0;
  for (int axis = 0; axis < 6; ++axis) {
    vec3 d = directedAxis(axis);
    for (int f = 0; f < STANDARD_FACES; ++f) {
      vec4 transferred =
          propagateThroughFace(lobe, standardFaceDirection(d, f), standardFaceNormal(d, f),
                               standardFaceSolidAngle(f, farSolidAngle, sideSolidAngle));
      kept += shIntegral(directedReprojectUnnormalised(transferred, n));
    }
  }
  return 1.0 / kept;
}

// The standard transfer through one face (whose crossing lets `transmittance` of the light
// through: 1 without a GV) followed by the second reprojection about the receiving cell's unit
// normal n with gain G(n) (`gain`; 0 for a cell without a normal, which gets the standard
// transfer). The transmittance is a non-negative factor, so it commutes with the clamp.
vec4 directedThroughFace(vec4 c, vec3 toFaceCentre, vec3 faceNormal, real solidAngle,
                         real transmittance, vec3 n, real gain) {
  vec4 transferred =
      propagateThroughOccludedFace(c, toFaceCentre, faceNormal, solidAngle, transmittance);
  if (gain == 0.0) return transferred;
  return gain * directedReprojectUnnormalised(transferred, n);
}

// Its gain: G(n), or 0 without a normal.
real directedGainOf(vec4 stored, real farSolidAngle, real sideSolidAngle) {
  if (!directedHasNormal(stored)) return 0.0;
  return directedGain(directedUnitNormal(stored), farSolidAngle, sideSolidAngle);
}

#endif

// Standard LPV propagation between two face-adjacent cubic cells (thesis eq. 4.5-4.9, alg. 6.2),
// shared by the GLSL kernels and the double-precision C++ reference.
//
// Normalisation (lpvlab's, stated because the thesis and public code differ): a cell's
// coefficients are the radiant intensity I(w) (W/sr) of the light passing through it, as if
// emitted from its centre. The flux that reaches face f of the neighbour is
//     Phi_f = Omega_f * max(0, I(w_f))                                            [W]
// with Omega_f the face's solid angle seen from the source centre and w_f the direction to the
// face centre. The face re-emits Phi_f into the neighbour as a Lambertian emitter with normal n_f:
//     I_f(w) = Phi_f / pi * max(0, n_f . w)   ->   coefficients  Phi_f / pi * shCosineLobe(n_f)
// which integrates back to Phi_f, so the only losses are the SH's own approximation and the
// clamp. (Thesis eq. 4.9 writes Omega_f / (4 pi): that factor would remove 3/4 of the light at
// every step; Kaplanyan and Dachsbacher's Omega_f / pi is what conserves flux.) The 30 faces of
// the 6 neighbours tile the sphere, so a cell's whole flux leaves it each iteration.
// The same transfer holds at every SH order: only the number of coefficients changes.
//
// With the geometry volume (thesis 4.4, fig. 4.3, alg. 6.2 lines 11-14) the face's flux is
// multiplied by the transmittance T = gvTransmittance(B, w_f) of the blocking potential B read
// where w_f, leaving the source centre, crosses the face the two cells share:
//     Phi_f = T * Omega_f * max(0, I(w_f))
// (shaders/common/geometry_volume.glsl). Gather and scatter kernels both call
// shaders/propagation/standard_transfer.glsl, which calls the functions below.
#ifndef LPVLAB_STANDARD_FACES_GLSL
#define LPVLAB_STANDARD_FACES_GLSL
#include "../common/sh.glsl"
#include "../common/geometry_volume.glsl"

const int STANDARD_FACES = 5;  // faces of the neighbour that receive light: all but the shared one

// The neighbour one cell along the unit axis `d` receives light through its far face (f = 0:
// normal d, centre at 1.5 d) and its four side faces (f = 1..4: normal +-s, centre at d + s / 2).
vec3 standardFaceNormal(vec3 d, int f) {
  vec3 s1 = vec3(abs(d.y) + abs(d.z), abs(d.x), 0.0);
  vec3 s2 = cross(d, s1);
  if (f == 0) return d;
  if (f == 1) return s1;
  if (f == 2) return -s1;
  if (f == 3) return s2;
  return -s2;
}

// Unit direction from the source cell's centre to the centre of face f.
vec3 standardFaceDirection(vec3 d, int f) {
  if (f == 0) return d;
  return normalize(d + 0.5 * standardFaceNormal(d, f));
}

real standardFaceSolidAngle(int f, real farSolidAngle, real sideSolidAngle) {
  return f == 0 ? farSolidAngle : sideSolidAngle;
}

// Where the direction to face f, from the source centre `sourceCentre` (light-grid coordinates),
// crosses the face shared with the neighbour along d: where the GV is read.
vec3 standardFaceCrossing(vec3 sourceCentre, vec3 d, int f) {
  return sharedFaceCrossing(sourceCentre, d, standardFaceDirection(d, f));
}

// The flux (W) through one face: the source's intensity towards the face centre, clamped, times
// the face's solid angle and the transmittance of the GV there (1 without a GV).
real standardFaceFlux(real intensity, real solidAngle, real transmittance) {
  return transmittance * solidAngle * max(0.0, intensity);
}

// Order 1: coefficients added to the target by the source's coefficients `c` through one face
// whose crossing point lets `transmittance` of the light through.
vec4 propagateThroughOccludedFace(vec4 c, vec3 toFaceCentre, vec3 faceNormal, real solidAngle,
                                  real transmittance) {
  real flux = standardFaceFlux(shEvaluate(c, toFaceCentre), solidAngle, transmittance);
  return (flux / PI) * shCosineLobe(faceNormal);
}

// Order 1, without a GV.
vec4 propagateThroughFace(vec4 c, vec3 toFaceCentre, vec3 faceNormal, real solidAngle) {
  return propagateThroughOccludedFace(c, toFaceCentre, faceNormal, solidAngle, 1.0);
}

// Order 1: what the source cell `c` sends into its neighbour one cell along `d`.
vec4 propagateToNeighbour(vec4 c, vec3 d, real farSolidAngle, real sideSolidAngle) {
  vec4 sum = vec4(0.0);
  for (int f = 0; f < STANDARD_FACES; ++f)
    sum += propagateThroughFace(c, standardFaceDirection(d, f), standardFaceNormal(d, f),
                                standardFaceSolidAngle(f, farSolidAngle, sideSolidAngle));
  return sum;
}

#endif

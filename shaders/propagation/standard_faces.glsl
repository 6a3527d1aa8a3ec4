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

// ---- multiple bounces (standard.cpp's `bounces`) ------------------------------------------------
// The light a face crossing blocks, Phi_b = (1 - T) Omega_f max(0, I(w_f)), has hit the GV's
// surfaces there. Lambertian surfaces of albedo rho re-emit rho Phi_b as a clamped cosine lobe
// about their normal n, into the cell the light came from (it never left it):
//     I_b(w) = rho Phi_b / pi * max(0, n . w)   ->   coefficients  rho Phi_b / pi * shCosineLobe(n)
// whose integral is rho Phi_b, so with rho <= 1 a face never sends on more than Phi_f in all.

// The blocked flux (W) of one face: standardFaceFlux with the fraction the GV stops.
real standardBlockedFlux(real intensity, real solidAngle, real transmittance) {
  return standardFaceFlux(intensity, solidAngle, 1.0 - transmittance);
}

// Below this |band 1| / |c0| the blocking potential has no usable direction (opposite surfels
// cancelled, or isotropic blocking): a single surfel has 2 / sqrt(3).
const real GV_NORMAL_MIN_BAND1 = 1e-4;

// The normal of the surfaces behind blocking potential b, on the side that light travelling in w
// arrives at. A surfel adds A / s^2 cosLobe(-n) (shaders/common/geometry_volume.glsl), whose
// band-1 coefficients (c1, c2, c3) are proportional to (n.y, -n.z, n.x) (sh.glsl's basis), so
// n ~ (c3, c1, -c2). The light was blocked, so it arrived at the surface's lit side: a normal
// facing along w (interpolation across surfels of mixed orientation, or light blocked at grazing
// incidence from behind by the order-1 lobe's tail) is turned round, and without a usable
// direction the surface is taken to face the light, n = -w.
vec3 gvSurfaceNormal(vec4 b, vec3 w) {
  vec3 v = vec3(b.w, b.y, -b.z);
  real band1 = length(v);
  if (!(band1 > GV_NORMAL_MIN_BAND1 * abs(b.x))) return -w;
  vec3 n = v / band1;
  return dot(n, w) > 0.0 ? -n : n;
}

// The mean albedo of the GV's surfels from their (sum rho A, sum A) (geometry_volume.h's albedo
// layout, interpolated like the blocking potential); 0 where no surfel with an albedo was seen.
// Clamped to [0, 1] so that re-emission never adds energy, whatever the rounding.
vec3 gvMeanAlbedo(vec4 weighted) {
  if (!(weighted.w > 0.0)) return vec3(0.0);
  return clamp(vec3(weighted.x, weighted.y, weighted.z) / weighted.w, 0.0, 1.0);
}

// Order 1: coefficients re-emitted into the source cell `c` by the surfaces (normal n, one
// channel's albedo rho) at the crossing of the face towards `toFaceCentre`.
vec4 bounceAtFace(vec4 c, vec3 toFaceCentre, real solidAngle, real transmittance, vec3 n, real rho) {
  real blocked = standardBlockedFlux(shEvaluate(c, toFaceCentre), solidAngle, transmittance);
  return (rho * blocked / PI) * shCosineLobe(n);
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

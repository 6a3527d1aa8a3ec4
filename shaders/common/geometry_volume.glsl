// The geometry volume's side of propagation, shared by the GLSL kernels and C++
// (variants/resources/geometry_volume.h describes the buffers).
//
// Blocking potential (thesis eq. 4.4): a surfel of area A_s whose normal n faces the viewer that
// saw it (the light of an RSM, or the camera) stops, of the light travelling in direction w,
//     B(w) = A_s / s^2 * max(0, -n . w)      (s: the cell's edge)
// i.e. light arriving at its visible side; its order-1 coefficients are A_s / s^2 cosLobe(-n).
// (Eq. 4.4 writes <n_s | w>_+ with n_s pointing into the surface; lpvlab's normals point out of
// it, hence the minus.) A cell's surfels add up; the transmitted fraction is 1 - B, clamped to
// [0, 1] because the SH of a sum of lobes can leave that range.
//
// Placement: GV coordinates are light-grid coordinates plus one half (GV cell centres sit on
// light-grid cell corners), so the point where a propagation direction crosses the face shared
// by two light-grid cells lies in the plane of four GV cell centres (the face's corners), and
// trilinear interpolation there is the bilinear interpolation of thesis fig. 4.3.
#ifndef LPVLAB_GEOMETRY_VOLUME_GLSL
#define LPVLAB_GEOMETRY_VOLUME_GLSL
#include "sh.glsl"

vec3 gvFromLightGrid(vec3 g) {
  return g + real(0.5);
}

// Where the ray from the light-grid point `from` in direction `w` crosses the plane `from + 0.5 d`
// (d: the unit axis towards the neighbour; the shared face when `from` is a cell centre).
vec3 sharedFaceCrossing(vec3 from, vec3 d, vec3 w) {
  return from + w * (real(0.5) / dot(w, d));
}

// A surfel's blocking weight A_s / s^2 (area over the cell's face): what its lobe is scaled by, and
// the weight of its albedo in the cell's mean albedo.
real gvSurfelWeight(real area, real cellSize) {
  return area / (cellSize * cellSize);
}

// The order-1 blocking potential one surfel adds to its GV cell: its weight times cosLobe(-n),
// times the occlusion strategy's blocking_scale.
vec4 gvSurfelBlocking(vec3 n, real weight, real blockingScale) {
  return (blockingScale * weight) * shCosineLobe(-n);
}

// Merging two sources' GVs "by the larger coefficients" (thesis 4.3): per GV cell the merged cell
// is the whole cell of the source whose c0, the blocking averaged over directions, is larger; on a
// tie the first source's is kept. Taking one source's cell whole, rather than a per-coefficient
// maximum, keeps B a sum of real surfels' lobes; a sum of both would count a surface seen by both
// views twice.
bool gvMergeTakesOther(real firstC0, real otherC0) {
  return otherC0 > firstC0;
}

// Fraction of light travelling in direction w that passes blocking potential `b`.
real gvTransmittance(vec4 b, vec3 w) {
  return clamp(1.0 - shEvaluate(b, w), 0.0, 1.0);
}

#endif

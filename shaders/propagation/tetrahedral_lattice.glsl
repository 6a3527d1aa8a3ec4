// The tetrahedral lattice of "tetrahedral" propagation, shared by its kernels and the
// double-precision C++ tests (docs/variants/tetrahedral.md#tetrahedral derives everything stated here).
//
// Lattice: the Delaunay cells of the body-centred cubic (BCC) lattice whose points are the light
// grid's cube corners and cube centres (grid units: cube edge 1). Every cell is a congruent
// tetragonal disphenoid. One exists per (cube face, edge of that face): the two centres P, Q of
// the cubes sharing the face and the two ends R+, R- of the edge. Each is addressed by the lower
// of its two cubes and a code = axis * 4 + edge (12 per cube):
//   axis a (0..2): the cubes are `cube` and `cube + A` (A the unit vector of a), so the shared
//                  face has centre F = cube + 0.5 + 0.5 A;
//   edge e (0..3): the face's edge at F + T / 2, T = -U, +U, -V, +V for e = 0..3, where
//                  U, V are the unit vectors of axes (a + 1) % 3, (a + 2) % 3;
//   W:             the unit vector of the face's other axis (positive), along the edge.
// Vertices (i = 0..3): P = F - A/2, Q = F + A/2, R+ = F + T/2 + W/2, R- = F + T/2 - W/2;
// centroid G = F + T/4 (volume 1/12: 12 per cube tile space).
// Face k is opposite vertex k ^ 1 (face 0 opposite Q, 1 opposite P, 2 opposite R-, 3 opposite
// R+); outward unit normals (T - A), (T + A), (W - T), (-W - T), each / sqrt(2); every face is
// sqrt(2)/8 from G and the neighbour across it is the mirror image of the cell in its plane, so
// the neighbour's centroid is G + sqrt(2)/4 n_k. Each face subtends exactly pi from G.
//
// A tetrahedron is passed around as ivec4(cube, code). Its slot in a tetrahedral grid is
// cellIndex(cube) * 12 + code; slots whose second cube lies outside the light grid hold no
// cell (tetInside) and stay zero, so the lattice covers the grid's interior between cube centres.
#ifndef LPVLAB_TETRAHEDRAL_LATTICE_GLSL
#define LPVLAB_TETRAHEDRAL_LATTICE_GLSL
#include "standard_faces.glsl"
#include "../common/grid.glsl"

#ifdef LPVLAB_SHARED_CPP
using ivec4 = glm::ivec4;
#endif

const int TET_PER_CUBE = 12;
const int TET_FACES = 4;
const real TET_SQRT2 = 1.41421356237309504880;

vec3 tetUnitAxis(int axis) {
  return vec3(axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0);
}

ivec3 tetUnitOffset(int axis) {
  return ivec3(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0);
}

int tetAxis(int code) {
  return code / 4;
}

int tetEdge(int code) {
  return code - 4 * (code / 4);
}

// The axis of T and its sign, and the axis of W.
int tetTAxis(int code) {
  return tetEdge(code) < 2 ? (tetAxis(code) + 1) % 3 : (tetAxis(code) + 2) % 3;
}

int tetTSign(int code) {
  return tetEdge(code) == 1 || tetEdge(code) == 3 ? 1 : -1;
}

int tetWAxis(int code) {
  return tetEdge(code) < 2 ? (tetAxis(code) + 2) % 3 : (tetAxis(code) + 1) % 3;
}

vec3 tetA(int code) {
  return tetUnitAxis(tetAxis(code));
}

vec3 tetT(int code) {
  return real(tetTSign(code)) * tetUnitAxis(tetTAxis(code));
}

vec3 tetW(int code) {
  return tetUnitAxis(tetWAxis(code));
}

// The code of the cell with the given axis whose edge lies on side `sign` of axis tAxis.
int tetCode(int axis, int tAxis, int sign) {
  int edge = (tAxis == (axis + 1) % 3 ? 0 : 2) + (sign > 0 ? 1 : 0);
  return axis * 4 + edge;
}

vec3 tetCentroid(ivec4 tet) {
  ivec3 cube = ivec3(tet.x, tet.y, tet.z);
  return vec3(cube) + vec3(0.5) + 0.5 * tetA(tet.w) + 0.25 * tetT(tet.w);
}

// Vertex i (0 P, 1 Q, 2 R+, 3 R-) relative to the centroid.
vec3 tetVertexFromCentroid(int code, int i) {
  vec3 a = tetA(code);
  vec3 t = tetT(code);
  vec3 w = tetW(code);
  if (i == 0) return -0.5 * a - 0.25 * t;
  if (i == 1) return 0.5 * a - 0.25 * t;
  if (i == 2) return 0.25 * t + 0.5 * w;
  return 0.25 * t - 0.5 * w;
}

int tetOppositeVertex(int face) {
  return face + 1 - 2 * (face % 2);
}

vec3 tetFaceNormal(int code, int face) {
  vec3 a = tetA(code);
  vec3 t = tetT(code);
  vec3 w = tetW(code);
  if (face == 0) return (t - a) / TET_SQRT2;
  if (face == 1) return (t + a) / TET_SQRT2;
  if (face == 2) return (w - t) / TET_SQRT2;
  return (-w - t) / TET_SQRT2;
}

// The centroid of face k relative to the cell's centroid: the mean of its three vertices, which
// is -1/3 of the opposite vertex (the four vertices sum to zero about G).
vec3 tetFaceCentroidFromCentroid(int code, int face) {
  return -tetVertexFromCentroid(code, tetOppositeVertex(face)) / 3.0;
}

// The neighbour across face k. Faces 0 and 1 hold a cube centre (P, resp. Q) and the edge: the
// neighbour pairs that centre with the cube beyond T, sharing the same edge, whose midpoint lies
// at +A (resp. -A) from the new shared face. Faces 2 and 3 hold P, Q and R+ (resp. R-): the
// neighbour is the cell of the same cube face at the edge through that corner, T' = +W (-W).
ivec4 tetNeighbour(ivec4 tet, int face) {
  int code = tet.w;
  ivec3 cube = ivec3(tet.x, tet.y, tet.z);
  int axis = tetAxis(code);
  int tAxis = tetTAxis(code);
  if (face >= 2) {
    int newCode = tetCode(axis, tetWAxis(code), face == 2 ? 1 : -1);
    return ivec4(cube.x, cube.y, cube.z, newCode);
  }
  ivec3 lower = cube;
  if (face == 1) lower += tetUnitOffset(axis);
  if (tetTSign(code) < 0) lower -= tetUnitOffset(tAxis);
  return ivec4(lower.x, lower.y, lower.z, tetCode(tAxis, axis, face == 0 ? 1 : -1));
}

// Whether the cell exists in a grid of `res` cubes: both its cubes are inside.
bool tetInside(ivec4 tet, ivec3 res) {
  ivec3 cube = ivec3(tet.x, tet.y, tet.z);
  return cellInside(cube, res) && cellInside(cube + tetUnitOffset(tetAxis(tet.w)), res);
}

int tetSlot(ivec4 tet, ivec3 res) {
  return cellIndex(ivec3(tet.x, tet.y, tet.z), res) * TET_PER_CUBE + tet.w;
}

int tetSlotCount(ivec3 res) {
  return cellCount(res) * TET_PER_CUBE;
}

// ---- propagation -----------------------------------------------------------------------------
// Standard LPV logic (standard_faces.glsl) on this lattice, as a gather: the target cell receives
// from its neighbour across its face j through its three other faces k, seen from the source's
// centroid G_s = G + sqrt(2)/4 n_j. Face k != j is seen from G_s under
//   TET_SMALL (k = j ^ 1, the face whose normal is perpendicular to the source-target line)
//   TET_LARGE (the two others, normals at 60 degrees to it),
// Omega_small = 2 atan(4 / (sqrt(13) + 3 sqrt(5))) = 0.7399..., Omega_large = (pi - small) / 2.
// All three are back faces seen from G_s, so every ray from G_s through the shared face leaves
// the target through exactly one of them: they tile the shared face's solid angle pi, and the 12
// faces of the 4 neighbours tile the sphere (4 pi) with neither gap nor overlap, so no
// renormalisation is needed: each face's flux Phi_k (below), re-emitted as Phi_k / pi times a
// clamped cosine lobe along n_k, conserves a cell's flux up to the clamp.
real tetFarFaceSolidAngle(int sharedFace, int face, real smallAngle, real largeAngle) {
  return face == tetOppositeVertex(sharedFace) ? smallAngle : largeAngle;
}

// Unit direction from the centroid of the source across face j to the centroid of face k.
vec3 tetFarFaceDirection(int code, int sharedFace, int face) {
  vec3 sourceCentroid = (0.25 * TET_SQRT2) * tetFaceNormal(code, sharedFace);
  return normalize(tetFaceCentroidFromCentroid(code, face) - sourceCentroid);
}

// At any SH order (the kernel's face loop, and the tests' C++ reference, which run per face k):
//   Phi_k = T_k * max(0, sum_i c_i m_ki)                      (standardFaceFlux with Omega = 1)
//   target coefficients += Phi_k / pi * shCosineLobeAt(i, n_k)
// with the face's weights m_ki, by the strategy's `face_flux`:
//   "integral" (default): m_ki = the integral of Y_i over face k seen from G_s
//              (tetFaceIntegralIndex; framework/math/tetrahedral_face_integrals.h). The 12 far
//              faces tile the sphere, so the 12 fluxes sum to the integral of I over the sphere:
//              a step conserves flux for every SH function, and the clamp acts only where a
//              whole face's integral is negative.
//   "centre":  m_ki = Omega_k Y_i(w_k), the standard method's one-point quadrature (the
//              intensity towards the face's centroid). It conserves flux only for an isotropic
//              source; the clamp of a lobe's negative side sampled at single directions adds up
//              to 1.21x (order 1) / 1.26x (orders 2-3) per step, which compounds over a lattice's
//              many steps (docs/variants/tetrahedral.md#tetrahedral).
// Only the number of coefficients changes with the order: the lobe integrates to Phi_k at every
// order (only Y00 has an integral).
const int TET_FACE_INTEGRAL_COUNT = TET_PER_CUBE * TET_FACES * TET_FACES * SH_MAX_COEFFICIENTS;

int tetFaceIntegralIndex(int code, int sharedFace, int face, int i) {
  return ((code * TET_FACES + sharedFace) * TET_FACES + face) * SH_MAX_COEFFICIENTS + i;
}

// With the geometry volume (alg. 6.2 lines 11-14 on this lattice), T_k is the GV's transmittance
// for w_k where w_k, leaving the source's centroid, crosses the shared face j: that point lies on
// the shared triangle (face k is a back face seen from G_s, seen through face j), and the shared
// face is sqrt(2)/8 from G_s along -n_j. Light-grid coordinates, where the GV is interpolated.
vec3 tetFarFaceCrossing(ivec4 tet, int sharedFace, int face) {
  vec3 n = tetFaceNormal(tet.w, sharedFace);
  vec3 sourceCentroid = tetCentroid(tet) + (0.25 * TET_SQRT2) * n;
  vec3 w = tetFarFaceDirection(tet.w, sharedFace, face);
  return sourceCentroid + w * ((0.125 * TET_SQRT2) / dot(w, -n));
}

// The first lattice step the GV attenuates: the GV's firstOccludedIteration counts standard steps
// of one cube edge (1 lets light leave the injected cube unblocked, as its own surfels would
// block it); a lattice step moves light sqrt(2)/4 edges, so the lattice occludes once light has
// travelled as far: from step ceil(2 sqrt(2) firstOccludedIteration) on (3 for 1).
int tetFirstOccludedStep(int firstOccludedIteration) {
  return int(ceil(real(firstOccludedIteration) * 2.0 * TET_SQRT2));
}

// ---- resampling between the cubic light grid and the lattice ---------------------------------
// Cube -> cells: the part of a cell inside one of its cubes is the tetrahedron (centre, face
// centre, edge) of volume 1/24; a cube is exactly 24 such parts, so it gives each of its cells
// 1/24 of its coefficients. Parts that belong to no cell (faces on the grid's boundary) would
// lose light, so a cube splits among the cells that exist: 1 / (4 * faces with a neighbour).
int tetCubeInnerFaces(ivec3 cube, ivec3 res) {
  int faces = 0;
  for (int axis = 0; axis < 3; ++axis) {
    if (cellInside(cube + tetUnitOffset(axis), res)) faces += 1;
    if (cellInside(cube - tetUnitOffset(axis), res)) faces += 1;
  }
  return faces;
}

real tetSplitWeight(ivec3 cube, ivec3 res) {
  return 1.0 / real(4 * max(tetCubeInnerFaces(cube, res), 1));
}

// Cells -> cube: each cell gives half of its coefficients to each of its two cubes (both inside,
// as the cell exists). Both directions conserve flux (shIntegral is linear in c0) and are linear
// maps applied to every coefficient alike, so they hold at every SH order.
const real TET_MERGE_WEIGHT = 0.5;

// The sum of the steps counts light once per step it spends in a cell. The cubic grid's sum counts
// it once per cube edge travelled (a standard step moves light one edge, which is what makes its
// radiance I / h^2 the same at every resolution); a lattice step moves light sqrt(2)/4 edges
// (between neighbouring centroids), so light crossing a cube is in it for 2 sqrt(2) times as
// many steps. The lattice's sum is weighted by the step length in cube edges so that the same
// light gives the same accumulated grid on both lattices.
const real TET_STEP_LENGTH = 0.25 * TET_SQRT2;

#endif

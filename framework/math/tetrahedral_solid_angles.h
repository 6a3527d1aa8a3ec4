#pragma once
// Face solid angles of tetrahedral propagation (shaders/propagation/tetrahedral_lattice.glsl,
// docs/variants/tetrahedral.md#tetrahedral), from the geometry. A lattice cell (BCC Delaunay disphenoid,
// cube edge 1) in its local frame (A, T, W) = (x, y, z) has its centroid at the origin and
// vertices P = (-1/2, -1/4, 0), Q = (1/2, -1/4, 0), R+ = (0, 1/4, 1/2), R- = (0, 1/4, -1/2). Its
// neighbour across face (P, Q, R+) has its centroid at (0, -1/4, 1/4); seen from there, the
// cell's three other faces subtend:
//   smallFace: (P, Q, R-), normal perpendicular to the line between the centroids:
//              2 atan(4 / (sqrt 13 + 3 sqrt 5)) = 0.73994509...
//   largeFace: (P, R+, R-) and (Q, R+, R-): (pi - smallFace) / 2 = 1.20082377... each
// Together they fill the shared face's solid angle pi, and the 12 faces of a cell's four
// neighbours tile the sphere.
namespace lpvlab {

struct TetrahedralFaceSolidAngles {
  double smallFace;
  double largeFace;
  double sharedFace;  // a cell's face seen from its own centroid: pi
};
TetrahedralFaceSolidAngles tetrahedralFaceSolidAngles();

}  // namespace lpvlab

// The tetrahedral lattice of "tetrahedral" propagation (shaders/propagation/
// tetrahedral_lattice.glsl, compiled here as double-precision C++) against its geometry:
//   - the cells tile space (every point lies in exactly one) and the lattice keeps all 48
//     symmetries of the cube about a cube centre;
//   - neighbour addressing: the cell across face k shares exactly that face, lies mirrored in
//     it, and its neighbour across the same face is the cell again;
//   - face solid angles: a cell's four faces seen from its centroid are pi each (4 pi); the three
//     far faces of each neighbour are back faces that fill exactly the shared face's pi, and the
//     values the kernel uses (framework/math/tetrahedral_solid_angles.h) are those of every face
//     of every cell, against closed forms;
//   - where the GV is read: the crossing of each far face's direction with the shared face lies
//     on that direction's ray from the source's centroid and inside the shared triangle.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "framework/math/shared.h"
#include "framework/math/solid_angle.h"
#include "framework/math/tetrahedral_solid_angles.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/tetrahedral_lattice.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

using glm::dvec3;
using glm::ivec3;
using glm::ivec4;
using Vertices = std::array<dvec3, 4>;

Vertices verticesOf(const ivec4& tet) {
  const dvec3 g = shared::tetCentroid(tet);
  Vertices v;
  for (int i = 0; i < 4; ++i) v[i] = g + shared::tetVertexFromCentroid(tet.w, i);
  return v;
}

// Vertices in doubled integer coordinates (all BCC points are then integer), for exact matching.
using Key = std::array<int, 3>;
Key keyOf(const dvec3& p) {
  return {int(std::lround(2.0 * p.x)), int(std::lround(2.0 * p.y)), int(std::lround(2.0 * p.z))};
}
std::set<Key> keysOf(const Vertices& v) { return {keyOf(v[0]), keyOf(v[1]), keyOf(v[2]), keyOf(v[3])}; }

// Face k's vertices: all but the opposite one.
std::array<dvec3, 3> faceOf(const Vertices& v, int face) {
  std::array<dvec3, 3> out;
  int n = 0;
  for (int i = 0; i < 4; ++i)
    if (i != shared::tetOppositeVertex(face)) out[n++] = v[i];
  return out;
}

double solidAngle(const std::array<dvec3, 3>& f, const dvec3& from) {
  return triangleSolidAngle(f[0] - from, f[1] - from, f[2] - from);
}

// Every cell of the cubes in [-r, r]^3, by vertex set.
std::map<std::set<Key>, ivec4> latticeAround(int r) {
  std::map<std::set<Key>, ivec4> cells;
  for (int z = -r; z <= r; ++z)
    for (int y = -r; y <= r; ++y)
      for (int x = -r; x <= r; ++x)
        for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
          const ivec4 tet{x, y, z, code};
          cells[keysOf(verticesOf(tet))] = tet;
        }
  return cells;
}

const ivec3 kCube{3, -2, 5};  // away from the origin, so sign and floor mistakes show

TEST(TetrahedralLattice, CellsAreCongruentDisphenoidsOfVolumeOneTwelfth) {
  for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
    const Vertices v = verticesOf({kCube.x, kCube.y, kCube.z, code});
    EXPECT_NEAR(std::abs(glm::dot(v[1] - v[0], glm::cross(v[2] - v[0], v[3] - v[0]))) / 6.0,
                1.0 / 12.0, 1e-14);
    // A tetragonal disphenoid: opposite edges equal, PQ = R+R- = 1, the other four sqrt(3)/2.
    EXPECT_NEAR(glm::length(v[1] - v[0]), 1.0, 1e-14);
    EXPECT_NEAR(glm::length(v[3] - v[2]), 1.0, 1e-14);
    for (int i : {0, 1})
      for (int j : {2, 3}) EXPECT_NEAR(glm::length(v[j] - v[i]), std::sqrt(3.0) / 2.0, 1e-14);
    // The cube centres and corners are BCC points.
    EXPECT_EQ(keyOf(v[0]), (Key{2 * kCube.x + 1, 2 * kCube.y + 1, 2 * kCube.z + 1}));
  }
}

TEST(TetrahedralLattice, CellsTileSpace) {
  const auto cells = latticeAround(2);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 1500; ++i) {
    const dvec3 p{u(rng), u(rng), u(rng)};  // inside cube (0, 0, 0)
    int containing = 0;
    for (const auto& [keys, tet] : cells) {
      const Vertices v = verticesOf(tet);
      const double volume = glm::dot(v[1] - v[0], glm::cross(v[2] - v[0], v[3] - v[0]));
      bool inside = true;
      for (int k = 0; k < 4; ++k) {  // barycentric signs: replace vertex k by p
        Vertices w = v;
        w[k] = p;
        if (glm::dot(w[1] - w[0], glm::cross(w[2] - w[0], w[3] - w[0])) / volume < 0.0) inside = false;
      }
      containing += inside;
    }
    EXPECT_EQ(containing, 1) << "point " << p.x << " " << p.y << " " << p.z;
  }
}

TEST(TetrahedralLattice, KeepsEverySymmetryOfTheCube) {
  const auto cells = latticeAround(2);
  const dvec3 centre{0.5, 0.5, 0.5};
  int symmetries = 0;
  const std::array<std::array<int, 3>, 6> permutations{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  for (const auto& perm : permutations)
    for (int signs = 0; signs < 8; ++signs) {
      for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
        Vertices image;
        const Vertices v = verticesOf({0, 0, 0, code});
        for (int i = 0; i < 4; ++i) {
          const dvec3 d = v[i] - centre;
          for (int axis = 0; axis < 3; ++axis)
            image[i][axis] = centre[axis] + ((signs >> axis) & 1 ? -1.0 : 1.0) * d[perm[axis]];
        }
        EXPECT_TRUE(cells.count(keysOf(image))) << "symmetry " << symmetries << " code " << code;
      }
      ++symmetries;
    }
  EXPECT_EQ(symmetries, 48);
}

TEST(TetrahedralLattice, NeighbourSharesTheFaceLiesMirroredAndAddressesBack) {
  for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
    const ivec4 tet{kCube.x, kCube.y, kCube.z, code};
    const Vertices v = verticesOf(tet);
    const dvec3 g = shared::tetCentroid(tet);
    std::set<Key> seen;
    for (int face = 0; face < shared::TET_FACES; ++face) {
      const ivec4 n = shared::tetNeighbour(tet, face);
      ASSERT_GE(n.w, 0);
      ASSERT_LT(n.w, shared::TET_PER_CUBE);
      const Vertices nv = verticesOf(n);
      std::set<Key> common;
      for (const Key& k : keysOf(nv))
        if (keysOf(v).count(k)) common.insert(k);
      const auto f = faceOf(v, face);
      EXPECT_EQ(common, (std::set<Key>{keyOf(f[0]), keyOf(f[1]), keyOf(f[2])}))
          << "code " << code << " face " << face;
      // The outward normal: unit, perpendicular to the face, away from the opposite vertex.
      const dvec3 normal = shared::tetFaceNormal(code, face);
      EXPECT_NEAR(glm::length(normal), 1.0, 1e-14);
      EXPECT_NEAR(glm::dot(normal, f[1] - f[0]), 0.0, 1e-14);
      EXPECT_NEAR(glm::dot(normal, f[2] - f[0]), 0.0, 1e-14);
      EXPECT_NEAR(glm::dot(normal, f[0] - g), std::sqrt(2.0) / 8.0, 1e-14);
      const dvec3 mirrored = g + std::sqrt(2.0) / 4.0 * normal;
      EXPECT_NEAR(glm::length(shared::tetCentroid(n) - mirrored), 0.0, 1e-14);
      int back = 0;
      for (int nf = 0; nf < shared::TET_FACES; ++nf)
        back += shared::tetNeighbour(n, nf) == tet;
      EXPECT_EQ(back, 1) << "code " << code << " face " << face;
      seen.insert(keyOf(shared::tetCentroid(n)));
    }
    EXPECT_EQ(seen.size(), 4u);
  }
}

TEST(TetrahedralLattice, FacesAroundACellSumToFourPi) {
  for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
    const ivec4 tet{kCube.x, kCube.y, kCube.z, code};
    const Vertices v = verticesOf(tet);
    const dvec3 g = shared::tetCentroid(tet);
    double sum = 0.0;
    for (int face = 0; face < 4; ++face) {
      const double omega = solidAngle(faceOf(v, face), g);
      EXPECT_NEAR(omega, M_PI, 1e-13);
      sum += omega;
    }
    EXPECT_NEAR(sum, 4.0 * M_PI, 1e-12);
  }
}

TEST(TetrahedralLattice, SolidAnglesMatchClosedForms) {
  const TetrahedralFaceSolidAngles angles = tetrahedralFaceSolidAngles();
  EXPECT_NEAR(angles.smallFace, 2.0 * std::atan(4.0 / (std::sqrt(13.0) + 3.0 * std::sqrt(5.0))),
              1e-14);
  EXPECT_NEAR(angles.smallFace, 0.7399450994, 1e-10);
  EXPECT_NEAR(angles.largeFace, 0.5 * (M_PI - angles.smallFace), 1e-13);
  EXPECT_NEAR(angles.sharedFace, M_PI, 1e-13);
}

// The gather's view: a cell receives from its neighbour across face j through its faces k != j,
// seen from the neighbour's centroid. Those faces are back faces from there (every ray through
// the shared face leaves through exactly one of them), they fill the shared face's pi, the 12
// faces of the four neighbours fill 4 pi, and the kernel's solid angle and direction for each
// are the geometry's.
TEST(TetrahedralLattice, NeighboursFarFacesTileTheSphere) {
  const TetrahedralFaceSolidAngles angles = tetrahedralFaceSolidAngles();
  for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
    const ivec4 source{kCube.x, kCube.y, kCube.z, code};
    const dvec3 from = shared::tetCentroid(source);
    double total = 0.0;
    for (int face = 0; face < shared::TET_FACES; ++face) {
      const ivec4 target = shared::tetNeighbour(source, face);
      const Vertices v = verticesOf(target);
      int j = -1;  // the target's face towards the source
      for (int k = 0; k < 4; ++k)
        if (shared::tetNeighbour(target, k) == source) j = k;
      ASSERT_GE(j, 0);
      double covered = 0.0;
      for (int k = 0; k < 4; ++k) {
        if (k == j) continue;
        const auto f = faceOf(v, k);
        const dvec3 normal = shared::tetFaceNormal(target.w, k);
        EXPECT_GT(glm::dot(normal, f[0] - from), 1e-3) << "a front face seen from the source";
        const double omega = solidAngle(f, from);
        EXPECT_NEAR(omega, shared::tetFarFaceSolidAngle(j, k, angles.smallFace, angles.largeFace),
                    1e-13)
            << "code " << code << " face " << face << " k " << k;
        const dvec3 toCentre = glm::normalize((f[0] + f[1] + f[2]) / 3.0 - from);
        EXPECT_NEAR(glm::length(shared::tetFarFaceDirection(target.w, j, k) - toCentre), 0.0, 1e-13);
        covered += omega;
      }
      EXPECT_NEAR(covered, solidAngle(faceOf(v, j), from), 1e-13);
      EXPECT_NEAR(covered, M_PI, 1e-13);
      total += covered;
    }
    EXPECT_NEAR(total, 4.0 * M_PI, 1e-12);
  }
}

TEST(TetrahedralLattice, FarFaceCrossingsLieOnTheSharedTriangle) {
  for (int code = 0; code < shared::TET_PER_CUBE; ++code) {
    const ivec4 tet{kCube.x, kCube.y, kCube.z, code};
    const Vertices v = verticesOf(tet);
    for (int j = 0; j < shared::TET_FACES; ++j) {
      const dvec3 source = shared::tetCentroid(shared::tetNeighbour(tet, j));
      const std::array<dvec3, 3> f = faceOf(v, j);
      const dvec3 normal = glm::cross(f[1] - f[0], f[2] - f[0]);
      for (int k = 0; k < shared::TET_FACES; ++k) {
        if (k == j) continue;
        const dvec3 p = shared::tetFarFaceCrossing(tet, j, k);
        const dvec3 w = shared::tetFarFaceDirection(code, j, k);
        EXPECT_NEAR(glm::length(glm::cross(p - source, w)), 0.0, 1e-13) << "on the ray";
        EXPECT_GT(glm::dot(p - source, w), 0.0) << "ahead of the source";
        EXPECT_NEAR(glm::dot(p - f[0], normal), 0.0, 1e-13) << "in the shared face's plane";
        // Inside the triangle: on the inner side of each of its edges.
        for (int e = 0; e < 3; ++e) {
          const dvec3 a = f[e], b = f[(e + 1) % 3], c = f[(e + 2) % 3];
          const dvec3 edgeNormal = glm::cross(normal, b - a);
          EXPECT_GT(glm::dot(p - a, edgeNormal) * glm::dot(c - a, edgeNormal), 0.0)
              << "code " << code << " face " << j << " -> " << k << " edge " << e;
        }
      }
    }
  }
}

}  // namespace
}  // namespace lpvlab

#pragma once
// The scene split into patches (seed 004, 2.2.1): every triangle of every mesh cut into m^2
// congruent triangles, m = ceil(longest edge / size) (uniform subdivision: the seed's meshes keep
// sides within a factor 2 of each other, and so do the pieces of a triangle), or, for adaptive
// subdivision, patches split further into their four midpoint triangles (splitPatches).
//
// A patch has two sides, as the scene's surfaces do (the path tracer reflects and emits on both):
// side 2p + 0 faces along the patch's winding normal, side 2p + 1 against it. Radiosity is solved
// per side; a side nothing sees and nothing lights simply stays dark.
//
// Per patch, what the radiosity equation B = E + rho H (seed 004, equation 2-2) needs of it:
//   albedo     rho, the material's albedo (base colour times texture) averaged over the patch
//   exitance   E = pi L_e, W/m^2, the emitted radiance of a Lambertian emitter times pi; both
//              sides emit (the path tracer's convention, material_sampling.h)
// Alpha masks are ignored: radiosity treats cut-out surfaces as opaque (docs/variants/radiosity.md).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "framework/scene/scene.h"

namespace lpvlab {

struct Patch {
  std::array<glm::vec3, 3> corners;   // counter-clockwise seen from the front side
  std::array<std::uint32_t, 3> vertex;  // welded vertex of each corner (PatchMesh::vertexCount)
  std::array<glm::vec2, 3> uv;        // texture coordinates of the corners
  std::array<glm::vec3, 3> color;     // vertex colours of the corners (Mesh::colors; white without)
  glm::vec3 normal;                   // unit, the front side's
  glm::vec3 centroid;
  float area;                         // m^2
  glm::vec3 albedo;                   // mean over the patch (material x vertex colour), in [0, 1]
  glm::vec3 exitance;                 // pi L_e, W/m^2, per side
  int mesh;                           // of the scene
  int level;                          // subdivisions by splitPatches (0: uniform meshing)
};

struct PatchMesh {
  std::vector<Patch> patches;
  std::size_t vertexCount = 0;  // corners welded by position (Gouraud display's vertices)

  std::size_t sides() const { return 2 * patches.size(); }
  std::size_t memoryBytes() const { return patches.capacity() * sizeof(Patch); }
};

// Splits `scene`'s triangles into patches no longer than `maxEdge` (m). Degenerate triangles
// (zero area) make no patches. Throws an Error naming the mesh when maxEdge is not positive and
// finite or the patches would exceed `maxPatches`.
PatchMesh meshPatches(const Scene& scene, float maxEdge, std::size_t maxPatches);

// Replaces each patch whose `split` flag is set by its four midpoint triangles (level + 1),
// keeping the others; corners are welded again. `split` has one flag per patch.
PatchMesh splitPatches(const Scene& scene, const PatchMesh& mesh, const std::vector<bool>& split);

// A point of patch p from barycentrics (b1, b2): (1 - b1 - b2) c0 + b1 c1 + b2 c2.
inline glm::vec3 pointOn(const Patch& p, float b1, float b2) {
  return (1.0f - b1 - b2) * p.corners[0] + b1 * p.corners[1] + b2 * p.corners[2];
}

// The normal of side s of patch s / 2.
inline glm::vec3 sideNormal(const PatchMesh& mesh, std::size_t side) {
  const glm::vec3 n = mesh.patches[side / 2].normal;
  return (side & 1) ? -n : n;
}

}  // namespace lpvlab

#pragma once
// Shared helpers of the end-to-end pipeline tests:
//   - the binary's one GL context (gl/gl_test_context.h),
//   - the propagation mathematics of shaders/propagation/standard_faces.glsl compiled as C++ in
//     double precision (next to the shaders/common/ files that framework/math/shared.h compiles),
//   - a brute-force double-precision ray caster over a Scene's triangles, the independent ground
//     truth for what the rasterised passes (G-buffer, RSM) should see.

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "framework/math/shared.h"
#include "framework/scene/scene.h"
#include "gl/gl_test_context.h"

// standard_faces.glsl as C++, beside the shared GLSL of framework/math/shared.h.
LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/standard_faces.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab::test {

// The closest surface along a ray.
struct RayHit {
  double t = std::numeric_limits<double>::infinity();  // in units of |direction|
  int mesh = -1;
  glm::dvec3 normal{0.0};  // the triangle's geometric normal (unit, either side)
  std::size_t firstIndex = 0;  // of the triangle's corners in the mesh's indices
  double u = 0.0, v = 0.0;     // barycentrics: (1 - u - v) corner 0 + u corner 1 + v corner 2
};

// Every triangle of a scene in double precision, with its mesh.
class SceneRaycaster {
public:
  explicit SceneRaycaster(const Scene& scene) : scene_(scene) {
    for (int m = 0; m < int(scene.meshes.size()); ++m) {
      const Mesh& mesh = scene.meshes[m];
      for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
        triangles_.push_back({glm::dvec3(mesh.positions[mesh.indices[i]]),
                              glm::dvec3(mesh.positions[mesh.indices[i + 1]]),
                              glm::dvec3(mesh.positions[mesh.indices[i + 2]]), m, i});
    }
  }

  // Moeller-Trumbore against every triangle; t > tMin.
  std::optional<RayHit> cast(const glm::dvec3& origin, const glm::dvec3& direction,
                             double tMin = 1e-9) const {
    RayHit best;
    for (const Triangle& tri : triangles_) {
      const glm::dvec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
      const glm::dvec3 p = glm::cross(direction, e2);
      const double det = glm::dot(e1, p);
      if (std::abs(det) < 1e-18) continue;
      const double inv = 1.0 / det;
      const glm::dvec3 s = origin - tri.a;
      const double u = glm::dot(s, p) * inv;
      if (u < 0.0 || u > 1.0) continue;
      const glm::dvec3 q = glm::cross(s, e1);
      const double v = glm::dot(direction, q) * inv;
      if (v < 0.0 || u + v > 1.0) continue;
      const double t = glm::dot(e2, q) * inv;
      if (t > tMin && t < best.t) {
        best.t = t;
        best.mesh = tri.mesh;
        best.normal = glm::normalize(glm::cross(e1, e2));
        best.firstIndex = tri.firstIndex;
        best.u = u, best.v = v;
      }
    }
    if (best.mesh < 0) return std::nullopt;
    return best;
  }

  const Material& material(const RayHit& hit) const {
    return scene_.materials[scene_.meshes[hit.mesh].material];
  }

  // The albedo at the hit of an untextured material: its base colour times the vertex colours
  // interpolated (Mesh::colors; white without).
  glm::dvec3 untexturedAlbedo(const RayHit& hit) const {
    const Mesh& mesh = scene_.meshes[std::size_t(hit.mesh)];
    glm::dvec3 colour(1.0);
    if (!mesh.colors.empty()) {
      const std::uint32_t* corner = &mesh.indices[hit.firstIndex];
      colour = (1.0 - hit.u - hit.v) * glm::dvec3(mesh.colors[corner[0]]) + hit.u * glm::dvec3(mesh.colors[corner[1]]) +
               hit.v * glm::dvec3(mesh.colors[corner[2]]);
    }
    return glm::dvec3(material(hit).baseColor) * colour;
  }

private:
  struct Triangle {
    glm::dvec3 a, b, c;
    int mesh;
    std::size_t firstIndex;
  };
  const Scene& scene_;
  std::vector<Triangle> triangles_;
};

// The camera ray through the centre of output pixel (x, y) (top row first), as the G-buffer's
// glm::lookAt + glm::perspective rasterise it, scaled so that dot(direction, forward) = 1: a hit
// at parameter t has view depth t.
inline glm::dvec3 cameraRay(const Camera& camera, int width, int height, int x, int y) {
  const glm::dvec3 f = glm::normalize(glm::dvec3(camera.forward));
  const glm::dvec3 s = glm::normalize(glm::cross(f, glm::dvec3(camera.up)));
  const glm::dvec3 u = glm::cross(s, f);
  const double tanHalf = std::tan(0.5 * double(camera.verticalFov));
  const double aspect = double(width) / double(height);
  const double ndcX = 2.0 * (x + 0.5) / width - 1.0;
  const double ndcY = 1.0 - 2.0 * (y + 0.5) / height;
  return f + ndcX * tanHalf * aspect * s + ndcY * tanHalf * u;
}

}  // namespace lpvlab::test

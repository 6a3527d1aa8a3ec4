#include "framework/radiosity/patches.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "framework/core/error.h"
#include "framework/reference/material_sampling.h"

namespace lpvlab {

namespace {

// Corners within `quantum` of each other become one vertex. A grid of cells of that size is
// searched in the 27 cells around a corner, so two copies of a point computed along different
// subdivisions (equal to float rounding) weld even where they straddle a cell boundary.
class VertexWelder {
public:
  explicit VertexWelder(float quantum) : quantum_(quantum) {}

  std::uint32_t weld(const glm::vec3& p) {
    const glm::i64vec3 cell = cellOf(p);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto found = cells_.equal_range(key(cell + glm::i64vec3(dx, dy, dz)));
          for (auto it = found.first; it != found.second; ++it)
            if (glm::all(glm::lessThanEqual(glm::abs(points_[it->second] - p), glm::vec3(quantum_))))
              return it->second;
        }
    const auto id = std::uint32_t(points_.size());
    points_.push_back(p);
    cells_.emplace(key(cell), id);
    return id;
  }
  std::size_t count() const { return points_.size(); }

private:
  glm::i64vec3 cellOf(const glm::vec3& p) const {
    return glm::i64vec3(glm::floor(glm::dvec3(p) / double(quantum_)));
  }
  static std::uint64_t key(const glm::i64vec3& c) {
    return std::uint64_t(c.x) * 0x9e3779b97f4a7c15ull ^ std::uint64_t(c.y) * 0xc2b2ae3d27d4eb4full ^
           std::uint64_t(c.z) * 0x165667b19e3779f9ull;
  }
  float quantum_;
  std::vector<glm::vec3> points_;
  std::unordered_multimap<std::uint64_t, std::uint32_t> cells_;
};

float weldQuantum(const Scene& scene) {
  const Bounds b = scene.bounds();
  const glm::vec3 extent = b.max - b.min;
  const glm::vec3 far = glm::max(glm::abs(b.min), glm::abs(b.max));
  const float largest = std::max({extent.x, extent.y, extent.z, far.x, far.y, far.z});
  return b.empty() ? 1e-30f : std::max(1e-5f * largest, 1e-30f);
}

// The values at the corners of a triangle that the patches carry (position, uv, colour) are
// linear across it: the patches of a triangle, and the children of a split, interpolate them.
template <class T>
using Corners = std::array<T, 3>;

template <class T>
T interpolate(const Corners<T>& v, float b1, float b2) {
  return v[0] + b1 * (v[1] - v[0]) + b2 * (v[2] - v[0]);
}

// The patch's albedo: the material's times the vertex colour, averaged over a 4 x 4 grid of
// sub-triangle centres (a texture or the colours vary across a patch; the mean is what the
// patch reflects in total).
glm::vec3 meanAlbedo(const SurfaceMaterial& material, const Corners<glm::vec2>& uv, const Corners<glm::vec3>& color) {
  if (!material.texture && color[0] == color[1] && color[1] == color[2]) return material.baseColor * color[0];
  constexpr int n = 4;
  glm::vec3 sum(0.0f);
  int count = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      const float b1 = (float(i) + 1.0f / 3.0f) / n, b2 = (float(j) + 1.0f / 3.0f) / n;
      sum += albedoAt(material, interpolate(uv, b1, b2)) * interpolate(color, b1, b2);
      ++count;
    }
  return sum / float(count);
}

// A patch from three corners (and their uvs and colours); false for a degenerate one.
bool makePatch(const Corners<glm::vec3>& c, const Corners<glm::vec2>& uv, const Corners<glm::vec3>& color,
               const SurfaceMaterial& material, int mesh, int level, Patch& out) {
  const glm::dvec3 cross =
      glm::cross(glm::dvec3(c[1]) - glm::dvec3(c[0]), glm::dvec3(c[2]) - glm::dvec3(c[0]));
  const double twiceArea = glm::length(cross);
  if (!(twiceArea > 0.0) || !std::isfinite(twiceArea)) return false;
  out.corners = c;
  out.uv = uv;
  out.color = color;
  out.normal = glm::vec3(cross / twiceArea);
  out.centroid = (c[0] + c[1] + c[2]) / 3.0f;
  out.area = float(0.5 * twiceArea);
  out.albedo = glm::clamp(meanAlbedo(material, uv, color), 0.0f, 1.0f);
  out.exitance = float(M_PI) * material.emission;
  out.mesh = mesh;
  out.level = level;
  return true;
}

// The two sub-triangles at (i, j) of a triangle cut into n x n along its edges from corner 0:
// the upright one, and the one turned over beside it (where i + j + 2 <= n).
template <class T>
Corners<T> upright(const Corners<T>& v, int i, int j, int n) {
  const auto at = [&](int a, int b) { return interpolate(v, float(a) / float(n), float(b) / float(n)); };
  return {at(i, j), at(i + 1, j), at(i, j + 1)};
}
template <class T>
Corners<T> turned(const Corners<T>& v, int i, int j, int n) {
  const auto at = [&](int a, int b) { return interpolate(v, float(a) / float(n), float(b) / float(n)); };
  return {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
}

// The four children of a split at the edges' midpoints, corner k's child first, the middle last.
template <class T>
std::array<Corners<T>, 4> halves(const Corners<T>& c) {
  const T m01 = 0.5f * (c[0] + c[1]), m12 = 0.5f * (c[1] + c[2]), m20 = 0.5f * (c[2] + c[0]);
  return {{{c[0], m01, m20}, {m01, c[1], m12}, {m20, m12, c[2]}, {m12, m20, m01}}};
}

void weldAll(const Scene& scene, PatchMesh& mesh) {
  VertexWelder welder(weldQuantum(scene));
  for (Patch& p : mesh.patches)
    for (int k = 0; k < 3; ++k) p.vertex[k] = welder.weld(p.corners[k]);
  mesh.vertexCount = welder.count();
}

}  // namespace

PatchMesh meshPatches(const Scene& scene, float maxEdge, std::size_t maxPatches) {
  if (!(maxEdge > 0.0f) || !std::isfinite(maxEdge))
    throw Error("radiosity: the patch size must be positive and finite, not " + std::to_string(maxEdge));
  const std::vector<SurfaceMaterial> materials = prepareMaterials(scene);
  PatchMesh out;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const SurfaceMaterial& material = materials.at(std::size_t(mesh.material));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::array<std::uint32_t, 3> index = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
      const Corners<glm::vec3> corners = {mesh.positions[index[0]], mesh.positions[index[1]], mesh.positions[index[2]]};
      const Corners<glm::vec2> uvs = {mesh.uvs[index[0]], mesh.uvs[index[1]], mesh.uvs[index[2]]};
      Corners<glm::vec3> colors = {glm::vec3(1.0f), glm::vec3(1.0f), glm::vec3(1.0f)};
      if (!mesh.colors.empty()) colors = {mesh.colors[index[0]], mesh.colors[index[1]], mesh.colors[index[2]]};
      const auto& [a, b, c] = corners;
      const float longest = std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)});
      if (!std::isfinite(longest))
        throw Error(scene.source + ": mesh '" + mesh.name + "' has a non-finite vertex");
      const double pieces = std::max(1.0, std::ceil(double(longest) / double(maxEdge)));
      if (pieces * pieces + double(out.patches.size()) > double(maxPatches))
        throw Error("radiosity: patches of at most " + std::to_string(maxEdge) + " m would be more than " +
                    std::to_string(maxPatches) + " (mesh '" + mesh.name +
                    "' alone needs " + std::to_string(pieces * pieces) +
                    " per triangle); raise patch_size or max_patches");
      const int n = int(pieces);
      Patch p;
      for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
          if (makePatch(upright(corners, i, j, n), upright(uvs, i, j, n), upright(colors, i, j, n), material,
                        int(m), 0, p))
            out.patches.push_back(p);
          if (i + j + 2 <= n && makePatch(turned(corners, i, j, n), turned(uvs, i, j, n),
                                          turned(colors, i, j, n), material, int(m), 0, p))
            out.patches.push_back(p);
        }
    }
  }
  weldAll(scene, out);
  return out;
}

PatchMesh splitPatches(const Scene& scene, const PatchMesh& mesh, const std::vector<bool>& split) {
  const std::vector<SurfaceMaterial> materials = prepareMaterials(scene);
  PatchMesh out;
  out.patches.reserve(mesh.patches.size());
  for (std::size_t i = 0; i < mesh.patches.size(); ++i) {
    const Patch& p = mesh.patches[i];
    if (!split.at(i)) {
      out.patches.push_back(p);
      continue;
    }
    const SurfaceMaterial& material = materials.at(std::size_t(scene.meshes.at(std::size_t(p.mesh)).material));
    const auto corners = halves(p.corners);
    const auto uvs = halves(p.uv);
    const auto colors = halves(p.color);
    Patch child;
    for (int k = 0; k < 4; ++k)
      if (makePatch(corners[k], uvs[k], colors[k], material, p.mesh, p.level + 1, child)) out.patches.push_back(child);
  }
  weldAll(scene, out);
  return out;
}

}  // namespace lpvlab

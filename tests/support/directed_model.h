#pragma once
// Directed propagation's normal dilation (directed_dilate.comp) as a double-precision model over
// the shared GLSL (directed_faces.glsl), for the tests of both backends' kernels.

#include <cstddef>
#include <random>
#include <vector>

#include "grid_test_support.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/propagation/directed_faces.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab::test {

// A cell's stored value in a normal grid (vec4 per cell).
inline glm::dvec4 normalOf(const std::vector<float>& n, const glm::ivec3& res,
                           const glm::ivec3& cell) {
  const std::size_t i = std::size_t(4) * shared::cellIndex(cell, res);
  return {n[i], n[i + 1], n[i + 2], n[i + 3]};
}

// One dilation step of the whole grid.
inline std::vector<float> dilate(const std::vector<float>& normals, const glm::ivec3& res) {
  std::vector<float> out(normals.size());
  forEachCell(res, [&](const glm::ivec3& c) {
    glm::dvec3 sum(0.0);
    for (const glm::ivec3& d : kAxes)
      if (shared::cellInside(c + d, res))
        sum += shared::directedUnitNormal(normalOf(normals, res, c + d));
    const glm::dvec4 v = shared::directedDilated(normalOf(normals, res, c), sum);
    for (int k = 0; k < 4; ++k) out[std::size_t(4) * shared::cellIndex(c, res) + k] = float(v[k]);
  });
  return out;
}

// A normal grid of regions for the tests of the release: about `fraction` of the cells hold a
// VPL normal, flux-weighted by a random flux, of one of three directions by where the cell lies
// (x below the middle: +y; else z below the middle: -x; else (1, 2, 3)/|.|), so that
// neighbouring cells mostly agree (their attached light is reprojected) and the regions'
// boundaries and the cells without normals release theirs.
inline std::vector<float> regionNormals(const glm::ivec3& res, std::mt19937& random, float fraction) {
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<float> normals(std::size_t(4) * cells(res), 0.0f);
  const glm::dvec3 oblique = glm::normalize(glm::dvec3(1.0, 2.0, 3.0));
  forEachCell(res, [&](const glm::ivec3& c) {
    if (uniform(random) >= fraction) return;
    const glm::dvec3 n = 2 * c.x < res.x ? glm::dvec3(0, 1, 0)
                         : 2 * c.z < res.z ? glm::dvec3(-1, 0, 0)
                                           : oblique;
    const double phi = 0.5 + uniform(random);
    const std::size_t i = std::size_t(4) * shared::cellIndex(c, res);
    for (int k = 0; k < 3; ++k) normals[i + k] = float(phi * n[k]);
    normals[i + 3] = float(phi);
  });
  return normals;
}

}  // namespace lpvlab::test

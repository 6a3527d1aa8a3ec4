#pragma once
// Directed propagation's normal dilation (directed_dilate.comp) as a double-precision model over
// the shared GLSL (directed_faces.glsl), for the tests of both backends' kernels.

#include <cstddef>
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

}  // namespace lpvlab::test

// viewFromWorld (framework/math/view_matrix.h) against the view of the same eye computed in double:
// a point straight ahead of an eye 1000 m from the origin lands on the view axis (off it by float
// rounding of the translation alone, ~1e-4 m, where glm::lookAt(eye, eye + forward, up), whose
// direction comes from (eye + forward) - eye, misses it by centimetres); near the origin it is
// glm::lookAt's matrix.

#include "framework/math/view_matrix.h"

#include <gtest/gtest.h>

#include <iostream>
#include <random>

namespace lpvlab {
namespace {

TEST(ViewMatrix, FarFromTheOriginTheViewKeepsItsDirection) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  double worst = 0.0, worstLookAt = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const glm::vec3 eye = glm::vec3(1000.0 * glm::dvec3(uniform(rng), uniform(rng), uniform(rng)));
    const glm::vec3 forward = glm::vec3(glm::normalize(glm::dvec3(uniform(rng), uniform(rng), uniform(rng))));
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    if (std::abs(forward.y) > 0.95f) continue;
    // Points 1 m and 1000 m ahead, on the axis and off it, placed in double along the float eye's
    // exact view axes: their view-space x and y are the offsets.
    for (double distance : {1.0, 1000.0})
      for (const glm::dvec2 offset : {glm::dvec2(0.0), glm::dvec2(0.3, -0.2)}) {
        const glm::dvec3 f = glm::normalize(glm::dvec3(forward));
        const glm::dvec3 s = glm::normalize(glm::cross(f, glm::dvec3(up)));
        const glm::dvec3 u = glm::cross(s, f);
        const glm::dvec3 point = glm::dvec3(eye) + distance * f + offset.x * s + offset.y * u;
        const glm::vec4 got = viewFromWorld(eye, forward, up) * glm::vec4(glm::vec3(point), 1.0f);
        const glm::vec4 old = glm::lookAt(eye, eye + forward, up) * glm::vec4(glm::vec3(point), 1.0f);
        // Across the view (x, y): what decides the pixel.
        worst = std::max(worst, glm::length(glm::dvec2(got) - offset));
        worstLookAt = std::max(worstLookAt, glm::length(glm::dvec2(old) - offset));
      }
  }
  std::cout << "[ view matrix ] eyes 1000 m out: worst error across the view " << worst
            << " m (glm::lookAt(eye, eye + forward, up): " << worstLookAt << " m)\n";
  // The point itself is rounded to float (6e-5 m at 1000 m) and so is the translation.
  EXPECT_LT(worst, 1e-3);
  EXPECT_GT(worstLookAt, 10.0 * worst);  // the test can tell the two apart
}

TEST(ViewMatrix, NearTheOriginItIsLookAt) {
  const glm::vec3 eye(0.3f, 1.2f, -0.7f), forward = glm::normalize(glm::vec3(0.2f, -0.4f, 1.0f)),
                  up(0.0f, 1.0f, 0.0f);
  const glm::mat4 a = viewFromWorld(eye, forward, up), b = glm::lookAt(eye, eye + forward, up);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], 1e-6f) << c << ", " << r;
}

}  // namespace
}  // namespace lpvlab

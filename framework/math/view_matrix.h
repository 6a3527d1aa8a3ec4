#pragma once
// The view matrix of an eye looking along a direction: glm::lookAt(eye, eye + forward, up)
// without lookAt's round trip through the point eye + forward, whose float subtraction
// (eye + forward) - eye keeps only the digits of forward that survive next to eye: a camera
// 1000 m from the origin looked along a direction off by 6e-5 rad, 6 cm at 1000 m. Here the
// rotation comes from forward itself and the translation from eye alone.

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace lpvlab {

// Rows of the rotation: right = normalize(forward x up), the up orthogonal to forward,
// -forward (glm::lookAt's right-handed view space, looking down -z).
inline glm::mat4 viewFromWorld(const glm::vec3& eye, const glm::vec3& forward, const glm::vec3& up) {
  return glm::lookAt(glm::vec3(0.0f), forward, up) * glm::translate(glm::mat4(1.0f), -eye);
}

}  // namespace lpvlab

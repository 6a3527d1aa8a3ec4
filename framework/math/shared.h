#pragma once
// The GLSL files under shaders/common/ compiled as C++ in double precision. Tests and CPU
// reference implementations call these, so they check the exact functions the kernels run.

#include <glm/glm.hpp>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-variable"

namespace lpvlab::shared {
namespace {
#define LPVLAB_SHARED_CPP 1
using real = double;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using ivec3 = glm::ivec3;
using glm::abs;
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::floor;
using glm::length;
using glm::max;
using glm::min;
using glm::normalize;
using glm::sqrt;

#include "shaders/common/sh.glsl"
#include "shaders/common/grid.glsl"
#include "shaders/common/lights.glsl"

#undef LPVLAB_SHARED_CPP
}  // namespace
}  // namespace lpvlab::shared

#pragma GCC diagnostic pop

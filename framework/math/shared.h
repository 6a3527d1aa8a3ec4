#pragma once
// The GLSL files under shaders/common/ compiled as C++ in double precision. Tests and CPU
// reference implementations call these, so they check the exact functions the kernels run.
//
// A variant's own shared GLSL (e.g. shaders/propagation/standard_faces.glsl) is compiled the
// same way, after this header, between the same two macros:
//   LPVLAB_SHARED_GLSL_BEGIN
//   #include "shaders/propagation/standard_faces.glsl"
//   LPVLAB_SHARED_GLSL_END

#include <glm/glm.hpp>

// Opens lpvlab::shared's anonymous namespace (one per translation unit, so the GLSL functions get
// internal linkage) with the GLSL types and functions in scope, and silences the warnings about
// shared functions a translation unit doesn't call.
#define LPVLAB_SHARED_GLSL_BEGIN                                  \
  _Pragma("GCC diagnostic push")                                  \
  _Pragma("GCC diagnostic ignored \"-Wunused-function\"")         \
  _Pragma("GCC diagnostic ignored \"-Wunused-variable\"")         \
  namespace lpvlab::shared {                                      \
  namespace {
#define LPVLAB_SHARED_GLSL_END \
  }                            \
  }                            \
  _Pragma("GCC diagnostic pop")

// prelude.glsl leaves `real` to C++ when this is defined.
#define LPVLAB_SHARED_CPP 1

LPVLAB_SHARED_GLSL_BEGIN
using real = double;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using ivec2 = glm::ivec2;
using ivec3 = glm::ivec3;
using ivec4 = glm::ivec4;
using mat4 = glm::dmat4;
using glm::abs;
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::floor;
using glm::length;
using glm::max;
using glm::min;
using glm::normalize;
using glm::pow;
using glm::sqrt;

#include "shaders/common/sh.glsl"
#include "shaders/common/grid.glsl"
#include "shaders/common/lights.glsl"
#include "shaders/common/geometry_volume.glsl"
LPVLAB_SHARED_GLSL_END

#pragma once
// The GLSL files under shaders/common/ compiled as C++ in double precision. Tests and CPU
// reference implementations call these, so they check the exact functions the kernels run.
//
// A CPU kernel's translation unit that defines LPVLAB_SHARED_SINGLE_PRECISION before including
// this header gets the same functions in single precision (`real` = float), as the GL kernels
// run them: the speed of float arithmetic and half the memory traffic, and its tests compare it
// with the double-precision functions of another translation unit (internal linkage keeps the
// two apart). One that defines LPVLAB_SHARED_DUAL gets them on dual numbers (`real` = Dual,
// framework/math/dual.h): each result with its derivatives with respect to the parameters seeded.
//
// A variant's own shared GLSL (e.g. shaders/propagation/standard_faces.glsl) is compiled the
// same way, after this header, between the same two macros:
//   LPVLAB_SHARED_GLSL_BEGIN
//   #include "shaders/propagation/standard_faces.glsl"
//   LPVLAB_SHARED_GLSL_END
//
// What shared GLSL avoids, so that both languages and both compilers take it: struct
// constructors (`S(a, b)` is C++20's parenthesised aggregate initialisation, which clang before
// 16 lacks: build the struct member by member) and structured bindings captured by lambdas in
// the C++ around it (clang 14 again; scripts/checked-build.sh compiles everything with it).

#include <glm/glm.hpp>

#ifdef LPVLAB_SHARED_DUAL
#include "framework/math/dual.h"
#endif

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
#if defined(LPVLAB_SHARED_SINGLE_PRECISION)
using real = float;
#elif defined(LPVLAB_SHARED_DUAL)
using real = lpvlab::Dual;
#else
using real = double;
#endif
using vec2 = glm::vec<2, real>;
using vec3 = glm::vec<3, real>;
using vec4 = glm::vec<4, real>;
using ivec2 = glm::ivec2;
using ivec3 = glm::ivec3;
using ivec4 = glm::ivec4;
using mat4 = glm::mat<4, 4, real>;
using glm::abs;
using glm::any;
using glm::clamp;
using glm::cross;
using glm::dot;
#ifdef LPVLAB_SHARED_DUAL
using lpvlab::dual_number::floor;  // GLM's passes std::floor, which has no Dual overload
#else
using glm::floor;
#endif
using glm::greaterThan;
using glm::length;
using glm::lessThan;
using glm::max;
using glm::min;
using glm::normalize;
using glm::pow;
using glm::reflect;
using glm::sqrt;
using glm::step;

#include "shaders/common/sh.glsl"
#include "shaders/common/grid.glsl"
#include "shaders/common/lights.glsl"
#include "shaders/common/geometry_volume.glsl"
LPVLAB_SHARED_GLSL_END

// Shared GLSL/C++ prelude. Files under shaders/common/ that include this are written in the
// common subset of GLSL 4.50 and C++ with GLM: no swizzles, no out-parameters, no arrays,
// explicit real(...) conversions. In C++ (framework/math/shared.h) `real` is double, so tests
// run the very functions the kernels run, in double precision.
#ifndef LPVLAB_PRELUDE_GLSL
#define LPVLAB_PRELUDE_GLSL

#ifndef LPVLAB_SHARED_CPP
#define real float
#endif

const real PI = 3.14159265358979323846;

#endif

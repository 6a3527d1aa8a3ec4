// Where every kernel that reads the light and view records (lights_gpu.glsl) finds them, shared
// with C++ (framework/pipeline/light_views.h binds them): storage-buffer bindings, defined here
// once. Plain `const int`s, valid GLSL and C++.
#ifndef LPVLAB_LIGHT_RECORDS_INTERFACE_GLSL
#define LPVLAB_LIGHT_RECORDS_INTERFACE_GLSL
const int BUFFER_LIGHTS = 1;  // storage buffer: GpuLight[]
const int BUFFER_VIEWS = 2;   // storage buffer: GpuView[]
#endif

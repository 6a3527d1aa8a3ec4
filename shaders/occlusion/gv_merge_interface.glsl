// The interface of gv_merge.comp, shared with its C++ side (variants/occlusion/geometry_volume_gl.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 64;   // work-group size
const int GROUP_SIZE_Y = 1;
const int GROUP_SIZE_Z = 1;
const int BUFFER_TARGET = 0;   // storage buffer: Target
const int BUFFER_OTHER = 1;    // storage buffer: Other
const int BUFFER_TARGET_ALBEDO = 2;  // storage buffer: TargetAlbedo (read with WITH_ALBEDO only)
const int BUFFER_OTHER_ALBEDO = 3;   // storage buffer: OtherAlbedo
const int LOCATION_CELLS = 0;  // uniform int cells

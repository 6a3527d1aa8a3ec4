// The interface of directed_release.comp, shared with its C++ side (variants/propagation/directed_gl.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 4;         // work-group size
const int GROUP_SIZE_Y = 4;
const int GROUP_SIZE_Z = 4;
const int BUFFER_NORMALS = 0;       // storage buffer: Normals
const int BUFFER_ATTACHED = 1;      // storage buffer: Attached
const int BUFFER_FREE = 2;          // storage buffer: Free
const int LOCATION_RESOLUTION = 0;  // uniform ivec3 resolution
const int LOCATION_RELEASE_ALL = 1; // uniform int releaseAll

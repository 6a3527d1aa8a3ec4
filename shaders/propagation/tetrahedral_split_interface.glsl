// The interface of tetrahedral_split.comp, shared with its C++ side (variants/propagation/tetrahedral_gl.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 4;         // work-group size
const int GROUP_SIZE_Y = 4;
const int GROUP_SIZE_Z = 4;
const int BUFFER_CUBES = 0;         // storage buffer: Cubes
const int BUFFER_CELLS = 1;         // storage buffer: Cells
const int LOCATION_RESOLUTION = 0;  // uniform ivec3 resolution

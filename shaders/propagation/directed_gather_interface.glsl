// The interface of directed_gather.comp, shared with its C++ side (variants/propagation/directed_gl.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 4;                     // work-group size
const int GROUP_SIZE_Y = 4;
const int GROUP_SIZE_Z = 4;
const int BUFFER_SOURCE = 0;                    // storage buffer: Source
const int BUFFER_TARGET = 1;                    // storage buffer: Target
const int BUFFER_ACCUMULATED = 2;               // storage buffer: Accumulated
const int BUFFER_NORMALS = 3;                   // storage buffer: Normals
const int BUFFER_GEOMETRY_VOLUME = 4;           // storage buffer: GeometryVolume
const int LOCATION_RESOLUTION = 0;              // uniform ivec3 resolution
const int LOCATION_OCCLUDE_THIS_ITERATION = 1;  // uniform int occludeThisIteration

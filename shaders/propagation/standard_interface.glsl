// The interface of standard_gather.comp, standard_gather_tiled.comp and standard_scatter.comp, shared with their C++ side (variants/propagation/standard_gl.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 4;                       // work-group size
const int GROUP_SIZE_Y = 4;
const int GROUP_SIZE_Z = 4;
const int BUFFER_SOURCE = 0;                      // storage buffer: Source
const int BUFFER_TARGET = 1;                      // storage buffer: Target
const int BUFFER_ACCUMULATED = 2;                 // storage buffer: Accumulated
const int BUFFER_GEOMETRY_VOLUME = 3;             // storage buffer: GeometryVolume
const int BUFFER_GEOMETRY_VOLUME_ALBEDO = 4;      // storage buffer: GeometryVolumeAlbedo
const int LOCATION_RESOLUTION = 0;                // uniform ivec3 resolution
const int LOCATION_ITERATION = 1;                 // uniform int iteration
const int LOCATION_FIRST_OCCLUDED_ITERATION = 2;  // uniform int firstOccludedIteration

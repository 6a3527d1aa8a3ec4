// The interface of render.comp, shared with its C++ side (variants/rendering/subsurface.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 8;           // work-group size
const int GROUP_SIZE_Y = 8;
const int GROUP_SIZE_Z = 1;
const int UNIT_G_POSITION = 0;        // texture unit: sampler2D gPosition
const int UNIT_G_NORMAL = 1;          // texture unit: sampler2D gNormal
const int UNIT_TRANSLUCENT_MASK = 2;  // texture unit: sampler2D translucentMask
const int BUFFER_ACCUMULATED = 0;     // storage buffer: Accumulated
const int IMAGE_INDIRECT = 0;         // image unit: image2D indirect
const int LOCATION_GRID_ORIGIN = 0;   // uniform vec3 gridOrigin
const int LOCATION_CELL_SIZE = 1;     // uniform float cellSize
const int LOCATION_RESOLUTION = 2;    // uniform ivec3 resolution

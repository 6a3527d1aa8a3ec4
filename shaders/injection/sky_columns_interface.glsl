// The interface of sky_columns.comp, shared with its C++ side (variants/injection/sky_columns.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 8;            // work-group size
const int GROUP_SIZE_Y = 8;
const int GROUP_SIZE_Z = 1;
const int UNIT_SKY_DEPTH = 0;          // texture unit: sampler2D skyDepth
const int BUFFER_GRID = 0;             // storage buffer: Grid
const int LOCATION_GRID_ORIGIN = 0;    // uniform vec3 gridOrigin
const int LOCATION_CELL_SIZE = 1;      // uniform float cellSize
const int LOCATION_RESOLUTION = 2;     // uniform ivec3 resolution
const int LOCATION_SHIFT_CELLS = 3;    // uniform float shiftCells
const int LOCATION_SKY_PER_TEXEL = 4;  // uniform vec3 skyPerTexel
const int LOCATION_EVERY_FREE_CELL = 5;  // uniform int everyFreeCell (0: the lowest free cell only)

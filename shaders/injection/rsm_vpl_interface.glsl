// The interface of rsm_vpl.comp, shared with its C++ side (variants/injection/rsm_vpl_gl.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 8;             // work-group size
const int GROUP_SIZE_Y = 8;
const int GROUP_SIZE_Z = 1;
const int UNIT_RSM_POSITION = 0;        // texture unit: sampler2DArray rsmPosition
const int UNIT_RSM_NORMAL = 1;          // texture unit: sampler2DArray rsmNormal
const int UNIT_RSM_FLUX = 2;            // texture unit: sampler2DArray rsmFlux
const int BUFFER_GRID = 0;              // storage buffer: Grid
const int BUFFER_NORMALS = 1;           // storage buffer: Normals
const int LOCATION_GRID_ORIGIN = 0;     // uniform vec3 gridOrigin
const int LOCATION_CELL_SIZE = 1;       // uniform float cellSize
const int LOCATION_RESOLUTION = 2;      // uniform ivec3 resolution
const int LOCATION_SHIFT_CELLS = 3;     // uniform float shiftCells
const int LOCATION_RSM_RESOLUTION = 4;  // uniform int rsmResolution

// The interface of gv_surfel.glsl, shared with its C++ side (variants/occlusion/geometry_volume_gl.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
// The surfels' textures, bound alike by both injection kernels (gv_camera.comp: the G-buffer;
// gv_rsm.comp: the RSM): position, normal, and what gives the albedo.
const int UNIT_SURFEL_POSITION = 0;
const int UNIT_SURFEL_NORMAL = 1;
const int UNIT_SURFEL_ALBEDO = 2;
const int BUFFER_TARGET = 0;            // storage buffer: Target
const int LOCATION_GV_ORIGIN = 0;       // uniform vec3 gvOrigin
const int LOCATION_CELL_SIZE = 1;       // uniform float cellSize
const int LOCATION_GV_RESOLUTION = 2;   // uniform ivec3 gvResolution
const int LOCATION_BLOCKING_SCALE = 6;  // uniform float blockingScale
const int BUFFER_ALBEDO = 3;            // storage buffer: Albedo

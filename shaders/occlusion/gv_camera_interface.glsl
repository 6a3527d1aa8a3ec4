// The interface of gv_camera.comp, shared with its C++ side (variants/occlusion/geometry_volume_gl.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 8;              // work-group size
const int GROUP_SIZE_Y = 8;
const int GROUP_SIZE_Z = 1;
const int LOCATION_CAMERA_POSITION = 3;  // uniform vec3 cameraPosition
const int LOCATION_TEXEL_EDGE = 4;       // uniform float texelEdge
const int LOCATION_SIZE = 5;             // uniform ivec2 size

// The interface of gbuffer.frag, shared with its C++ side (framework/pipeline/raster_passes.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int LOCATION_CAMERA_POSITION = 2;  // uniform vec3 cameraPosition
const int LOCATION_CAMERA_FORWARD = 3;   // uniform vec3 cameraForward

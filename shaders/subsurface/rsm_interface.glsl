// The interface of rsm.frag, shared with its C++ side (variants/rendering/subsurface.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int LOCATION_VIEW_INDEX = 2;  // uniform int viewIndex
const int LOCATION_RESOLUTION = 3;  // uniform int resolution

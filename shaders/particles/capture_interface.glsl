// The interface of capture.frag, shared with its C++ side (framework/particles/light_field.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int LOCATION_VIEW_DIRECTION = 2;  // uniform vec3 viewDirection (towards the viewer, unit)

// The interface of translucency.glsl, shared with its C++ side (variants/rendering/subsurface.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int BUFFER_TRANSLUCENCY = 3;  // storage buffer: Translucency

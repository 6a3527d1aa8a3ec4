// The interface of restrict.comp, shared with its C++ side (framework/pipeline/cascade.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 4;           // work-group size
const int GROUP_SIZE_Y = 4;
const int GROUP_SIZE_Z = 4;
const int BUFFER_CHILD = 0;           // storage buffer: Child
const int BUFFER_PARENT = 1;          // storage buffer: Parent
const int LOCATION_RESOLUTION = 0;    // uniform ivec3 resolution
const int LOCATION_CHILD_OFFSET = 1;  // uniform ivec3 childOffset

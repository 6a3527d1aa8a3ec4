// The interface of the hemicube's item-buffer pass (framework/radiosity/hemicube.cpp): vertex
// attributes and uniform locations, defined here once. Plain `const int`s, valid GLSL and C++.
const int HEMICUBE_ATTRIBUTE_POSITION = 0;  // vec3 world position of a patch corner
const int HEMICUBE_ATTRIBUTE_PATCH = 1;     // uint patch index (the same for its three corners)
const int HEMICUBE_LOCATION_CLIP_FROM_WORLD = 0;  // uniform mat4

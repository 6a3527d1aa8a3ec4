// The interface of material.glsl, shared with its C++ side (framework/pipeline/scene_gpu.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int BUFFER_MATERIALS = 0;         // storage buffer: Materials
const int UNIT_BASE_COLOR_TEXTURE = 0;  // texture unit: sampler2D baseColorTexture
const int LOCATION_MATERIAL_INDEX = 1;  // uniform int materialIndex

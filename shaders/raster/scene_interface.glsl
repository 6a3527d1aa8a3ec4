// The interface of scene.vert, shared with its C++ side (the vertex layout of
// framework/pipeline/scene_gpu.cpp, and every pass that rasterises the scene):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int ATTRIBUTE_POSITION = 0;        // vertex attribute: vec3 position
const int ATTRIBUTE_NORMAL = 1;          // vertex attribute: vec3 normal
const int ATTRIBUTE_UV = 2;              // vertex attribute: vec2 uv
const int ATTRIBUTE_COLOR = 3;           // vertex attribute: vec3 color (Mesh::colors, white without)
const int LOCATION_CLIP_FROM_WORLD = 0;  // uniform mat4 clipFromWorld

// The interface of cascade_blend.glsl, shared with its C++ side (framework/pipeline/cascade_blend.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int CASCADE_MAX_LEVELS = 8;              // levels a rendering kernel can blend
const int LOCATION_CASCADE_LEVEL = 40;        // uniform vec4 cascadeLevel[CASCADE_MAX_LEVELS]
const int LOCATION_CASCADE_LEVELS = 48;       // uniform int cascadeLevels
const int LOCATION_CASCADE_CURRENT = 49;      // uniform int cascadeCurrent
const int LOCATION_CASCADE_BLEND_CELLS = 50;  // uniform float cascadeBlendCells
const int LOCATION_CASCADE_RESOLUTION = 51;   // uniform ivec3 cascadeResolution

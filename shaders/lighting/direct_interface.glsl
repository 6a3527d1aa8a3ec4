// The interface of direct.comp, shared with its C++ side (framework/pipeline/direct_lighting.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 8;                   // work-group size
const int GROUP_SIZE_Y = 8;
const int GROUP_SIZE_Z = 1;
const int UNIT_G_POSITION = 0;                // texture unit: sampler2D gPosition
const int UNIT_G_NORMAL = 1;                  // texture unit: sampler2D gNormal
const int UNIT_G_ALBEDO = 2;                  // texture unit: sampler2D gAlbedo
const int UNIT_G_EMISSION = 3;                // texture unit: sampler2D gEmission
const int UNIT_SHADOW_MAPS = 4;               // texture unit: sampler2DArrayShadow shadowMaps
const int IMAGE_OUT_DIRECT = 0;               // image unit: image2D outDirect
const int LOCATION_LIGHT_COUNT = 0;           // uniform int lightCount
const int LOCATION_SHADOW_RESOLUTION = 1;     // uniform int shadowResolution
const int LOCATION_NORMAL_OFFSET_TEXELS = 2;  // uniform float normalOffsetTexels
const int LOCATION_DEPTH_BIAS = 3;            // uniform float depthBias

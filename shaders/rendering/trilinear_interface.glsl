// The interface of trilinear.comp, shared with its C++ side (variants/rendering/trilinear_gl.cpp):
// its binding points and uniform locations (and a kernel's work-group size), defined here once. Plain
// `const int`s, valid GLSL and C++ (C++ includes this inside a namespace of its own).
const int GROUP_SIZE_X = 8;                    // work-group size
const int GROUP_SIZE_Y = 8;
const int GROUP_SIZE_Z = 1;
const int UNIT_G_POSITION = 0;                 // texture unit: sampler2D gPosition
const int UNIT_G_NORMAL = 1;                   // texture unit: sampler2D gNormal
const int UNIT_G_ALBEDO = 2;                   // texture unit: sampler2D gAlbedo
const int BUFFER_ACCUMULATED = 0;              // storage buffer: Accumulated
const int IMAGE_OUT_INDIRECT = 0;              // image unit: image2D outIndirect
const int LOCATION_GRID_ORIGIN = 0;            // uniform vec3 gridOrigin
const int LOCATION_CELL_SIZE = 1;              // uniform float cellSize
const int LOCATION_RESOLUTION = 2;             // uniform ivec3 resolution
const int LOCATION_NORMAL_OFFSET_CELLS = 3;    // uniform float normalOffsetCells
const int LOCATION_LEAK_DAMPING_STRENGTH = 4;  // uniform float leakDampingStrength
const int LOCATION_CAMERA_POSITION = 5;        // uniform vec3 cameraPosition
const int LOCATION_SPECULAR_ALBEDO = 6;        // uniform float specularAlbedo
const int LOCATION_PHONG_EXPONENT = 7;         // uniform float phongExponent
const int LOCATION_MARCH_STEP_CELLS = 8;       // uniform float marchStepCells
const int LOCATION_MARCH_SAMPLES = 9;          // uniform int marchSamples
const int LOCATION_INDIRECT_SCALE = 10;        // uniform float indirectScale

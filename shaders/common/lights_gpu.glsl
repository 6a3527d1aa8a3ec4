// GPU records of lights and light views (std430; mirrored by framework/pipeline/light_views.h).
#ifndef LPVLAB_LIGHTS_GPU_GLSL
#define LPVLAB_LIGHTS_GPU_GLSL

const int LIGHT_POINT = 0;
const int LIGHT_SPOT = 1;
const int LIGHT_DIRECTIONAL = 2;

struct GpuLight {
  vec4 positionType;       // xyz: position (m); w: LIGHT_* type
  vec4 directionCosOuter;  // xyz: unit direction the light travels; w: cos(outer cone half-angle)
  vec4 intensityCosInner;  // rgb: colour * intensity (W/sr, or W/m^2 for directional); w: cos(inner)
  ivec4 viewOfFace0123;    // view index per cube face +x,-x,+y,-y (-1: face culled); directional: x
  ivec4 viewOfFace45;      // +z,-z
};

struct GpuView {
  mat4 clipFromWorld;
  vec4 params;             // x: 1 = orthographic; y: tan(half fov) or the box's width (m); z: light
};

#endif

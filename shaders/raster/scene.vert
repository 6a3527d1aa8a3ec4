#version 450
// Every raster pass draws the scene with this vertex shader; positions are already in world space.
#include "scene_interface.glsl"
layout(location = ATTRIBUTE_POSITION) in vec3 position;
layout(location = ATTRIBUTE_NORMAL) in vec3 normal;
layout(location = ATTRIBUTE_UV) in vec2 uv;
layout(location = ATTRIBUTE_COLOR) in vec3 color;

layout(location = LOCATION_CLIP_FROM_WORLD) uniform mat4 clipFromWorld;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec2 texcoord;
layout(location = 3) out vec3 vertexColor;  // multiplies the material's albedo

void main() {
  worldPosition = position;
  worldNormal = normal;
  texcoord = uv;
  vertexColor = color;
  gl_Position = clipFromWorld * vec4(position, 1.0);
}

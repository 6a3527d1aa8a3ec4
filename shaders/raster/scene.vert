#version 450
// Every raster pass draws the scene with this vertex shader; positions are already in world space.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;

layout(location = 0) uniform mat4 clipFromWorld;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec2 texcoord;

void main() {
  worldPosition = position;
  worldNormal = normal;
  texcoord = uv;
  gl_Position = clipFromWorld * vec4(position, 1.0);
}

#version 450
// Geometry-volume injection from the camera's G-buffer: every covered pixel is a surfel whose
// area is its footprint on the surface (surfel_area.glsl, perspective view), with the G-buffer's
// albedo (WITH_ALBEDO).
#extension GL_EXT_shader_atomic_float : require
#include "gv_surfel.glsl"
#include "surfel_area.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D gPosition;
layout(binding = 1) uniform sampler2D gNormal;  // w: view depth
layout(binding = 2) uniform sampler2D gAlbedo;
layout(location = 3) uniform vec3 cameraPosition;
layout(location = 4) uniform float texelEdge;   // 2 tan(vertical fov / 2) / height
layout(location = 5) uniform ivec2 size;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  vec4 position = texelFetch(gPosition, pixel, 0);
  if (position.w == 0.0) return;
  vec4 normalDepth = texelFetch(gNormal, pixel, 0);
  vec3 n = normalDepth.xyz;
  vec3 toEye = cameraPosition - position.xyz;
  float distance = length(toEye);
  float area = perspectiveSurfelArea(texelEdge, normalDepth.w, distance, dot(n, toEye) / distance);
  vec3 albedo = WITH_ALBEDO ? texelFetch(gAlbedo, pixel, 0).rgb : vec3(0.0);
  gvAddSurfel(position.xyz, n, area, albedo, true);
}

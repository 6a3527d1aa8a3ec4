#version 450
// Geometry-volume injection from the camera's G-buffer: every covered pixel is a surfel whose
// area is its footprint on the surface (gv_surfel_sources.glsl, perspective view), with the
// G-buffer's albedo (WITH_ALBEDO).
#extension GL_EXT_shader_atomic_float : require
#include "gv_surfel.glsl"
#include "gv_surfel_sources.glsl"

#include "gv_camera_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(binding = UNIT_SURFEL_POSITION) uniform sampler2D gPosition;
layout(binding = UNIT_SURFEL_NORMAL) uniform sampler2D gNormal;  // w: view depth
layout(binding = UNIT_SURFEL_ALBEDO) uniform sampler2D gAlbedo;
layout(location = LOCATION_CAMERA_POSITION) uniform vec3 cameraPosition;
layout(location = LOCATION_TEXEL_EDGE) uniform float texelEdge;   // 2 tan(vertical fov / 2) / height
layout(location = LOCATION_SIZE) uniform ivec2 size;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  vec4 position = texelFetch(gPosition, pixel, 0);
  if (position.w == 0.0) return;
  vec4 normalDepth = texelFetch(gNormal, pixel, 0);
  float area = gvCameraSurfelArea(position.xyz, normalDepth.xyz, normalDepth.w, cameraPosition,
                                  texelEdge);
  vec3 albedo = WITH_ALBEDO ? texelFetch(gAlbedo, pixel, 0).rgb : vec3(0.0);
  gvAddSurfel(position.xyz, normalDepth.xyz, area, albedo, true);
}

#version 450
// Geometry-volume injection from the reflective shadow maps: every covered RSM texel is a surfel
// whose area is its footprint on the surface (surfel_area.glsl), perspective for the cube faces
// of point and spot lights, orthographic for a directional light's box.
#extension GL_EXT_shader_atomic_float : require
#include "gv_surfel.glsl"
#include "surfel_area.glsl"
#include "../common/lights_gpu.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2DArray rsmPosition;
layout(binding = 1) uniform sampler2DArray rsmNormal;
layout(std430, binding = 1) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = 2) readonly buffer Views { GpuView views[]; };
layout(location = 3) uniform int rsmResolution;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (texel.x >= rsmResolution || texel.y >= rsmResolution) return;
  vec4 position = texelFetch(rsmPosition, texel, 0);
  if (position.w == 0.0) return;
  vec3 p = position.xyz;
  vec3 n = texelFetch(rsmNormal, texel, 0).xyz;
  GpuView view = views[texel.z];
  GpuLight light = lights[int(view.params.z)];
  float area;
  if (view.params.x == 1.0) {
    area = orthographicSurfelArea(view.params.y / float(rsmResolution),
                                  dot(n, -light.directionCosOuter.xyz));
  } else {
    vec3 toLight = light.positionType.xyz - p;
    float distance = length(toLight);
    float depth = (view.clipFromWorld * vec4(p, 1.0)).w;  // distance along the face's axis
    area = perspectiveSurfelArea(2.0 * view.params.y / float(rsmResolution), depth, distance,
                                 dot(n, toLight) / distance);
  }
  gvAddSurfel(p, n, area);
}

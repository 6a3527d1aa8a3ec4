#version 450
// Reflective shadow map of one light view. Each texel stores the surface it sees and the flux
// that surface patch reflects: albedo * (light's intensity towards it) * (texel solid angle) for
// point and spot lights, albedo * irradiance * (texel area) for directional ones. The patch's
// slope cancels: its area times cos / r^2 is exactly the texel's solid angle.
#include "material.glsl"
#include "../common/lights_gpu.glsl"
#include "../common/lights.glsl"

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 texcoord;

layout(std430, binding = 1) readonly buffer Lights { GpuLight lights[]; };
layout(std430, binding = 2) readonly buffer Views { GpuView views[]; };
layout(location = 2) uniform int viewIndex;
layout(location = 3) uniform int resolution;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outFlux;

void main() {
  vec3 albedo = materialAlbedo(texcoord);
  GpuView view = views[viewIndex];
  GpuLight light = lights[int(view.params.z)];
  vec3 n = normalize(worldNormal);
  vec3 flux;
  if (view.params.x > 0.5) {
    if (dot(n, light.directionCosOuter.xyz) > 0.0) n = -n;
    float texelSize = view.params.y / float(resolution);
    flux = albedo * light.intensityCosInner.rgb * texelSize * texelSize;
  } else {
    vec3 toSurface = normalize(worldPosition - light.positionType.xyz);
    if (dot(n, toSurface) > 0.0) n = -n;
    // Texel centre in the view's image plane at unit distance (tan(fov/2) = params.y).
    vec2 plane = (2.0 * gl_FragCoord.xy / float(resolution) - 1.0) * view.params.y;
    float texel = 2.0 * view.params.y / float(resolution);
    float solidAngle = texel * texel / pow(1.0 + dot(plane, plane), 1.5);
    float falloff = 1.0;
    if (int(light.positionType.w) == LIGHT_SPOT)
      falloff = spotFalloff(dot(toSurface, light.directionCosOuter.xyz), light.intensityCosInner.w,
                            light.directionCosOuter.w);
    flux = albedo * light.intensityCosInner.rgb * falloff * solidAngle;
  }
  outPosition = vec4(worldPosition, 1.0);
  outNormal = vec4(n, 0.0);
  outFlux = vec4(flux, 1.0);
}

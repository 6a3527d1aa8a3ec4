// The light arriving at the surface patch one RSM texel sees, shared by the reflective shadow map
// (raster/rsm.frag: albedo times this is the reflected flux) and the subsurface LPV's RSM
// (subsurface/rsm.frag: transmittance times this enters translucent objects).
//   point and spot views: I(w) * (texel solid angle) [* spot falloff]; the patch's slope cancels:
//     its area times cos / r^2 is exactly the texel's solid angle;
//   directional views: irradiance (on a surface facing the light) * texel area.
// The including shader declares the Lights and Views buffers (lights_gpu.glsl records).
#ifndef LPVLAB_RSM_TEXEL_GLSL
#define LPVLAB_RSM_TEXEL_GLSL
#include "../common/lights_gpu.glsl"
#include "../common/lights.glsl"

struct RsmTexelLight {
  vec3 flux;    // W per channel arriving at the texel's patch
  vec3 normal;  // the surface's unit normal turned to face the light
};

RsmTexelLight rsmTexelLight(GpuView view, GpuLight light, vec3 worldPosition, vec3 worldNormal,
                            vec2 fragCoord, int resolution) {
  vec3 n = normalize(worldNormal);
  if (view.params.x > 0.5) {
    if (dot(n, light.directionCosOuter.xyz) > 0.0) n = -n;
    float texelSize = view.params.y / float(resolution);
    return RsmTexelLight(light.intensityCosInner.rgb * texelSize * texelSize, n);
  }
  vec3 toSurface = normalize(worldPosition - light.positionType.xyz);
  if (dot(n, toSurface) > 0.0) n = -n;
  // Texel centre in the view's image plane at unit distance (tan(fov/2) = params.y).
  vec2 plane = (2.0 * fragCoord / float(resolution) - 1.0) * view.params.y;
  float texel = 2.0 * view.params.y / float(resolution);
  float solidAngle = texel * texel / pow(1.0 + dot(plane, plane), 1.5);
  float falloff = 1.0;
  if (int(light.positionType.w) == LIGHT_SPOT)
    falloff = spotFalloff(dot(toSurface, light.directionCosOuter.xyz), light.intensityCosInner.w,
                          light.directionCosOuter.w);
  return RsmTexelLight(light.intensityCosInner.rgb * falloff * solidAngle, n);
}

#endif

// The light arriving at the surface patch one RSM texel sees, shared by the reflective shadow map
// (raster/rsm.frag: albedo times this is the reflected flux), the subsurface LPV's RSM
// (subsurface/rsm.frag: transmittance times this enters translucent objects) and the geometry
// volume's albedo (occlusion/gv_rsm_surfel.glsl, on GL and on the CPU).
//   point and spot views: I(w) * (texel solid angle) [* spot falloff]; the patch's slope cancels:
//     its area times cos / r^2 is exactly the texel's solid angle;
//   directional views: irradiance (on a surface facing the light) * texel area.
// Written in the shared subset (prelude.glsl): C++ compiles it too. The including shader declares
// the Lights and Views buffers (lights_gpu.glsl records).
#ifndef LPVLAB_RSM_TEXEL_GLSL
#define LPVLAB_RSM_TEXEL_GLSL
#include "../common/lights_gpu.glsl"
#include "../common/lights.glsl"

struct RsmTexelLight {
  vec3 flux;    // W per channel arriving at the texel's patch
  vec3 normal;  // the surface's unit normal turned to face the light
};

// Built member by member (shared.h: no struct constructors in shared GLSL).
RsmTexelLight makeRsmTexelLight(vec3 flux, vec3 normal) {
  RsmTexelLight result;
  result.flux = flux;
  result.normal = normal;
  return result;
}

RsmTexelLight rsmTexelLight(GpuView view, GpuLight light, vec3 worldPosition, vec3 worldNormal,
                            vec2 fragCoord, int resolution) {
  vec3 n = normalize(worldNormal);
  vec3 intensity = vec3(light.intensityCosInner);
  vec3 lightDirection = vec3(light.directionCosOuter);
  if (view.params.x > 0.5) {
    if (dot(n, lightDirection) > 0.0) n = -n;
    real texelSize = real(view.params.y) / real(resolution);
    return makeRsmTexelLight(intensity * (texelSize * texelSize), n);
  }
  vec3 toSurface = normalize(worldPosition - vec3(light.positionType));
  if (dot(n, toSurface) > 0.0) n = -n;
  // Texel centre in the view's image plane at unit distance (tan(fov/2) = params.y).
  vec2 plane = (real(2.0) * fragCoord / real(resolution) - real(1.0)) * real(view.params.y);
  real texel = 2.0 * real(view.params.y) / real(resolution);
  real solidAngle = texel * texel / pow(1.0 + dot(plane, plane), real(1.5));
  real falloff = 1.0;
  if (int(light.positionType.w) == LIGHT_SPOT)
    falloff = spotFalloff(dot(toSurface, lightDirection), light.intensityCosInner.w,
                          light.directionCosOuter.w);
  return makeRsmTexelLight(intensity * (falloff * solidAngle), n);
}

#endif

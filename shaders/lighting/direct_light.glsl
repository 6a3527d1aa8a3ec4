// Direct light at a surface point: Lambertian reflection of each light, shadow-mapped, plus the
// surface's own emission. Out: radiance, W/(m^2 sr).
//   L = emission + albedo / pi * sum over lights of E_light * visibility
//   point/spot: E = I * falloff * cos(theta) / r^2;  directional: E = E_perp * cos(theta)
// Written in the shared subset (common/prelude.glsl): the GL kernel (direct.comp) and the CPU
// kernel (framework/pipeline/direct_lighting_cpu.cpp) call these same functions. The includer
// defines, before including this file, how the records and the shadow maps are read:
//   GpuLight directLight(int i)              light record i (lights_gpu.glsl)
//   GpuView directView(int v)                view record v
//   real shadowTaps3x3(int view, vec2 uv, real reference)
//                                            the mean of nine 2x2 depth-compare taps of view's
//                                            shadow map, one texel apart around window position
//                                            uv: GL's LINEAR, LEQUAL filtering (GL: the texture
//                                            unit, tap by tap; CPU: shadow_tap.glsl)
// and, if it defines LPVLAB_DIRECT_LIGHT_VISIBILITY, lightVisibility (below) itself: the CPU
// kernel then reads exact shadow rays' results where [light_maps] shadows = "rays".
#ifndef LPVLAB_DIRECT_LIGHT_GLSL
#define LPVLAB_DIRECT_LIGHT_GLSL
#include "../common/lights_gpu.glsl"
#include "../common/lights.glsl"

int cubeFace(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x > 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y > 0.0 ? 2 : 3;
  return d.z > 0.0 ? 4 : 5;
}

int viewOfFace(GpuLight light, int face) {
  return face < 4 ? light.viewOfFace0123[face] : light.viewOfFace45[face - 4];
}

// Fraction of a 3x3 tap of the shadow map of `view` that sees p: the taps one shadow texel apart
// around p's window position, each a 2x2 depth comparison (shadowTaps3x3).
real shadowVisibility(int view, vec3 p, int resolution, real depthBias) {
  vec4 clip = directView(view).clipFromWorld * vec4(p, 1.0);
  vec3 window = vec3(clip) / clip.w * real(0.5) + real(0.5);
  // A directional light's view that follows the camera (light_views.h) covers a box: outside it
  // the map knows nothing of occluders, and lpvlab does not light what it cannot shadow. (A view
  // around the whole scene, and a cube face chosen by direction, hold every point they are asked
  // about.)
  if (directView(view).params.x == real(1.0) &&
      (min(window.x, window.y) < real(0.0) || max(window.x, window.y) > real(1.0)))
    return real(0.0);
  return shadowTaps3x3(view, vec2(window.x, window.y), window.z - depthBias);
}

#ifndef LPVLAB_DIRECT_LIGHT_VISIBILITY
// How much of light `light` reaches p: its shadow map's filtered lookup from p moved `offset`
// metres along n.
real lightVisibility(int light, int view, vec3 p, vec3 n, real offset, int resolution,
                     real depthBias) {
  return shadowVisibility(view, p + n * offset, resolution, depthBias);
}
#endif

// The direct radiance of a surface point p (unit normal n, Lambertian albedo, emission), from
// `lightCount` lights whose shadow maps have shadowResolution^2 texels; the shadow lookup moves
// normalOffsetTexels shadow texels along n and compares depthBias (window units) nearer.
vec3 directRadiance(vec3 p, vec3 n, vec3 albedo, vec3 emission, int lightCount,
                    int shadowResolution, real normalOffsetTexels, real depthBias) {
  vec3 irradiance = vec3(0.0);
  for (int i = 0; i < lightCount; ++i) {
    GpuLight light = directLight(i);
    int type = int(light.positionType.w);
    vec3 toLight;
    vec3 e;
    int view;
    real texelWorld;
    if (type == LIGHT_DIRECTIONAL) {
      toLight = -vec3(light.directionCosOuter);
      e = vec3(light.intensityCosInner);
      view = light.viewOfFace0123.x;
      texelWorld = view >= 0 ? real(directView(view).params.y) / real(shadowResolution) : real(0.0);
    } else {
      vec3 d = vec3(light.positionType) - p;
      real r2 = max(dot(d, d), real(1e-12));
      real r = sqrt(r2);
      toLight = d / r;
      real falloff = type == LIGHT_SPOT
          ? spotFalloff(dot(-toLight, vec3(light.directionCosOuter)), light.intensityCosInner.w,
                        light.directionCosOuter.w)
          : real(1.0);
      e = vec3(light.intensityCosInner) * (falloff / r2);
      view = viewOfFace(light, cubeFace(-d));
      // A texel of a 90-degree face spans about 2 r / N metres at distance r.
      texelWorld = real(2.0) * r / real(shadowResolution);
    }
    real cosTheta = dot(n, toLight);
    if (cosTheta <= 0.0 || view < 0 || e == vec3(0.0)) continue;
    irradiance += e * (cosTheta * lightVisibility(i, view, p, n, normalOffsetTexels * texelWorld,
                                                  shadowResolution, depthBias));
  }
  return emission + albedo / PI * irradiance;
}

#endif

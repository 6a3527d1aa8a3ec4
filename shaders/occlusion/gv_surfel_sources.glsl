// What a G-buffer pixel or an RSM texel is as a geometry-volume surfel (thesis 4.3): its area
// (surfel_area.glsl) and, for an RSM texel, its albedo. Written in the shared subset
// (common/prelude.glsl): the GL kernels (gv_camera.comp, gv_rsm.comp) and the CPU kernel
// (variants/occlusion/geometry_volume_cpu.cpp) call these same functions.
#ifndef LPVLAB_GV_SURFEL_SOURCES_GLSL
#define LPVLAB_GV_SURFEL_SOURCES_GLSL
#include "surfel_area.glsl"
#include "../raster/rsm_texel.glsl"

// A camera surfel: the G-buffer pixel at `position`, normal n and view depth `depth`, seen from
// `cameraPosition` through pixels of edge `texelEdge` (2 tan(vertical fov / 2) / height).
real gvCameraSurfelArea(vec3 position, vec3 n, real depth, vec3 cameraPosition, real texelEdge) {
  vec3 toEye = cameraPosition - position;
  real distance = length(toEye);
  return perspectiveSurfelArea(texelEdge, depth, distance, dot(n, toEye) / distance);
}

// An RSM surfel: the texel at p, normal n, of `view` (perspective for the cube faces of point and
// spot lights, orthographic for a directional light's box) of `light`.
real gvRsmSurfelArea(GpuView view, GpuLight light, vec3 p, vec3 n, int rsmResolution) {
  if (view.params.x == 1.0)
    return orthographicSurfelArea(real(view.params.y) / real(rsmResolution),
                                  dot(n, -vec3(light.directionCosOuter)));
  vec3 toLight = vec3(light.positionType) - p;
  real distance = length(toLight);
  real depth = (view.clipFromWorld * vec4(p, 1.0)).w;  // distance along the face's axis
  return perspectiveSurfelArea(2.0 * real(view.params.y) / real(rsmResolution), depth, distance,
                               dot(n, toLight) / distance);
}

struct GvSurfelAlbedo {
  vec3 albedo;
  bool known;  // false: the surfel adds blocking only
};

// An RSM surfel's albedo: its reflected flux (the RSM texel) over the flux arriving at it
// (rsm_texel.glsl, the very function the RSM multiplied by the albedo). A texel whose arriving
// light is 0 in some channel (outside a spot's cone, a light without that colour) tells nothing
// about the albedo.
GvSurfelAlbedo gvRsmSurfelAlbedo(GpuView view, GpuLight light, vec3 p, vec3 n, vec2 texelCentre,
                                 vec3 reflectedFlux, int rsmResolution) {
  vec3 arriving = rsmTexelLight(view, light, p, n, texelCentre, rsmResolution).flux;
  bool known = min(arriving.x, min(arriving.y, arriving.z)) > 0.0;
  GvSurfelAlbedo result;  // member by member (shared.h: no struct constructors)
  result.albedo = known ? reflectedFlux / arriving : vec3(0.0);
  result.known = known;
  return result;
}

#endif

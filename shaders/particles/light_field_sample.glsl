// The surface a light-field billboard's fragment shows (billboard.vert's outputs in): each view it
// blends is sampled where the fragment's point of the square projects onto that view's image
// plane (an orthographic reprojection, exact for the view along the direction to the viewer and
// ignoring parallax for the others), the premultiplied albedo, normal and offset are blended
// with the views' weights and divided by the blended coverage, and the fragment is discarded
// where that is below one half (the alpha test of seed 2.1.3's transparent billboards, which a
// G-buffer needs: it keeps one surface per pixel, so no sorting is needed). The point is moved
// off the square by the stored offset, so the fragment lies on the model's surface: its depth,
// its world position for lighting and its shadows are the model's, not a flat card's.
#ifndef LPVLAB_LIGHT_FIELD_SAMPLE_GLSL
#define LPVLAB_LIGHT_FIELD_SAMPLE_GLSL

#include "particle_instance.glsl"
#include "light_field_views.glsl"

layout(location = LOCATION_BILLBOARD_CLIP_FROM_WORLD) uniform mat4 clipFromWorld;
layout(location = LOCATION_VIEW_GRID) uniform ivec2 viewGrid;
layout(location = LOCATION_RADIUS) uniform float radius;
layout(binding = UNIT_LIGHT_FIELD_ALBEDO) uniform sampler2DArray lightFieldAlbedo;
layout(binding = UNIT_LIGHT_FIELD_NORMAL) uniform sampler2DArray lightFieldNormal;

layout(location = 0) in vec3 planeObject;
layout(location = 1) flat in int particle;
layout(location = 2) flat in ivec4 viewLayers;
layout(location = 3) flat in vec4 viewWeights;
layout(location = 4) flat in vec3 towardsViewerObject;

struct LightFieldSurface {
  vec3 worldPosition;
  vec3 worldNormal;
  vec3 albedo;
};

// Texture coordinates of the square's point in view `layer`'s image.
vec3 lightFieldTexel(int layer) {
  int i = layer % viewGrid.x;
  int j = layer / viewGrid.x;
  vec3 d = lightFieldViewDirection(i, j, viewGrid);
  vec2 plane = vec2(dot(planeObject, lightFieldRight(d)), dot(planeObject, lightFieldUp(d)));
  return vec3(0.5 + 0.5 * plane / radius, float(layer));
}

// Discards the fragment where the model is not; writes gl_FragDepth.
LightFieldSurface lightFieldSurface() {
  vec4 albedo = vec4(0.0);
  vec4 normalOffset = vec4(0.0);
  for (int k = 0; k < 4; ++k) {
    if (viewWeights[k] <= 0.0) continue;
    vec3 texel = lightFieldTexel(viewLayers[k]);
    albedo += viewWeights[k] * texture(lightFieldAlbedo, texel);
    normalOffset += viewWeights[k] * texture(lightFieldNormal, texel);
  }
  if (albedo.a < 0.5) discard;
  ParticleInstance p = instances[particle];
  vec3 surfaceObject = planeObject + (normalOffset.w / albedo.a) * towardsViewerObject;
  LightFieldSurface s;
  s.worldPosition = p.positionSize.xyz + p.positionSize.w * rotateByQuaternion(p.orientation, surfaceObject);
  s.worldNormal = normalize(rotateByQuaternion(p.orientation, normalOffset.xyz));
  s.albedo = albedo.rgb / albedo.a * p.tint.rgb;
  vec4 clip = clipFromWorld * vec4(s.worldPosition, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
  return s;
}

#endif

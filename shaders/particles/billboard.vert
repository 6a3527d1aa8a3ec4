#version 450
// A light-field particle (seed 002, 4.2): a square facing the viewer of the pass (the camera, or
// a light for the shadow maps and RSMs) that shows the model as seen along the particle's
// direction to that viewer. Instance i is particle i; vertices 0-5 its two triangles. The square
// lies in the plane through the particle orthogonal to the direction to the viewer, its axes the
// light field's image axes for that direction turned into the world, half as wide as the view's
// square (radius, model units) times the size: it covers the model from any direction. It is cut
// down to where the views it blends show the model: a fragment samples each view at its point's
// orthographic projection onto that view's image plane, a linear map M of the square's
// coordinates, so the preimage under M of each view's image bounds (LightField::viewBounds) holds
// every fragment that view can cover; the square is cut to the box around those preimages. On
// the crystal that halves the fragments of every pass (docs/particles.md).
// Per particle (flat) go on: the views and weights the fragment blends (light_field_views.glsl)
// and the direction to the viewer in object space.
#include "particle_instance.glsl"
#include "light_field_views.glsl"

layout(location = LOCATION_BILLBOARD_CLIP_FROM_WORLD) uniform mat4 clipFromWorld;
layout(location = LOCATION_VIEWER) uniform vec4 viewer;
layout(location = LOCATION_VIEW_GRID) uniform ivec2 viewGrid;
layout(location = LOCATION_RADIUS) uniform float radius;
layout(location = LOCATION_INTERPOLATE) uniform int interpolate;

layout(location = 0) out vec3 planeObject;  // the fragment's point of the square, object space
layout(location = 1) flat out int particle;
layout(location = 2) flat out ivec4 viewLayers;
layout(location = 3) flat out vec4 viewWeights;
layout(location = 4) flat out vec3 towardsViewerObject;

layout(std430, binding = BUFFER_VIEW_BOUNDS) readonly buffer ViewBounds { vec4 viewBounds[]; };

const vec2 CORNERS[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));

// The part of the square [-1, 1]^2 (units of radius, axes lightFieldRight(d), lightFieldUp(d))
// where the views can show the model: (min, max) corners. The whole square where a view's map is
// near singular (a view almost edge-on to the square, which blending never picks).
vec4 coveredPart(vec3 d, LightFieldViews views) {
  vec3 right = lightFieldRight(d), up = lightFieldUp(d);
  vec2 lo = vec2(1.0), hi = vec2(-1.0);
  for (int k = 0; k < 4; ++k) {
    if (views.weight[k] <= 0.0) continue;
    int layer = views.layer[k];
    vec3 dk = lightFieldViewDirection(layer % viewGrid.x, layer / viewGrid.x, viewGrid);
    vec3 rightK = lightFieldRight(dk), upK = lightFieldUp(dk);
    mat2 toView = mat2(dot(right, rightK), dot(right, upK), dot(up, rightK), dot(up, upK));
    if (abs(determinant(toView)) < 0.1) return vec4(-1.0, -1.0, 1.0, 1.0);
    mat2 fromView = inverse(toView);
    vec4 b = viewBounds[layer];
    for (int c = 0; c < 4; ++c) {
      vec2 p = fromView * vec2((c & 1) == 0 ? b.x : b.z, (c & 2) == 0 ? b.y : b.w);
      lo = min(lo, p);
      hi = max(hi, p);
    }
  }
  return vec4(clamp(lo, -1.0, 1.0), clamp(hi, -1.0, 1.0));
}

void main() {
  ParticleInstance p = instances[gl_InstanceID];
  vec3 centre = p.positionSize.xyz;
  vec3 towardsViewer = viewer.w > 0.5 ? normalize(viewer.xyz - centre) : normalize(viewer.xyz);
  vec3 d = rotateByQuaternion(conjugateQuaternion(p.orientation), towardsViewer);
  LightFieldViews views = lightFieldViews(d, viewGrid, interpolate != 0);
  vec4 part = coveredPart(d, views);
  vec2 corner = mix(part.xy, part.zw, CORNERS[gl_VertexID]);
  planeObject = radius * (corner.x * lightFieldRight(d) + corner.y * lightFieldUp(d));
  particle = gl_InstanceID;
  viewLayers = views.layer;
  viewWeights = views.weight;
  towardsViewerObject = d;
  vec3 world = centre + p.positionSize.w * rotateByQuaternion(p.orientation, planeObject);
  gl_Position = clipFromWorld * vec4(world, 1.0);
}

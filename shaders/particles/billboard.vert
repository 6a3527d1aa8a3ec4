#version 450
// A light-field particle (seed 002, 4.2): a square facing the viewer of the pass (the camera, or
// a light for the shadow maps and RSMs) that shows the model as seen along the particle's
// direction to that viewer. Instance i is particle i; vertices 0-5 its two triangles. The square
// lies in the plane through the particle orthogonal to the direction to the viewer, its axes the
// light field's image axes for that direction turned into the world, half as wide as the view's
// square (radius, model units) times the size: it covers the model from any direction.
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

const vec2 CORNERS[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));

void main() {
  ParticleInstance p = instances[gl_InstanceID];
  vec3 centre = p.positionSize.xyz;
  vec3 towardsViewer = viewer.w > 0.5 ? normalize(viewer.xyz - centre) : normalize(viewer.xyz);
  vec3 d = rotateByQuaternion(conjugateQuaternion(p.orientation), towardsViewer);
  LightFieldViews views = lightFieldViews(d, viewGrid, interpolate != 0);
  vec2 corner = CORNERS[gl_VertexID];
  planeObject = radius * (corner.x * lightFieldRight(d) + corner.y * lightFieldUp(d));
  particle = gl_InstanceID;
  viewLayers = views.layer;
  viewWeights = views.weight;
  towardsViewerObject = d;
  vec3 world = centre + p.positionSize.w * rotateByQuaternion(p.orientation, planeObject);
  gl_Position = clipFromWorld * vec4(world, 1.0);
}

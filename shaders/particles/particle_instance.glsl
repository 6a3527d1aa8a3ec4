// One particle as the billboards read it (framework/particles/particle_billboards.h mirrors it),
// and the rotation of its orientation.
#ifndef LPVLAB_PARTICLE_INSTANCE_GLSL
#define LPVLAB_PARTICLE_INSTANCE_GLSL

struct ParticleInstance {
  vec4 positionSize;  // xyz: world position (m); w: size (m, the model's largest extent)
  vec4 orientation;   // unit quaternion (x, y, z, w), object to world
  vec4 tint;          // rgb: colour multiplying the albedo
};

#include "billboard_interface.glsl"
layout(std430, binding = BUFFER_INSTANCES) readonly buffer Instances { ParticleInstance instances[]; };

// q v q* for a unit quaternion q.
vec3 rotateByQuaternion(vec4 q, vec3 v) {
  return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}

vec4 conjugateQuaternion(vec4 q) { return vec4(-q.xyz, q.w); }

#endif

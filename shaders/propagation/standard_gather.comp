#version 450
// One iteration of standard propagation by gathering: every cell pulls from its six face
// neighbours what each sends it through its five faces (standard_faces.glsl), writes that as the
// next iteration's light and adds it to the accumulated grid. Light that would leave the grid is
// lost. Any SH order: SH_COEFFICIENTS per channel.
#include "standard_faces.glsl"
#include "../common/grid.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(constant_id = 0) const float FAR_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 1) const float SIDE_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 2) const int SH_COEFFICIENTS = 4;

layout(std430, binding = 0) readonly buffer Source { float source[]; };
layout(std430, binding = 1) writeonly buffer Target { float target[]; };
layout(std430, binding = 2) buffer Accumulated { float accumulated[]; };
layout(location = 0) uniform ivec3 resolution;

const int N = SH_COEFFICIENTS;  // arrays sized by the specialisation constant stay in registers

void main() {
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (!cellInside(cell, resolution)) return;
  int cells = cellCount(resolution);
  float gathered[3 * N];
  for (int i = 0; i < 3 * N; ++i) gathered[i] = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      ivec3 offset = ivec3(0);
      offset[axis] = sign;
      ivec3 neighbour = cell + offset;
      if (!cellInside(neighbour, resolution)) continue;
      int n = cellIndex(neighbour, resolution);
      float c[3 * N];
      for (int channel = 0; channel < 3; ++channel)
        for (int k = 0; k < N; ++k)
          c[channel * N + k] = source[coefficientIndex(channel, k, SH_COEFFICIENTS, n, cells)];
      vec3 towardsUs = vec3(-offset);
      for (int f = 0; f < STANDARD_FACES; ++f) {
        vec3 direction = standardFaceDirection(towardsUs, f);
        vec3 normal = standardFaceNormal(towardsUs, f);
        float solidAngle = standardFaceSolidAngle(f, FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE);
        float basis[N];
        float lobe[N];
        for (int k = 0; k < N; ++k) {
          basis[k] = shBasisAt(k, direction);
          lobe[k] = shCosineLobeAt(k, normal) / PI;
        }
        for (int channel = 0; channel < 3; ++channel) {
          float intensity = 0.0;
          for (int k = 0; k < N; ++k) intensity += c[channel * N + k] * basis[k];
          float flux = solidAngle * max(0.0, intensity);
          for (int k = 0; k < N; ++k) gathered[channel * N + k] += flux * lobe[k];
        }
      }
    }
  }
  int index = cellIndex(cell, resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < SH_COEFFICIENTS; ++k) {
      int i = coefficientIndex(channel, k, SH_COEFFICIENTS, index, cells);
      target[i] = gathered[channel * N + k];
      accumulated[i] += gathered[channel * N + k];
    }
}

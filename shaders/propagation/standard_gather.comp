#version 450
// One iteration of standard propagation by gathering: every cell pulls from its six face
// neighbours what each sends it (standard_faces.glsl), writes that as the next iteration's light
// and adds it to the accumulated grid. Light that would leave the grid is lost.
#include "standard_faces.glsl"
#include "../common/grid.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(constant_id = 0) const float FAR_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 1) const float SIDE_FACE_SOLID_ANGLE = 0.0;

layout(std430, binding = 0) readonly buffer Source { float source[]; };
layout(std430, binding = 1) writeonly buffer Target { float target[]; };
layout(std430, binding = 2) buffer Accumulated { float accumulated[]; };
layout(location = 0) uniform ivec3 resolution;

const int COEFFICIENTS = 4;

vec4 readCell(int channel, int cell, int cells) {
  int base = coefficientIndex(channel, 0, COEFFICIENTS, cell, cells);
  return vec4(source[base], source[base + cells], source[base + 2 * cells], source[base + 3 * cells]);
}

void main() {
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (!cellInside(cell, resolution)) return;
  int cells = cellCount(resolution);
  vec4 gathered[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      ivec3 offset = ivec3(0);
      offset[axis] = sign;
      ivec3 neighbour = cell + offset;
      if (!cellInside(neighbour, resolution)) continue;
      int n = cellIndex(neighbour, resolution);
      vec3 towardsUs = vec3(-offset);
      for (int channel = 0; channel < 3; ++channel)
        gathered[channel] += propagateToNeighbour(readCell(channel, n, cells), towardsUs,
                                                  FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE);
    }
  }
  int index = cellIndex(cell, resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < COEFFICIENTS; ++k) {
      int i = coefficientIndex(channel, k, COEFFICIENTS, index, cells);
      target[i] = gathered[channel][k];
      accumulated[i] += gathered[channel][k];
    }
}

#version 450
// Directed propagation's release (directed_faces.glsl): before each gather, a cell without a
// normal, or with a neighbour whose normal is of another region, moves its attached light into
// the free grid, which propagates as standard propagation. After the last iteration the strategy
// releases every cell (releaseAll), so that the free grid holds the step's whole light. In place:
// each invocation writes only its own cell's coefficients and reads only normals.
#include "directed_faces.glsl"
#include "../common/grid.glsl"

#include "directed_release_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const int SH_COEFFICIENTS = 4;
layout(constant_id = 1) const float COS_REGION_ANGLE = 1.0;

layout(std430, binding = BUFFER_NORMALS) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = BUFFER_ATTACHED) buffer Attached { float attached[]; };
layout(std430, binding = BUFFER_FREE) buffer Free { float freeLight[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_RELEASE_ALL) uniform int releaseAll;

void main() {
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (!cellInside(cell, resolution)) return;
  int index = cellIndex(cell, resolution);
  vec4 own = normals[index];
  bool release = releaseAll != 0 || !directedHasNormal(own);
  for (int axis = 0; axis < 3 && !release; ++axis)
    for (int sign = -1; sign <= 1; sign += 2) {
      ivec3 neighbour = cell;
      neighbour[axis] += sign;
      if (cellInside(neighbour, resolution) &&
          directedNeighbourReleases(own, normals[cellIndex(neighbour, resolution)], COS_REGION_ANGLE))
        release = true;
    }
  if (!release) return;
  int cells = cellCount(resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < SH_COEFFICIENTS; ++k) {
      int i = coefficientIndex(channel, k, SH_COEFFICIENTS, index, cells);
      freeLight[i] += attached[i];
      attached[i] = 0.0;
    }
}

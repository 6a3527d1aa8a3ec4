#version 450
// Normal dilation of directed propagation, by gathering (directed_faces.glsl): a cell without a
// normal takes the normalised mean of its six face neighbours' unit normals.
#include "directed_faces.glsl"
#include "../common/grid.glsl"

#include "directed_dilate_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;

layout(std430, binding = BUFFER_SOURCE) readonly buffer Source { vec4 source[]; };
layout(std430, binding = BUFFER_TARGET) writeonly buffer Target { vec4 target[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;

void main() {
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (!cellInside(cell, resolution)) return;
  vec3 sum = vec3(0.0);
  for (int axis = 0; axis < 3; ++axis)
    for (int sign = -1; sign <= 1; sign += 2) {
      ivec3 neighbour = cell;
      neighbour[axis] += sign;
      if (cellInside(neighbour, resolution))
        sum += directedUnitNormal(source[cellIndex(neighbour, resolution)]);
    }
  int index = cellIndex(cell, resolution);
  target[index] = directedDilated(source[index], sum);
}

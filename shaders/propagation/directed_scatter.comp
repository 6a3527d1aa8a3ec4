#version 450
// One iteration of directed propagation by scattering (thesis 5.2 with 7.4.3's scatter): every
// cell pushes into each face neighbour what that neighbour would gather from it
// (directed_gather.comp): the five faces' flux towards it, reprojected about the receiving cell's
// dilated normal where it has one (directed_transfer.glsl: the one face loop both kernels run).
// It is added with float atomics to the next iteration's light (cleared before the dispatch) and
// to the accumulated grid. The reprojection is linear in each neighbour's contribution, so the
// grid is the gather's up to the order of float additions. Light that would leave the grid is
// lost, as in gathering. Same bindings and uniforms as the gather (directed_gather_interface.glsl).
#extension GL_EXT_shader_atomic_float : require
#include "directed_gather_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const float FAR_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 1) const float SIDE_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 2) const bool GEOMETRY_VOLUME = false;
layout(constant_id = 3) const int SH_COEFFICIENTS = 4;

layout(std430, binding = BUFFER_SOURCE) readonly buffer Source { float source[]; };
layout(std430, binding = BUFFER_TARGET) buffer Target { float target[]; };
layout(std430, binding = BUFFER_ACCUMULATED) buffer Accumulated { float accumulated[]; };
layout(std430, binding = BUFFER_NORMALS) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME) readonly buffer GeometryVolume { float gvBlocking[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_OCCLUDE_THIS_ITERATION) uniform int occludeThisIteration;  // 0 or 1

const int N = SH_COEFFICIENTS;
#include "directed_transfer.glsl"

void main() {
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (!cellInside(cell, resolution)) return;
  int cells = cellCount(resolution);
  int index = cellIndex(cell, resolution);
  bool occluded = GEOMETRY_VOLUME && occludeThisIteration != 0;
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < N; ++k)
      directedSource[channel * N + k] = source[coefficientIndex(channel, k, N, index, cells)];
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      ivec3 offset = ivec3(0);
      offset[axis] = sign;
      ivec3 receiver = cell + offset;
      if (!cellInside(receiver, resolution)) continue;
      int r = cellIndex(receiver, resolution);
      vec3 normal = directedUnitNormal(normals[r]);
      float gain = directedGainOf(normals[r], FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE, N);
      bool reproject = gain != 0.0;
      directedGatherBegin();
      directedGatherFrom(cell, vec3(offset), normal, gain, reproject, occluded,
                         FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE);
      directedGatherEnd(normal, reproject);
      for (int channel = 0; channel < 3; ++channel)
        for (int k = 0; k < N; ++k) {
          int i = coefficientIndex(channel, k, N, r, cells);
          atomicAdd(target[i], directedGathered[channel * N + k]);
          atomicAdd(accumulated[i], directedGathered[channel * N + k]);
        }
    }
  }
}

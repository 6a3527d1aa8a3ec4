#version 450
// One iteration of directed propagation by gathering: as standard_gather.comp, with the second
// reprojection of alg. 6.3 about this (the receiving) cell's dilated normal applied to what each
// face passes (directed_transfer.glsl, directed_faces.glsl). Any SH order: SH_COEFFICIENTS per
// channel. With a geometry volume, the light crossing the shared face is attenuated by its
// blocking potential (thesis alg. 6.2 lines 11-15) from the occlusion strategy's first occluded
// iteration on.
#include "directed_gather_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const float FAR_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 1) const float SIDE_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 2) const bool GEOMETRY_VOLUME = false;
layout(constant_id = 3) const int SH_COEFFICIENTS = 4;

layout(std430, binding = BUFFER_SOURCE) readonly buffer Source { float source[]; };
layout(std430, binding = BUFFER_TARGET) writeonly buffer Target { float target[]; };
layout(std430, binding = BUFFER_ACCUMULATED) buffer Accumulated { float accumulated[]; };
layout(std430, binding = BUFFER_NORMALS) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME) readonly buffer GeometryVolume { float gvBlocking[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_OCCLUDE_THIS_ITERATION) uniform int occludeThisIteration;  // 0 or 1

const int N = SH_COEFFICIENTS;  // arrays sized by the specialisation constant stay in registers
#include "directed_transfer.glsl"

void main() {
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (!cellInside(cell, resolution)) return;
  int cells = cellCount(resolution);
  int index = cellIndex(cell, resolution);
  vec3 normal = directedUnitNormal(normals[index]);
  float gain = directedGainOf(normals[index], FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE, N);
  bool reproject = gain != 0.0;
  bool occluded = GEOMETRY_VOLUME && occludeThisIteration != 0;
  directedGatherBegin();
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      ivec3 offset = ivec3(0);
      offset[axis] = sign;
      ivec3 neighbour = cell + offset;
      if (!cellInside(neighbour, resolution)) continue;
      int n = cellIndex(neighbour, resolution);
      for (int channel = 0; channel < 3; ++channel)
        for (int k = 0; k < N; ++k)
          directedSource[channel * N + k] = source[coefficientIndex(channel, k, N, n, cells)];
      directedGatherFrom(neighbour, vec3(-offset), normal, gain, reproject, occluded,
                         FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE);
    }
  }
  directedGatherEnd(normal, reproject);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < N; ++k) {
      int i = coefficientIndex(channel, k, N, index, cells);
      target[i] = directedGathered[channel * N + k];
      accumulated[i] += directedGathered[channel * N + k];
    }
}

#version 450
// Directed propagation by gathering, laid out for GPUs ([propagation] gpu_kernel = "tiled"): the
// same transfer as directed_gather.comp (directed_transfer.glsl, called with the same arguments
// in the same order), so the same grid; the neighbours' light comes from tiled_walk.glsl's tiles
// in shared memory, walking up z. The normals and the GV are read as in the simple kernel.
#include "directed_gather_interface.glsl"
#include "tiled_walk_interface.glsl"
layout(local_size_x_id = SPEC_TILE_X, local_size_y_id = SPEC_TILE_Y,
       local_size_z = TILED_GROUP_SIZE_Z) in;
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
#include "tiled_walk.glsl"

void main() {
  bool occluded = GEOMETRY_VOLUME && occludeThisIteration != 0;
  TiledWalk walk = tiledWalkBegin();
  for (int z = walk.first.z; z < walk.end; ++z) {
    ivec3 cell = tiledWalkStage(walk, z);
    if (walk.inColumn) {
      int index = cellIndex(cell, resolution);
      vec3 normal = directedUnitNormal(normals[index]);
      float gain = directedGainOf(normals[index], FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE, N);
      bool reproject = gain != 0.0;
      directedGatherBegin();
      // The neighbours in directed_gather.comp's order (-x, +x, -y, +y, -z, +z): the same sum.
      for (int axis = 0; axis < 3; ++axis) {
        for (int sign = -1; sign <= 1; sign += 2) {
          ivec3 offset = ivec3(0);
          offset[axis] = sign;
          ivec3 neighbour = cell + offset;
          if (!cellInside(neighbour, resolution)) continue;
          tiledWalkNeighbour(walk, offset);
          for (int i = 0; i < 3 * N; ++i) directedSource[i] = walkCell[i];
          directedGatherFrom(neighbour, vec3(-offset), normal, gain, reproject, occluded,
                             FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE);
        }
      }
      directedGatherEnd(normal, reproject);
      for (int channel = 0; channel < 3; ++channel)
        for (int k = 0; k < N; ++k) {
          int i = coefficientIndex(channel, k, N, index, walk.cells);
          target[i] = directedGathered[channel * N + k];
          accumulated[i] += directedGathered[channel * N + k];
        }
    }
    tiledWalkAdvance();
  }
}

#version 450
// Standard propagation by gathering, laid out for GPUs ([propagation] gpu_kernel = "tiled"): the
// same transfer as standard_gather.comp (standard_transfer.glsl's face loop, called with the same
// arguments in the same order), so the same grid; only where the neighbours' light comes from
// differs: tiled_walk.glsl's tiles in shared memory, walking up z. The GV corners are read as in
// the simple kernel. The tile sizes are specialisation constants, chosen per SH order by
// variants/propagation/tiled_walk.h so that the shared tile fits GL's guaranteed 32 KiB.
// Not done: several iterations per dispatch (temporal blocking), which the halo would allow.
#include "standard_interface.glsl"
#include "tiled_walk_interface.glsl"
layout(local_size_x_id = SPEC_TILE_X, local_size_y_id = SPEC_TILE_Y,
       local_size_z = TILED_GROUP_SIZE_Z) in;
layout(constant_id = 0) const float FAR_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 1) const float SIDE_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 2) const int SH_COEFFICIENTS = 4;
layout(constant_id = 3) const bool HAS_GV = false;
layout(constant_id = 4) const bool BOUNCES = false;  // re-emit blocked light (only with HAS_GV)

layout(std430, binding = BUFFER_SOURCE) readonly buffer Source { float source[]; };
layout(std430, binding = BUFFER_TARGET) writeonly buffer Target { float target[]; };
layout(std430, binding = BUFFER_ACCUMULATED) buffer Accumulated { float accumulated[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME) readonly buffer GeometryVolume { float gvBlocking[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME_ALBEDO) readonly buffer GeometryVolumeAlbedo { vec4 gvAlbedo[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_ITERATION) uniform int iteration;
layout(location = LOCATION_FIRST_OCCLUDED_ITERATION) uniform int firstOccludedIteration;

const int N = SH_COEFFICIENTS;  // arrays sized by the specialisation constant stay in registers
#include "standard_transfer.glsl"
#include "tiled_walk.glsl"

void main() {
  bool occluded = iteration >= firstOccludedIteration;
  TiledWalk walk = tiledWalkBegin();
  for (int z = walk.first.z; z < walk.end; ++z) {
    ivec3 cell = tiledWalkStage(walk, z);
    if (walk.inColumn) {
      if (HAS_GV && occluded) loadGvCorners(cell, resolution + 1);
      float gathered[3 * N];
      for (int i = 0; i < 3 * N; ++i) gathered[i] = 0.0;
      // The neighbours in standard_gather.comp's order (-x, +x, -y, +y, -z, +z): the same sum.
      for (int axis = 0; axis < 3; ++axis) {
        for (int sign = -1; sign <= 1; sign += 2) {
          ivec3 offset = ivec3(0);
          offset[axis] = sign;
          ivec3 neighbour = cell + offset;
          if (!cellInside(neighbour, resolution)) continue;
          tiledWalkNeighbour(walk, offset);
          for (int i = 0; i < 3 * N; ++i) sourceCell[i] = walkCell[i];
          standardTransfer(neighbour, vec3(-offset), occluded, true, false, resolution,
                           FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE);
          for (int i = 0; i < 3 * N; ++i) gathered[i] += transferred[i];
        }
      }
      if (BOUNCES && occluded) {
        for (int i = 0; i < 3 * N; ++i) sourceCell[i] = walkCentre[i];
        for (int axis = 0; axis < 3; ++axis) {
          for (int sign = -1; sign <= 1; sign += 2) {
            vec3 d = vec3(0.0);
            d[axis] = float(sign);
            standardTransfer(cell, d, occluded, false, true, resolution, FAR_FACE_SOLID_ANGLE,
                             SIDE_FACE_SOLID_ANGLE);
            for (int i = 0; i < 3 * N; ++i) gathered[i] += bounced[i];
          }
        }
      }
      int index = cellIndex(cell, resolution);
      for (int channel = 0; channel < 3; ++channel)
        for (int k = 0; k < N; ++k) {
          int i = coefficientIndex(channel, k, N, index, walk.cells);
          target[i] = gathered[channel * N + k];
          accumulated[i] += gathered[channel * N + k];
        }
    }
    tiledWalkAdvance();
  }
}

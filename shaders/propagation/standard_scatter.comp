#version 450
// One iteration of standard propagation by scattering (thesis 7.4.3): every cell pushes into its
// six face neighbours what it sends them through their five faces (standard_transfer.glsl, the
// same transfer the gather kernel pulls), adding it with float atomics to the next iteration's
// light (cleared before the dispatch) and to the accumulated grid. Light that would leave the
// grid is lost. With BOUNCES, what the GV blocked of its transfers (the grid's edge included) is
// re-emitted into the cell itself. Gives the gather kernel's grid up to the order of float
// additions.
#extension GL_EXT_shader_atomic_float : require
#include "standard_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const float FAR_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 1) const float SIDE_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 2) const int SH_COEFFICIENTS = 4;
layout(constant_id = 3) const bool HAS_GV = false;
layout(constant_id = 4) const bool BOUNCES = false;  // re-emit blocked light (only with HAS_GV)

layout(std430, binding = BUFFER_SOURCE) readonly buffer Source { float source[]; };
layout(std430, binding = BUFFER_TARGET) buffer Target { float target[]; };
layout(std430, binding = BUFFER_ACCUMULATED) buffer Accumulated { float accumulated[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME) readonly buffer GeometryVolume { float gvBlocking[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME_ALBEDO) readonly buffer GeometryVolumeAlbedo { vec4 gvAlbedo[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_ITERATION) uniform int iteration;               // 0 for the first step after injection
layout(location = LOCATION_FIRST_OCCLUDED_ITERATION) uniform int firstOccludedIteration;  // GeometryVolume::firstOccludedIteration

const int N = SH_COEFFICIENTS;
#include "standard_transfer.glsl"

void main() {
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (!cellInside(cell, resolution)) return;
  int cells = cellCount(resolution);
  bool occluded = iteration >= firstOccludedIteration;
  if (HAS_GV && occluded) loadGvCorners(cell, resolution + 1);  // every face crossed is this cell's
  int index = cellIndex(cell, resolution);
  loadSourceCell(index, cells);
  bool bouncing = BOUNCES && occluded;
  float reemitted[3 * N];
  for (int i = 0; i < 3 * N; ++i) reemitted[i] = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      ivec3 offset = ivec3(0);
      offset[axis] = sign;
      ivec3 neighbour = cell + offset;
      bool inside = cellInside(neighbour, resolution);
      if (!inside && !bouncing) continue;
      standardTransfer(cell, vec3(offset), occluded, inside, true, resolution,
                       FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE);
      if (bouncing)
        for (int i = 0; i < 3 * N; ++i) reemitted[i] += bounced[i];
      if (!inside) continue;
      int n = cellIndex(neighbour, resolution);
      for (int channel = 0; channel < 3; ++channel)
        for (int k = 0; k < N; ++k) {
          int i = coefficientIndex(channel, k, N, n, cells);
          atomicAdd(target[i], transferred[channel * N + k]);
          atomicAdd(accumulated[i], transferred[channel * N + k]);
        }
    }
  }
  if (bouncing)
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < N; ++k) {
        int i = coefficientIndex(channel, k, N, index, cells);
        atomicAdd(target[i], reemitted[channel * N + k]);
        atomicAdd(accumulated[i], reemitted[channel * N + k]);
      }
}

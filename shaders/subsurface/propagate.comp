#version 450
// One iteration of the subsurface LPV's propagation (thesis 5.4, step 3): the standard transfer
// by gathering (shaders/propagation/standard_transfer.glsl, the very face loop of "standard"),
// without a geometry volume, and every step's light multiplied by the attenuation constant
//     a = exp(-sigma s)
// of the translucent material (extinction sigma, 1/m) over the one cell (s, m) the light moves
// per step. Writes the next iteration's light and adds it to the accumulated SSLPV; light that
// would leave the grid is lost.
#include "propagate_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const float FAR_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 1) const float SIDE_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 2) const int SH_COEFFICIENTS = 4;
const bool HAS_GV = false;   // the transfer's GV reads and bounces are compiled out:
const bool BOUNCES = false;  // the buffers below are declared for it, never read

layout(std430, binding = BUFFER_SOURCE) readonly buffer Source { float source[]; };
layout(std430, binding = BUFFER_TARGET) writeonly buffer Target { float target[]; };
layout(std430, binding = BUFFER_ACCUMULATED) buffer Accumulated { float accumulated[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME) readonly buffer GeometryVolume { float gvBlocking[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME_ALBEDO) readonly buffer GeometryVolumeAlbedo { vec4 gvAlbedo[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_ATTENUATION) uniform float attenuation;  // a, per step

const int N = SH_COEFFICIENTS;
#include "../propagation/standard_transfer.glsl"

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
      loadSourceCell(cellIndex(neighbour, resolution), cells);
      standardTransfer(neighbour, vec3(-offset), false, true, false, resolution,
                       FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE);
      for (int i = 0; i < 3 * N; ++i) gathered[i] += transferred[i];
    }
  }
  int index = cellIndex(cell, resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < N; ++k) {
      int i = coefficientIndex(channel, k, N, index, cells);
      float light = attenuation * gathered[channel * N + k];
      target[i] = light;
      accumulated[i] += light;
    }
}

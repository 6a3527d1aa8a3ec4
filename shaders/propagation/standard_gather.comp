#version 450
// One iteration of standard propagation by gathering: every cell pulls from its six face
// neighbours what each sends it through its five faces (standard_transfer.glsl), writes that as
// the next iteration's light and adds it to the accumulated grid. Light that would leave the grid
// is lost. Any SH order: SH_COEFFICIENTS per channel. With the GV (HAS_GV) and from the
// iteration `firstOccludedIteration` on, each face's flux is attenuated by the GV's transmittance;
// with BOUNCES the cell also runs its own outgoing transfers (all six, the grid's edge included)
// for what the GV blocked of them, which its surfaces re-emit into this cell: twice the face work.
#include "standard_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
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
layout(location = LOCATION_ITERATION) uniform int iteration;               // 0 for the first step after injection
layout(location = LOCATION_FIRST_OCCLUDED_ITERATION) uniform int firstOccludedIteration;  // GeometryVolume::firstOccludedIteration

const int N = SH_COEFFICIENTS;  // arrays sized by the specialisation constant stay in registers
#include "standard_transfer.glsl"

void main() {
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (!cellInside(cell, resolution)) return;
  int cells = cellCount(resolution);
  bool occluded = iteration >= firstOccludedIteration;
  if (HAS_GV && occluded) loadGvCorners(cell, resolution + 1);  // every face crossed is this cell's
  float gathered[3 * N];
  for (int i = 0; i < 3 * N; ++i) gathered[i] = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      ivec3 offset = ivec3(0);
      offset[axis] = sign;
      ivec3 neighbour = cell + offset;
      if (!cellInside(neighbour, resolution)) continue;
      loadSourceCell(cellIndex(neighbour, resolution), cells);
      standardTransfer(neighbour, vec3(-offset), occluded, true, false, resolution,
                       FAR_FACE_SOLID_ANGLE, SIDE_FACE_SOLID_ANGLE);
      for (int i = 0; i < 3 * N; ++i) gathered[i] += transferred[i];
    }
  }
  if (BOUNCES && occluded) {
    loadSourceCell(cellIndex(cell, resolution), cells);
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
      int i = coefficientIndex(channel, k, N, index, cells);
      target[i] = gathered[channel * N + k];
      accumulated[i] += gathered[channel * N + k];
    }
}

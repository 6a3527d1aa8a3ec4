#version 450
// One iteration of tetrahedral propagation by gathering: every lattice cell pulls from its four
// face neighbours what each sends it through its three other faces (tetReceiveFrom in
// tetrahedral_lattice.glsl), writes that as the next iteration's light and adds it to the
// lattice's running sum. Light towards cells that do not exist (past the grid) is lost.
#include "tetrahedral_slot.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(constant_id = 0) const float SMALL_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 1) const float LARGE_FACE_SOLID_ANGLE = 0.0;

layout(std430, binding = 0) readonly buffer Source { float source[]; };
layout(std430, binding = 1) writeonly buffer Target { float target[]; };
layout(std430, binding = 2) buffer Sum { float sum[]; };
layout(location = 0) uniform ivec3 resolution;

void main() {
  ivec4 tet = tetOfInvocation(gl_GlobalInvocationID);
  if (!cellInside(ivec3(tet.x, tet.y, tet.z), resolution) || !tetInside(tet, resolution)) return;
  int slots = tetSlotCount(resolution);
  vec4 gathered[3] = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
  for (int face = 0; face < TET_FACES; ++face) {
    ivec4 neighbour = tetNeighbour(tet, face);
    if (!tetInside(neighbour, resolution)) continue;
    int n = tetSlot(neighbour, resolution);
    vec4 c[3];
    for (int channel = 0; channel < 3; ++channel)
      c[channel] = vec4(source[coefficientIndex(channel, 0, 4, n, slots)],
                        source[coefficientIndex(channel, 1, 4, n, slots)],
                        source[coefficientIndex(channel, 2, 4, n, slots)],
                        source[coefficientIndex(channel, 3, 4, n, slots)]);
    // tetReceiveFrom with each face's geometry computed once for the three channels.
    for (int k = 0; k < TET_FACES; ++k) {
      if (k == face) continue;
      vec4 basis = shBasis(tetFarFaceDirection(tet.w, face, k));
      vec4 lobe = shCosineLobe(tetFaceNormal(tet.w, k)) *
                  (tetFarFaceSolidAngle(face, k, SMALL_FACE_SOLID_ANGLE, LARGE_FACE_SOLID_ANGLE) / PI);
      for (int channel = 0; channel < 3; ++channel)
        gathered[channel] += max(0.0, dot(c[channel], basis)) * lobe;
    }
  }
  int slot = tetSlot(tet, resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < 4; ++k) {
      int i = coefficientIndex(channel, k, 4, slot, slots);
      target[i] = gathered[channel][k];
      sum[i] += gathered[channel][k];
    }
}

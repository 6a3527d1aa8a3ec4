#version 450
// One iteration of tetrahedral propagation by gathering: every lattice cell pulls from its four
// face neighbours what each sends it through its three other faces (the face loop of
// tetrahedral_lattice.glsl, at any SH order: SH_COEFFICIENTS per channel), writes that as the
// next iteration's light and adds it to the lattice's running sum. Light towards cells that do
// not exist (past the grid) is lost. A face's flux weighs the neighbour's coefficients with the
// face's SH integrals (FACE_INTEGRALS, the buffer at binding 4) or with its solid angle times the
// basis towards its centroid (tetrahedral_lattice.glsl, "face_flux"). With the GV (HAS_GV) and
// `occluded`, each face's flux is multiplied by the GV's transmittance where its direction
// crosses the shared face.
#include "tetrahedral_gather_interface.glsl"
layout(local_size_x = GROUP_SIZE_X, local_size_y = GROUP_SIZE_Y, local_size_z = GROUP_SIZE_Z) in;
layout(constant_id = 0) const float SMALL_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 1) const float LARGE_FACE_SOLID_ANGLE = 0.0;
layout(constant_id = 2) const int SH_COEFFICIENTS = 4;
layout(constant_id = 3) const bool HAS_GV = false;
layout(constant_id = 4) const bool FACE_INTEGRALS = true;

layout(std430, binding = BUFFER_SOURCE) readonly buffer Source { float source[]; };
layout(std430, binding = BUFFER_TARGET) writeonly buffer Target { float target[]; };
layout(std430, binding = BUFFER_SUM) buffer Sum { float sum[]; };
layout(std430, binding = BUFFER_GEOMETRY_VOLUME) readonly buffer GeometryVolume { float gvBlocking[]; };
layout(std430, binding = BUFFER_FACE_INTEGRALS) readonly buffer FaceIntegrals { float faceIntegral[]; };
layout(location = LOCATION_RESOLUTION) uniform ivec3 resolution;
layout(location = LOCATION_OCCLUDED_STEP) uniform int occludedStep;  // 0 or 1: this step reads the GV (tetFirstOccludedStep)

const int N = SH_COEFFICIENTS;  // arrays sized by the specialisation constant stay in registers
#include "tetrahedral_slot.glsl"
#include "../common/geometry_volume_lookup.glsl"

void main() {
  ivec4 tet = tetOfInvocation(gl_GlobalInvocationID);
  if (!cellInside(ivec3(tet.x, tet.y, tet.z), resolution) || !tetInside(tet, resolution)) return;
  int slots = tetSlotCount(resolution);
  bool occluded = HAS_GV && occludedStep != 0;
  float gathered[3 * N];
  for (int i = 0; i < 3 * N; ++i) gathered[i] = 0.0;
  for (int face = 0; face < TET_FACES; ++face) {
    ivec4 neighbour = tetNeighbour(tet, face);
    if (!tetInside(neighbour, resolution)) continue;
    int n = tetSlot(neighbour, resolution);
    float c[3 * N];
    for (int channel = 0; channel < 3; ++channel)
      for (int i = 0; i < N; ++i) c[channel * N + i] = source[coefficientIndex(channel, i, N, n, slots)];
    // Each far face's geometry once for the three channels.
    for (int k = 0; k < TET_FACES; ++k) {
      if (k == face) continue;
      vec3 direction = tetFarFaceDirection(tet.w, face, k);
      vec3 normal = tetFaceNormal(tet.w, k);
      float solidAngle = tetFarFaceSolidAngle(face, k, SMALL_FACE_SOLID_ANGLE, LARGE_FACE_SOLID_ANGLE);
      float transmittance = 1.0;
      if (occluded)
        transmittance = gvTransmittance(gvBlockingAt(tetFarFaceCrossing(tet, face, k), resolution + 1),
                                        direction);
      float weight[N];  // face k's flux is max(0, sum_i c_i weight_i), times the transmittance
      float lobe[N];
      for (int i = 0; i < N; ++i) {
        weight[i] = FACE_INTEGRALS ? faceIntegral[tetFaceIntegralIndex(tet.w, face, k, i)]
                                   : solidAngle * shBasisAt(i, direction);
        lobe[i] = shCosineLobeAt(i, normal) / PI;
      }
      for (int channel = 0; channel < 3; ++channel) {
        float integral = 0.0;
        for (int i = 0; i < N; ++i) integral += c[channel * N + i] * weight[i];
        float flux = standardFaceFlux(integral, 1.0, transmittance);
        for (int i = 0; i < N; ++i) gathered[channel * N + i] += flux * lobe[i];
      }
    }
  }
  int slot = tetSlot(tet, resolution);
  for (int channel = 0; channel < 3; ++channel)
    for (int i = 0; i < N; ++i) {
      int at = coefficientIndex(channel, i, N, slot, slots);
      target[at] = gathered[channel * N + i];
      sum[at] += gathered[channel * N + i];
    }
}

// What a cell gathers from one face neighbour in directed propagation: the standard transfer's
// five faces (standard_faces.glsl), each face's flux attenuated by the GV where it crosses the
// shared face, and, where the receiving cell has a (dilated) normal, reprojected a second time
// about it (directed_faces.glsl, alg. 6.3). The one face loop of directed_gather.comp and
// directed_gather_tiled.comp (so they cannot drift apart).
//
// The including kernel declares, before including this file:
//   const int N                  coefficients per channel (specialisation constant)
//   buffer ... { float gvBlocking[]; }  the GV (read only when `occluded`)
//   uniform ivec3 resolution
// fills `directedSource` with the neighbour's light and calls directedGatherFrom per neighbour
// between directedGatherBegin and directedGatherEnd, whose result is in `directedGathered`.
#ifndef LPVLAB_DIRECTED_TRANSFER_GLSL
#define LPVLAB_DIRECTED_TRANSFER_GLSL
#include "directed_faces.glsl"
#include "../common/grid.glsl"
#include "../common/geometry_volume_lookup.glsl"

float directedSource[3 * N];    // the neighbour's light, channel-major
float directedGathered[3 * N];  // the cell's new light
float directedReprojected[3];   // with a normal: the multiple of cosLobe(normal) per channel

void directedGatherBegin() {
  for (int i = 0; i < 3 * N; ++i) directedGathered[i] = 0.0;
  for (int channel = 0; channel < 3; ++channel) directedReprojected[channel] = 0.0;
}

// Adds what directedSource, at `neighbour`, sends through the faces towards the receiving cell
// (`towardsUs`: the unit axis from the neighbour to it). Without a normal (`reproject` false)
// the standard transfer's coefficients are summed; with one, every face re-emits a multiple of
// cosLobe(normal): only that multiple is summed, per channel.
void directedGatherFrom(ivec3 neighbour, vec3 towardsUs, vec3 normal, float gain, bool reproject,
                        bool occluded, float farSolidAngle, float sideSolidAngle) {
  for (int f = 0; f < STANDARD_FACES; ++f) {
    vec3 direction = standardFaceDirection(towardsUs, f);
    vec3 faceNormal = standardFaceNormal(towardsUs, f);
    float solidAngle = standardFaceSolidAngle(f, farSolidAngle, sideSolidAngle);
    float transmittance = 1.0;
    if (occluded) {
      vec3 crossing = standardFaceCrossing(vec3(neighbour) + 0.5, towardsUs, f);
      transmittance = gvTransmittance(gvBlockingAt(crossing, resolution + 1), direction);
    }
    float basis[N];
    float lobe[N];  // the standard transfer's lobe, for a cell without a normal
    for (int k = 0; k < N; ++k) {
      basis[k] = shBasisAt(k, direction);
      lobe[k] = reproject ? 0.0 : shCosineLobeAt(k, faceNormal) / PI;
    }
    float factor = reproject ? directedReprojection(faceNormal, normal, gain, N) : 0.0;
    for (int channel = 0; channel < 3; ++channel) {
      float intensity = 0.0;
      for (int k = 0; k < N; ++k) intensity += directedSource[channel * N + k] * basis[k];
      float flux = standardFaceFlux(intensity, solidAngle, transmittance);
      if (reproject) {
        directedReprojected[channel] += flux * factor;
      } else {
        for (int k = 0; k < N; ++k) directedGathered[channel * N + k] += flux * lobe[k];
      }
    }
  }
}

// With a normal, the gathered light is the reprojected multiples times cosLobe(normal).
void directedGatherEnd(vec3 normal, bool reproject) {
  if (reproject)
    for (int channel = 0; channel < 3; ++channel)
      for (int k = 0; k < N; ++k)
        directedGathered[channel * N + k] = directedReprojected[channel] * shCosineLobeAt(k, normal);
}

#endif

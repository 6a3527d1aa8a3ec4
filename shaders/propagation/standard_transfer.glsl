// The standard transfer of one source cell into one face neighbour, at any SH order, with or
// without the geometry volume: the one face loop that the gather and the scatter kernels share
// (so they cannot drift apart). Per face it calls the shared functions of standard_faces.glsl.
//
// The including kernel declares, before including this file:
//   const int N                      coefficients per channel (specialisation constant)
//   const bool HAS_GV                whether a GV buffer is bound (specialisation constant)
//   const bool BOUNCES               whether blocked light is re-emitted (specialisation constant;
//                                    only with HAS_GV)
//   buffer ... { float source[]; }   the light of the previous iteration
//   buffer ... { float gvBlocking[]; } the GV (read only when HAS_GV and `occluded`)
//   buffer ... { vec4 gvAlbedo[]; }  the GV's albedo (read only when BOUNCES and `occluded`)
// and calls loadSourceCell(cell) and (with the GV) loadGvCorners(the cell all its transfers touch),
// then standardTransfer(...) per neighbour; the results are in the globals `transferred` (what
// reaches the neighbour) and `bounced` (what the GV's surfaces at the shared face re-emit into the
// source cell, standard_faces.glsl).
#ifndef LPVLAB_STANDARD_TRANSFER_GLSL
#define LPVLAB_STANDARD_TRANSFER_GLSL
#include "standard_faces.glsl"
#include "../common/grid.glsl"
#include "../common/geometry_volume_lookup.glsl"

float sourceCell[3 * N];   // coefficients of the cell being sent from, channel-major
float transferred[3 * N];  // what it sends to one neighbour
float bounced[3 * N];      // what the surfaces blocking that transfer re-emit into the source
vec4 gvCorners[8];         // the GV cells at the corners of light-grid cell gvCornerCell
vec4 gvAlbedoCorners[8];   // their albedo (with BOUNCES)
ivec3 gvCornerCell;

void loadSourceCell(int index, int cells) {
  for (int channel = 0; channel < 3; ++channel)
    for (int k = 0; k < N; ++k)
      sourceCell[channel * N + k] = source[coefficientIndex(channel, k, N, index, cells)];
}

// Loads the GV cells at the eight corners of light-grid cell `cell` (GV cells cell + {0,1}^3).
// Every face of the cell lies between them, so every crossing point of a transfer into the cell
// (gather: `cell` is the target) or out of it (scatter: the source) is interpolated from these
// registers: the GV is read 8 times per cell, not 30 x 8 times.
void loadGvCorners(ivec3 cell, ivec3 gvResolution) {
  gvCornerCell = cell;
  for (int corner = 0; corner < 8; ++corner) {
    ivec3 c = cell + ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    gvCorners[corner] = gvCell(c, gvResolution);
    if (BOUNCES)
      gvAlbedoCorners[corner] =
          cellInside(c, gvResolution) ? gvAlbedo[cellIndex(c, gvResolution)] : vec4(0.0);
  }
}

// The trilinear weight of corner `corner` of gvCornerCell at g (on a face of gvCornerCell: the
// bilinear interpolation of thesis fig. 4.3).
float gvCornerWeight(vec3 g, int corner) {
  vec3 f = clamp(g - vec3(gvCornerCell), 0.0, 1.0);
  vec3 w3 = mix(1.0 - f, f, vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1));
  return w3.x * w3.y * w3.z;
}

// gvBlockingAt(g) (geometry_volume_lookup.glsl) for g on a face of gvCornerCell.
vec4 gvBlockingFromCorners(vec3 g) {
  vec4 sum = vec4(0.0);
  for (int corner = 0; corner < 8; ++corner) sum += gvCornerWeight(g, corner) * gvCorners[corner];
  return sum;
}

// The albedo's (sum rho A, sum A) at g, interpolated as the blocking potential is.
vec4 gvAlbedoFromCorners(vec3 g) {
  vec4 sum = vec4(0.0);
  for (int corner = 0; corner < 8; ++corner)
    sum += gvCornerWeight(g, corner) * gvAlbedoCorners[corner];
  return sum;
}

// What the loaded source cell, at `from`, sends through the five faces of its neighbour one cell
// along the unit axis d (with `transfer`, into `transferred`), and, with BOUNCES and `bounce`,
// what the surfaces blocking that light re-emit into the source cell (into `bounced`);
// `occluded`: multiply each face's flux by the GV's transmittance where the face direction
// crosses the shared face (from the loaded GV corners of the source or of the neighbour: both
// have the shared face).
void standardTransfer(ivec3 from, vec3 d, bool occluded, bool transfer, bool bounce,
                      ivec3 resolution, float farSolidAngle, float sideSolidAngle) {
  for (int i = 0; i < 3 * N; ++i) {
    transferred[i] = 0.0;
    bounced[i] = 0.0;
  }
  vec3 sourceCentre = vec3(from) + 0.5;
  for (int f = 0; f < STANDARD_FACES; ++f) {
    vec3 direction = standardFaceDirection(d, f);
    vec3 normal = standardFaceNormal(d, f);
    float solidAngle = standardFaceSolidAngle(f, farSolidAngle, sideSolidAngle);
    float transmittance = 1.0;
    vec4 blocking = vec4(0.0);
    vec3 crossing = standardFaceCrossing(sourceCentre, d, f);
    if (HAS_GV && occluded) {
      blocking = gvBlockingFromCorners(crossing);
      transmittance = gvTransmittance(blocking, direction);
    }
    bool bounces = BOUNCES && bounce && occluded && transmittance < 1.0;
    vec3 albedo = vec3(0.0);
    vec3 surfaceNormal = -direction;
    if (bounces) {
      albedo = gvMeanAlbedo(gvAlbedoFromCorners(crossing));
      surfaceNormal = gvSurfaceNormal(blocking, direction);
    }
    float basis[N];
    float lobe[N];
    float bounceLobe[N];
    for (int k = 0; k < N; ++k) {
      basis[k] = shBasisAt(k, direction);
      lobe[k] = transfer ? shCosineLobeAt(k, normal) / PI : 0.0;
      bounceLobe[k] = shCosineLobeAt(k, surfaceNormal) / PI;
    }
    for (int channel = 0; channel < 3; ++channel) {
      float intensity = 0.0;
      for (int k = 0; k < N; ++k) intensity += sourceCell[channel * N + k] * basis[k];
      if (transfer) {
        float flux = standardFaceFlux(intensity, solidAngle, transmittance);
        for (int k = 0; k < N; ++k) transferred[channel * N + k] += flux * lobe[k];
      }
      if (bounces) {
        float reemitted =
            albedo[channel] * standardBlockedFlux(intensity, solidAngle, transmittance);
        for (int k = 0; k < N; ++k) bounced[channel * N + k] += reemitted * bounceLobe[k];
      }
    }
  }
}

#endif

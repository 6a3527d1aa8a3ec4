#pragma once
// Bias compensation for the VPL clamp (seed 001, 2.6; Kollig and Keller 2004, "Illumination in the
// presence of weak singularities"): the light the clamp min(c, G f_r) takes away, estimated by a
// short path-traced gather and added back, so that clamped instant radiosity plus its compensation
// has the expectation of unclamped instant radiosity, without its spikes.
//
// The light a Lambertian receiver x (albedo rho) gets from the surfaces y around it splits, per
// channel, as
//   L(x) = integral L_r(y) f_r G dA(y) = integral L_r(y) min(c, f_r G) dA(y)        (the VPLs)
//                                      + integral L_r(y) max(0, f_r G - c) dA(y)     (the bias)
// with f_r = rho / pi, G = cos(theta_x) cos(theta_y) / d^2 (visible pairs) and L_r(y) the light y
// reflects. In solid angle the bias is integral L_r(y(w)) f_r cos(theta_x) W(y) dw with the weight
// W = max(0, 1 - c / (f_r G)); for a cosine-distributed direction w its estimator is
//   rho * W(y(w)) * L_r(y(w)).
// W is zero unless f_r G > c, which needs d < r_c = sqrt(max(rho) / (pi c)): each direction's ray
// stops at r_c, and only the paths whose first hit lies where the clamp acts go on. That is the
// restriction to "the pixels and VPLs that were clamped", made exact: a pixel where no VPL
// happened to land near it still has a bias in expectation, so restricting to the pixels whose
// VPLs were clamped in this draw would leave that part out (docs/methods.md#clamp-compensation).
// Pairs closer than the gather's minimum distance, which the gather leaves out altogether, get
// W = 1.
//
// L_r(y) is estimated by the reference's integrator from y on (next-event estimation, BRDF
// sampling, Russian roulette): the light y reflects, with at most maxScatterings scatterings
// counted from the light to the camera, x included (the VPLs' walks' depth plus one), from the
// punctual lights the walks start at (emissive surfaces and the sky light nothing, as in the
// walks). Exact visibility; it does not depend on the VPLs, so it adds independent noise, not a
// second bias.

#include <cstdint>

#include "framework/pipeline/host_readback.h"

namespace lpvlab {

class RayScene;

struct ClampCompensationSettings {
  float clamp = 0.0f;         // c of the gather, 1/(m^2 sr); must be positive
  float minDistance = 1e-4f;  // the gather's: closer pairs get their whole G f_r back
  int samples = 4;            // directions per pixel
  int maxScatterings = 65;    // light-to-camera scatterings, x included (walks' max_bounces + 1)
  std::uint64_t seed = 1;
};

struct ClampCompensationCounts {
  double paths = 0.0;          // directions traced
  double weightedPaths = 0.0;  // of those, first hits where W > 0 (the clamp acts)
  double rays = 0.0;           // first, continuation and shadow rays
  double pixels = 0.0;         // covered pixels
  double compensatedPixels = 0.0;  // pixels that got some light back
  double radiance = 0.0;       // W/(m^2 sr) added, summed over pixels and RGB channels
};

// Adds the estimate of the clamped-away light to `indirect` (RGBA, the G-buffer's size) at each
// covered G-buffer pixel (position.w > 0). Pixel i's sample s draws from the stream
// (seed, i, s): the same estimate every frame while nothing moves, whatever the thread count.
// Throws an Error for a clamp that is not positive, samples below 1, or images of other sizes.
void compensateClamp(const HostImage& position, const HostImage& normal, const HostImage& albedo,
                     const RayScene& scene, const ClampCompensationSettings& settings,
                     HostImage& indirect, ClampCompensationCounts* counts = nullptr);

// The weight W of one pair (per channel): max(0, 1 - c / (f_r G)) with f_r = rho / pi and G =
// cosX cosY / d^2; 1 for d below minDistance (where the gather took everything away); 0 where
// either cosine is not positive.
glm::vec3 clampCompensationWeight(const glm::vec3& albedo, float cosX, float cosY, float distance,
                                  float clamp, float minDistance);

}  // namespace lpvlab

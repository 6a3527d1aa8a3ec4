#pragma once
// Temporal metrics of a sequence: how a frame's light changes from the previous frame's at the
// same surface points (docs/animation.md, "Temporal metrics", states the conventions).
//
// A Reprojection says, for each pixel of the current frame, where its surface point lies in the
// previous frame's image: up to four pixels there and their bilinear weights (which sum to 1).
// framework/reference/reprojection.h builds it from the depth and normal AOVs and the two
// cameras. A pixel whose point the previous frame did not see (disoccluded, outside the image,
// another surface at one of the four taps) has no taps and is left out of every figure here.
//
// frameToFrameChange(current, previous): over the pixels with taps (and in the mask), per channel
//   delta_i = c_i - sum_k w_ik p_j(i,k)     the value now less the previous frame's at that point
//   rms      = sqrt(mean_i mean_c delta^2)
//   meanAbs  = mean_i mean_c |delta|
//   level    = mean_i mean_c c_i            the current frame's mean over the same pixels
//   relative = rms / level                  unset when level is 0
// With only the camera moving, a view-independent light at a surface point should not change:
// delta is then the flicker the method adds (plus the error of interpolating the previous image
// between pixel centres, second order in the pixel size and 0 where taps fall on centres).
//
// temporalError(test now/before, reference now/before): the method's change against the
// reference's change at the same points, e_i = delta_test_i - delta_ref_i per channel, with the
// reference's Monte Carlo noise removed. The reference's two frames are independent estimates
// whose pixel means have the variances V (its <aov>_variance images), so
//   E[e_i^2] = (noise-free e_i)^2 + noise_i,   noise_i = V_now_i + sum_k w_ik^2 V_before_j(i,k)
// and meanSquare = mean_i mean_c (e_i^2 - noise_i) estimates the noise-free mean square without
// bias (it can come out negative when the true error is far below the noise). Its standard error
// is the spread of the per-pixel terms over sqrt(pixels): the path tracer's pixels are
// independent, so this is exact for taps on pixel centres and a slight underestimate where
// neighbouring pixels share bilinear taps. rms = sqrt(max(0, meanSquare)); relative divides by
// the reference's level (its mean now over the same pixels). Without variance images (the same
// reference entry for both frames, whose noise then cancels exactly) the noise term is 0.
//
// Every image must be RGB of the reprojection's size and finite (an Error names the image, pixel
// and channel otherwise); the mask is 1-channel, 0 = left out (metrics.h's convention).
//
// The lighting of a Lambertian output (demodulate): radiance albedo/pi * E divided by its albedo
// AOV, per pixel and channel, so that texture detail, which interpolating the previous image
// blurs (a floor under the change that grows with the textures' contrast), drops out and what is
// compared is the incident light alone. Pixels whose albedo is below a threshold in any channel
// have no lighting: they leave the mask, and so do current pixels with a tap on such a previous
// pixel (withoutTapsOnto). A variance image divides by albedo^2 (the albedo is exact, not noise).

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "framework/io/image.h"

namespace lpvlab {

struct Reprojection {
  struct Taps {
    std::array<std::int32_t, 4> pixel{};  // y * width + x in the previous frame
    std::array<float, 4> weight{};
    int count = 0;  // 0: the point was not seen in the previous frame
  };
  int width = 0, height = 0;  // of both frames
  std::vector<Taps> taps;     // per pixel of the current frame, row-major

  // Every pixel its own previous pixel (a frame compared with itself or a static view).
  static Reprojection identity(int width, int height);
  std::int64_t matched() const;
};

struct TemporalChange {
  double rms = 0.0, meanAbs = 0.0, level = 0.0;
  std::optional<double> relative;
  std::int64_t pixels = 0;       // pixels with taps in the mask
  double matchedFraction = 0.0;  // of the mask's pixels

  // {"rms", "mean_abs", "level", "relative" (null when unset), "pixels", "matched_fraction"}
  nlohmann::json toJson() const;
};

struct TemporalError {
  double rawMeanSquare = 0.0;    // mean e^2, noise included
  double noiseMeanSquare = 0.0;  // mean noise_i: what the reference's noise adds to it
  double meanSquare = 0.0;       // raw - noise: the noise-free estimate
  double meanSquareStandardError = 0.0;
  double rms = 0.0;    // sqrt(max(0, meanSquare))
  double level = 0.0;  // the reference's mean now
  std::optional<double> relative;
  std::int64_t pixels = 0;
  double matchedFraction = 0.0;

  // {"rms", "relative", "mean_square", "mean_square_standard_error", "raw_mean_square",
  //  "noise_mean_square", "level", "pixels", "matched_fraction"}
  nlohmann::json toJson() const;
};

// Throws an Error for images that do not match the reprojection, a mask of another size, or a
// mask and reprojection that leave no pixel.
TemporalChange frameToFrameChange(const Image& current, const Image& previous,
                                  const Reprojection& reprojection, const Image* mask = nullptr);

struct ReferencePair {
  const Image& now;
  const Image& before;
  const Image* nowVariance = nullptr;  // of the pixel means; both or neither
  const Image* beforeVariance = nullptr;
};

// Also throws for a variance that is negative or infinite (a reference of fewer than 2 samples
// per pixel has no variance estimate) and for only one of the two variance images.
TemporalError temporalError(const Image& testNow, const Image& testBefore,
                            const ReferencePair& reference, const Reprojection& reprojection,
                            const Image* mask = nullptr);

// `image` / `albedo` per pixel and channel, 0 where the albedo is below `minimumAlbedo` in any
// channel; `valid` (1-channel) is 1 where it is not. `squared`: divides by albedo^2 (variances).
// Throws an Error for images of different sizes or not RGB.
Image demodulate(const Image& image, const Image& albedo, float minimumAlbedo,
                 Image* valid = nullptr, bool squared = false);

// The reprojection without the current pixels that have a tap on a previous pixel where
// `previousValid` (1-channel, the previous frame's size) is 0.
Reprojection withoutTapsOnto(const Reprojection& reprojection, const Image& previousValid);

}  // namespace lpvlab

#include "framework/metrics/temporal.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/core/error.h"
#include "framework/metrics/mask.h"

namespace lpvlab {

namespace {

std::string sizeText(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

// The pixels both the mask and the reprojection keep, after checking that they fit the images.
struct Coverage {
  std::vector<std::size_t> pixels;  // current-frame pixels with taps, in the mask
  double matchedFraction = 0.0;
};

Coverage coverage(std::string_view where, const PixelMask& mask, const Reprojection& reprojection) {
  if (reprojection.width != mask.width || reprojection.height != mask.height ||
      reprojection.taps.size() != std::size_t(mask.width) * std::size_t(mask.height))
    throwAt(where, "the reprojection is for " + sizeText(reprojection.width, reprojection.height) +
                       " frames but the images are " + sizeText(mask.width, mask.height));
  const std::int64_t previousPixels = std::int64_t(mask.width) * mask.height;
  Coverage result;
  for (std::size_t p = 0; p < reprojection.taps.size(); ++p) {
    const Reprojection::Taps& taps = reprojection.taps[p];
    if (taps.count < 0 || taps.count > 4)
      throwAt(where, "reprojection pixel " + std::to_string(p) + " has " +
                         std::to_string(taps.count) + " taps; 0 to 4 expected");
    for (int k = 0; k < taps.count; ++k)
      if (taps.pixel[std::size_t(k)] < 0 || taps.pixel[std::size_t(k)] >= previousPixels)
        throwAt(where, "reprojection pixel " + std::to_string(p) + " taps pixel " +
                           std::to_string(taps.pixel[std::size_t(k)]) + ", outside the image");
    if (mask.covers(p) && taps.count > 0) result.pixels.push_back(p);
  }
  if (result.pixels.empty())
    throwAt(where, "no pixel of the mask was seen in the previous frame (nothing to compare)");
  result.matchedFraction = double(result.pixels.size()) / double(mask.count);
  return result;
}

// The previous frame's value of channel c at current pixel p's point.
double reprojected(const Image& previous, const Reprojection::Taps& taps, int c) {
  double value = 0.0;
  for (int k = 0; k < taps.count; ++k)
    value += double(taps.weight[std::size_t(k)]) *
             previous.pixels[std::size_t(taps.pixel[std::size_t(k)]) * 3 + std::size_t(c)];
  return value;
}

// The variance of that interpolated value: independent pixels, so the squared weights.
double reprojectedVariance(const Image& variance, const Reprojection::Taps& taps, int c) {
  double value = 0.0;
  for (int k = 0; k < taps.count; ++k) {
    const double w = taps.weight[std::size_t(k)];
    value += w * w * variance.pixels[std::size_t(taps.pixel[std::size_t(k)]) * 3 + std::size_t(c)];
  }
  return value;
}

nlohmann::json optionalJson(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

void requireVariances(std::string_view where, std::string_view name, const Image& variance) {
  for (std::size_t i = 0; i < variance.pixels.size(); ++i)
    if (!(variance.pixels[i] >= 0.0f))  // finite already checked
      throwAt(where, std::string(name) + " value " + std::to_string(variance.pixels[i]) +
                         " at pixel " + std::to_string(i / 3) + " is negative; a variance is not");
}

}  // namespace

Reprojection Reprojection::identity(int width, int height) {
  Reprojection r;
  r.width = width;
  r.height = height;
  r.taps.resize(std::size_t(width) * std::size_t(height));
  for (std::size_t p = 0; p < r.taps.size(); ++p) {
    r.taps[p].count = 1;
    r.taps[p].pixel[0] = std::int32_t(p);
    r.taps[p].weight[0] = 1.0f;
  }
  return r;
}

std::int64_t Reprojection::matched() const {
  std::int64_t n = 0;
  for (const Taps& t : taps) n += t.count > 0;
  return n;
}

nlohmann::json TemporalChange::toJson() const {
  return {{"rms", rms},       {"mean_abs", meanAbs},
          {"level", level},   {"relative", optionalJson(relative)},
          {"pixels", pixels}, {"matched_fraction", matchedFraction}};
}

nlohmann::json TemporalError::toJson() const {
  return {{"rms", rms},
          {"relative", optionalJson(relative)},
          {"mean_square", meanSquare},
          {"mean_square_standard_error", meanSquareStandardError},
          {"raw_mean_square", rawMeanSquare},
          {"noise_mean_square", noiseMeanSquare},
          {"level", level},
          {"pixels", pixels},
          {"matched_fraction", matchedFraction}};
}

TemporalChange frameToFrameChange(const Image& current, const Image& previous,
                                  const Reprojection& reprojection, const Image* mask) {
  constexpr std::string_view where = "frameToFrameChange";
  const PixelMask covered = checkInputs(where, current, previous, mask, "current", "previous");
  const Coverage kept = coverage(where, covered, reprojection);
  // Sums in double: a frame has millions of terms, and float sums would lose the small changes
  // this measures.
  double sumSquares = 0.0, sumAbs = 0.0, sumLevel = 0.0;
  for (std::size_t p : kept.pixels)
    for (int c = 0; c < 3; ++c) {
      const double now = current.pixels[p * 3 + std::size_t(c)];
      const double delta = now - reprojected(previous, reprojection.taps[p], c);
      sumSquares += delta * delta;
      sumAbs += std::abs(delta);
      sumLevel += now;
    }
  const double n = 3.0 * double(kept.pixels.size());
  TemporalChange change;
  change.rms = std::sqrt(sumSquares / n);
  change.meanAbs = sumAbs / n;
  change.level = sumLevel / n;
  if (change.level > 0.0) change.relative = change.rms / change.level;
  change.pixels = std::int64_t(kept.pixels.size());
  change.matchedFraction = kept.matchedFraction;
  return change;
}

TemporalError temporalError(const Image& testNow, const Image& testBefore,
                            const ReferencePair& reference, const Reprojection& reprojection,
                            const Image* mask) {
  constexpr std::string_view where = "temporalError";
  const PixelMask covered =
      checkInputs(where, testNow, testBefore, mask, "test (now)", "test (before)");
  checkInputs(where, testNow, reference.now, mask, "test (now)", "reference (now)");
  checkInputs(where, testNow, reference.before, mask, "test (now)", "reference (before)");
  if ((reference.nowVariance == nullptr) != (reference.beforeVariance == nullptr))
    throwAt(where, "the reference's variance is given for one frame only; give both or neither");
  if (reference.nowVariance) {
    checkInputs(where, testNow, *reference.nowVariance, mask, "test (now)",
                "reference variance (now)");
    checkInputs(where, testNow, *reference.beforeVariance, mask, "test (now)",
                "reference variance (before)");
    requireVariances(where, "reference variance (now)", *reference.nowVariance);
    requireVariances(where, "reference variance (before)", *reference.beforeVariance);
  }
  const Coverage kept = coverage(where, covered, reprojection);

  // Per pixel: the mean over channels of e^2 - noise, whose spread gives the standard error.
  double sumRaw = 0.0, sumNoise = 0.0, sumTerm = 0.0, sumTermSquares = 0.0, sumLevel = 0.0;
  for (std::size_t p : kept.pixels) {
    const Reprojection::Taps& taps = reprojection.taps[p];
    double pixelRaw = 0.0, pixelNoise = 0.0;
    for (int c = 0; c < 3; ++c) {
      const std::size_t i = p * 3 + std::size_t(c);
      const double testChange = double(testNow.pixels[i]) - reprojected(testBefore, taps, c);
      const double referenceChange =
          double(reference.now.pixels[i]) - reprojected(reference.before, taps, c);
      const double e = testChange - referenceChange;
      pixelRaw += e * e;
      if (reference.nowVariance)
        pixelNoise += double(reference.nowVariance->pixels[i]) +
                      reprojectedVariance(*reference.beforeVariance, taps, c);
      sumLevel += reference.now.pixels[i];
    }
    const double term = (pixelRaw - pixelNoise) / 3.0;
    sumRaw += pixelRaw / 3.0;
    sumNoise += pixelNoise / 3.0;
    sumTerm += term;
    sumTermSquares += term * term;
  }
  const double n = double(kept.pixels.size());
  TemporalError error;
  error.rawMeanSquare = sumRaw / n;
  error.noiseMeanSquare = sumNoise / n;
  error.meanSquare = sumTerm / n;
  // The sample standard deviation of the terms over sqrt(n); 0 for a single pixel.
  const double spread =
      n > 1.0 ? std::max(0.0, (sumTermSquares - sumTerm * sumTerm / n) / (n - 1.0)) : 0.0;
  error.meanSquareStandardError = std::sqrt(spread / n);
  error.rms = std::sqrt(std::max(0.0, error.meanSquare));
  error.level = sumLevel / (3.0 * n);
  if (error.level > 0.0) error.relative = error.rms / error.level;
  error.pixels = std::int64_t(kept.pixels.size());
  error.matchedFraction = kept.matchedFraction;
  return error;
}

Image demodulate(const Image& image, const Image& albedo, float minimumAlbedo, Image* valid,
                 bool squared) {
  if (image.channels != 3 || albedo.channels != 3 || image.width != albedo.width ||
      image.height != albedo.height)
    throw Error("demodulating: the image (" + sizeText(image.width, image.height) + ", " +
                std::to_string(image.channels) + " channels) and the albedo (" +
                sizeText(albedo.width, albedo.height) + ", " + std::to_string(albedo.channels) +
                " channels) must both be RGB of one size");
  Image out(image.width, image.height, 3);
  if (valid) *valid = Image(image.width, image.height, 1);
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  for (std::size_t p = 0; p < pixels; ++p) {
    const float* a = &albedo.pixels[3 * p];
    // A NaN albedo fails the comparison too, and leaves the pixel out.
    const bool known = a[0] >= minimumAlbedo && a[1] >= minimumAlbedo && a[2] >= minimumAlbedo;
    if (valid) valid->pixels[p] = known ? 1.0f : 0.0f;
    if (!known) continue;
    for (int c = 0; c < 3; ++c)
      out.pixels[3 * p + std::size_t(c)] =
          image.pixels[3 * p + std::size_t(c)] / (squared ? a[c] * a[c] : a[c]);
  }
  return out;
}

Reprojection withoutTapsOnto(const Reprojection& reprojection, const Image& previousValid) {
  if (previousValid.width != reprojection.width || previousValid.height != reprojection.height ||
      previousValid.channels != 1)
    throw Error("reprojection: the previous frame's valid pixels must be 1-channel, " +
                sizeText(reprojection.width, reprojection.height));
  Reprojection out = reprojection;
  for (Reprojection::Taps& taps : out.taps)
    for (int k = 0; k < taps.count; ++k)
      if (previousValid.pixels[std::size_t(taps.pixel[std::size_t(k)])] == 0.0f) {
        taps.count = 0;
        break;
      }
  return out;
}

}  // namespace lpvlab

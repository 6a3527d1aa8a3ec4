#include "framework/metrics/mask.h"

#include <cmath>
#include <string>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

std::string sizeOf(const Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void requireRgb(std::string_view where, std::string_view name, const Image& image) {
  if (image.channels != 3)
    throwAt(where, std::string(name) + " image has " + std::to_string(image.channels) +
                       " channels; RGB (3) expected");
  if (image.width <= 0 || image.height <= 0)
    throwAt(where, std::string(name) + " image is empty (" + sizeOf(image) + ")");
}

// Every value, background included: a NaN is a bug upstream that a metric must not hide.
void requireFinitePixels(std::string_view where, std::string_view name, const Image& image) {
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (std::isfinite(image.pixels[i])) continue;
    const std::size_t pixel = i / image.channels;
    throwAt(where, std::string(name) + " pixel (" + std::to_string(pixel % image.width) + ", " +
                       std::to_string(pixel / image.width) + ") channel " +
                       std::to_string(i % image.channels) + " is not finite (NaN or Inf)");
  }
}

}  // namespace

PixelMask checkInputs(std::string_view where, const Image& test, const Image& reference,
                      const Image* mask, std::string_view testName,
                      std::string_view referenceName) {
  requireRgb(where, testName, test);
  requireRgb(where, referenceName, reference);
  if (test.width != reference.width || test.height != reference.height)
    throwAt(where, std::string(testName) + " image is " + sizeOf(test) + " but " +
                       std::string(referenceName) + " is " + sizeOf(reference) +
                       "; they must have the same size");
  requireFinitePixels(where, testName, test);
  requireFinitePixels(where, referenceName, reference);

  PixelMask result;
  result.width = reference.width;
  result.height = reference.height;
  result.covered.assign(std::size_t(result.width) * result.height, 1);
  if (mask) {
    if (mask->channels != 1 || mask->width != result.width || mask->height != result.height)
      throwAt(where, "mask is " + sizeOf(*mask) + " with " + std::to_string(mask->channels) +
                         " channels; a 1-channel mask of the images' size " + sizeOf(reference) +
                         " expected");
    requireFinitePixels(where, "mask", *mask);
    for (std::size_t p = 0; p < result.covered.size(); ++p)
      result.covered[p] = mask->pixels[p] != 0.0f;
  }
  for (std::uint8_t c : result.covered) result.count += c;
  if (result.count == 0) throwAt(where, "the mask covers no pixel (every mask value is 0)");
  return result;
}

}  // namespace lpvlab

#pragma once
// The pixels a metric covers, found while checking the inputs every metric shares: RGB images of
// one size, finite values, and an optional 1-channel mask of that size (0 = background).

#include <cstdint>
#include <string_view>
#include <vector>

#include "framework/io/image.h"

namespace lpvlab {

struct PixelMask {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> covered;  // per pixel, row-major: 1 covered, 0 background
  std::int64_t count = 0;             // covered pixels, at least 1

  bool covers(std::size_t pixel) const { return covered[pixel] != 0; }
};

// Throws an Error starting with `where` (the calling function) that names the sizes, the channel
// counts, or the image, pixel and channel of a NaN or Inf; the images are called by the names
// given.
PixelMask checkInputs(std::string_view where, const Image& test, const Image& reference,
                      const Image* mask, std::string_view testName = "test",
                      std::string_view referenceName = "reference");

}  // namespace lpvlab

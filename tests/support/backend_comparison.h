#pragma once
// Comparing an image of the CPU backend with GL's. The strategies' kernels agree to float
// rounding everywhere. Direct light agrees to float rounding but for rare shadow-map texels:
// GL compares a point's window depth with a stored depth in float, the CPU in double, so where
// the two are within rounding of each other (grazing surfaces, a shadow's edge) one of a tap's
// four comparisons can come out the other way; a comparison weighs at most one of the nine taps,
// so such a pixel differs by at most 1/9 of its unshadowed light.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "framework/io/image.h"

namespace lpvlab::test {

struct ImageDifference {
  double largest = 0.0;   // max |cpu - gl|
  double scale = 0.0;     // max |gl|
  double differing = 0.0; // fraction of values with |cpu - gl| > 1e-4 scale
  double total = 0.0;     // sum |cpu - gl| / sum |gl|
};

inline ImageDifference difference(const Image& cpu, const Image& gl) {
  ImageDifference d;
  double sum = 0.0, sumGl = 0.0;
  for (std::size_t i = 0; i < gl.pixels.size(); ++i) d.scale = std::max(d.scale, double(std::abs(gl.pixels[i])));
  std::size_t differing = 0;
  for (std::size_t i = 0; i < gl.pixels.size(); ++i) {
    const double delta = std::abs(double(cpu.pixels[i]) - double(gl.pixels[i]));
    d.largest = std::max(d.largest, delta);
    sum += delta;
    sumGl += std::abs(double(gl.pixels[i]));
    differing += delta > 1e-4 * d.scale ? 1 : 0;
  }
  d.differing = gl.pixels.empty() ? 0.0 : double(differing) / double(gl.pixels.size());
  d.total = sumGl > 0.0 ? sum / sumGl : sum;
  return d;
}

// Everywhere within 1e-4 of the image's largest value: kernels that agree to float rounding.
inline void expectSameImage(const Image& cpu, const Image& gl, const std::string& what) {
  ASSERT_EQ(cpu.pixels.size(), gl.pixels.size()) << what;
  const ImageDifference d = difference(cpu, gl);
  EXPECT_GT(d.scale, 0.0) << what;
  EXPECT_LE(d.largest, 1e-4 * d.scale) << what;
}

// Direct light (or an image with it): as above but for at most 0.5% of the values, each off by
// less than 1/9 of the image's largest value, and 1e-4 of the image's light in all. A black
// image (a scene lit by the sky alone) must be black on both.
inline void expectSameDirectLight(const Image& cpu, const Image& gl, const std::string& what) {
  ASSERT_EQ(cpu.pixels.size(), gl.pixels.size()) << what;
  const ImageDifference d = difference(cpu, gl);
  if (d.scale == 0.0) {
    EXPECT_EQ(d.largest, 0.0) << what << ": black on GL, not on the CPU";
    return;
  }
  EXPECT_LE(d.differing, 0.005) << what;
  EXPECT_LT(d.largest, d.scale / 9.0) << what;
  EXPECT_LT(d.total, 1e-4) << what;
}

}  // namespace lpvlab::test

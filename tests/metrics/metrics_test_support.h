#pragma once
// Test images and helpers shared by the metrics tests.

#include <cmath>
#include <functional>
#include <initializer_list>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/io/image.h"

namespace lpvlab::test {

inline Image constantImage(int w, int h, float r, float g, float b) {
  Image image(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.at(x, y, 0) = r, image.at(x, y, 1) = g, image.at(x, y, 2) = b;
  return image;
}

// Smooth structure plus noise, every value in [0.1, 0.6], different per channel.
inline Image patternImage(int w, int h, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> noise(-0.05f, 0.05f);
  Image image(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = 0.35f + 0.15f * std::sin(0.3f * x + 0.2f * y + c) + noise(random);
  return image;
}

inline Image plus(Image image, float offset) {
  for (float& value : image.pixels) value += offset;
  return image;
}

// 1 everywhere except a rectangle of 0 (background) at [x0, x1) x [y0, y1).
inline Image maskWithHole(int w, int h, int x0, int y0, int x1, int y1) {
  Image mask(w, h, 1, 1.0f);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) mask.at(x, y, 0) = 0.0f;
  return mask;
}

// The sRGB transfer function written out here, independent of the code under test.
inline double srgb(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// Runs `action`, expecting an Error whose message contains every fragment.
inline void expectError(const std::function<void()>& action,
                        std::initializer_list<std::string> fragments) {
  try {
    action();
    ADD_FAILURE() << "no Error; expected one mentioning '" << *fragments.begin() << "'";
  } catch (const Error& error) {
    for (const std::string& fragment : fragments)
      EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos)
          << "message: " << error.what() << "\nexpected to contain: " << fragment;
  }
}

}  // namespace lpvlab::test

// The temporal metrics (framework/metrics/temporal.h) on hand-computed cases and on synthetic
// noise whose statistics are known.

#include "framework/metrics/temporal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "metrics_test_support.h"

namespace lpvlab {
namespace {

Image rgb(int w, int h, std::initializer_list<float> values) {
  Image image(w, h, 3);
  std::size_t i = 0;
  for (float v : values) image.pixels.at(i++) = v;
  EXPECT_EQ(i, image.pixels.size());
  return image;
}

Reprojection::Taps taps(std::initializer_list<std::pair<int, float>> pixelsAndWeights) {
  Reprojection::Taps t;
  for (const auto& [pixel, weight] : pixelsAndWeights) {
    t.pixel[std::size_t(t.count)] = pixel;
    t.weight[std::size_t(t.count)] = weight;
    ++t.count;
  }
  return t;
}

// A 2x1 frame whose pixels were where `first` and `second` say.
Reprojection twoPixels(const Reprojection::Taps& first, const Reprojection::Taps& second) {
  Reprojection r;
  r.width = 2;
  r.height = 1;
  r.taps = {first, second};
  return r;
}

TEST(TemporalChange, AFrameAgainstItselfThroughTheIdentityIsZero) {
  const Image frame = test::patternImage(33, 17, 4);
  const TemporalChange change = frameToFrameChange(frame, frame, Reprojection::identity(33, 17));
  EXPECT_EQ(change.rms, 0.0);
  EXPECT_EQ(change.meanAbs, 0.0);
  ASSERT_TRUE(change.relative.has_value());
  EXPECT_EQ(*change.relative, 0.0);
  EXPECT_EQ(change.pixels, 33 * 17);
  EXPECT_EQ(change.matchedFraction, 1.0);
  double sum = 0.0;
  for (float v : frame.pixels) sum += v;
  EXPECT_NEAR(change.level, sum / double(frame.pixels.size()), 1e-12);
}

TEST(TemporalChange, ReproducesAHandComputedTwoFrameCase) {
  // Pixel 0 was at pixel 1; pixel 1 halfway between pixels 0 and 1.
  const Image now = rgb(2, 1, {1, 2, 3, 4, 4, 4});
  const Image before = rgb(2, 1, {0, 0, 0, 2, 2, 2});
  const Reprojection r = twoPixels(taps({{1, 1.0f}}), taps({{0, 0.5f}, {1, 0.5f}}));
  // Deltas: (1-2, 2-2, 3-2) = (-1, 0, 1) and (4-1, 4-1, 4-1) = (3, 3, 3).
  const TemporalChange change = frameToFrameChange(now, before, r);
  EXPECT_DOUBLE_EQ(change.rms, std::sqrt(29.0 / 6.0));
  EXPECT_DOUBLE_EQ(change.meanAbs, 11.0 / 6.0);
  EXPECT_DOUBLE_EQ(change.level, 18.0 / 6.0);
  EXPECT_DOUBLE_EQ(*change.relative, std::sqrt(29.0 / 6.0) / 3.0);
  EXPECT_EQ(change.pixels, 2);
}

TEST(TemporalChange, UnseenAndMaskedPixelsAreLeftOut) {
  const Image now = rgb(3, 1, {1, 1, 1, 5, 5, 5, 100, 100, 100});
  const Image before = rgb(3, 1, {0, 0, 0, 5, 5, 5, -7, -7, -7});
  Reprojection r = Reprojection::identity(3, 1);
  r.taps[2].count = 0;  // not seen before
  Image mask(3, 1, 1, 1.0f);
  mask.pixels[0] = 0.0f;  // background
  const TemporalChange change = frameToFrameChange(now, before, r, &mask);
  EXPECT_EQ(change.pixels, 1);
  EXPECT_EQ(change.rms, 0.0);
  EXPECT_DOUBLE_EQ(change.level, 5.0);
  EXPECT_DOUBLE_EQ(change.matchedFraction, 0.5);  // of the mask's two pixels
}

TEST(TemporalChange, ABlackFrameHasNoRelativeChange) {
  const Image black(4, 4, 3, 0.0f);
  const TemporalChange change = frameToFrameChange(black, black, Reprojection::identity(4, 4));
  EXPECT_FALSE(change.relative.has_value());
  EXPECT_TRUE(change.toJson()["relative"].is_null());
}

TEST(TemporalError, ReproducesAHandComputedCaseWithTheNoiseRemoved) {
  const Image testNow = rgb(2, 1, {2, 2, 2, 1, 1, 1});
  const Image testBefore = rgb(2, 1, {1, 1, 1, 1, 1, 1});
  const Image refNow = rgb(2, 1, {3, 3, 3, 1, 1, 1});
  const Image refBefore = rgb(2, 1, {1, 1, 1, 3, 3, 3});
  const Image varNow = rgb(2, 1, {0.5f, 0.5f, 0.5f, 0.25f, 0.25f, 0.25f});
  const Image varBefore = rgb(2, 1, {1, 1, 1, 2, 2, 2});
  const Reprojection r = twoPixels(taps({{0, 1.0f}}), taps({{0, 0.5f}, {1, 0.5f}}));
  // Pixel 0: test change 1, reference change 2, e = -1; noise 0.5 + 1 = 1.5; term -0.5.
  // Pixel 1: test change 1 - 1 = 0, reference change 1 - 2 = -1, e = 1;
  //          noise 0.25 + 0.25 * 1 + 0.25 * 2 = 1; term 0.
  const TemporalError error =
      temporalError(testNow, testBefore, {refNow, refBefore, &varNow, &varBefore}, r);
  EXPECT_DOUBLE_EQ(error.rawMeanSquare, 1.0);
  EXPECT_DOUBLE_EQ(error.noiseMeanSquare, 1.25);
  EXPECT_DOUBLE_EQ(error.meanSquare, -0.25);
  EXPECT_EQ(error.rms, 0.0);  // clamped: below the noise
  // The terms -0.5 and 0: sample standard deviation sqrt(0.125), over sqrt(2).
  EXPECT_DOUBLE_EQ(error.meanSquareStandardError, std::sqrt(0.125 / 2.0));
  EXPECT_DOUBLE_EQ(error.level, 2.0);

  // Without variances (one reference for both frames) nothing is subtracted.
  const TemporalError raw = temporalError(testNow, testBefore, {refNow, refBefore}, r);
  EXPECT_DOUBLE_EQ(raw.meanSquare, 1.0);
  EXPECT_DOUBLE_EQ(raw.rms, 1.0);
  EXPECT_DOUBLE_EQ(*raw.relative, 0.5);
}

// Two independent noisy estimates of one static frame, with their variances: the method does not
// change (its error is the reference's noise alone), so the corrected error is consistent with 0
// while the raw one is clearly not; and a real change of the method's light is recovered.
TEST(TemporalError, TheNoiseCorrectionRemovesIndependentReferenceNoise) {
  const int w = 96, h = 64;
  const Image truth = test::patternImage(w, h, 9);
  std::mt19937 random(2024);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  const auto noisy = [&](Image& estimate, Image& variance) {
    estimate = truth;
    variance = Image(w, h, 3);
    for (std::size_t i = 0; i < estimate.pixels.size(); ++i) {
      const float sigma = 0.02f + 0.1f * truth.pixels[i];  // varies over the image
      estimate.pixels[i] += sigma * gauss(random);
      variance.pixels[i] = sigma * sigma;
    }
  };
  Image refNow, refBefore, varNow, varBefore;
  noisy(refNow, varNow);
  noisy(refBefore, varBefore);
  const Reprojection identity = Reprojection::identity(w, h);

  const TemporalError still =
      temporalError(truth, truth, {refNow, refBefore, &varNow, &varBefore}, identity);
  EXPECT_LT(std::abs(still.meanSquare), 4.0 * still.meanSquareStandardError)
      << still.toJson().dump();
  EXPECT_GT(still.rawMeanSquare, 20.0 * still.meanSquareStandardError);
  EXPECT_NEAR(still.rawMeanSquare, still.noiseMeanSquare, 4.0 * still.meanSquareStandardError);

  // The method brightens by 0.05 between the frames and the reference does not: the noise-free
  // mean square error of the change is 0.05^2.
  const TemporalError moved = temporalError(test::plus(truth, 0.05f), truth,
                                            {refNow, refBefore, &varNow, &varBefore}, identity);
  EXPECT_NEAR(moved.meanSquare, 0.05 * 0.05, 4.0 * moved.meanSquareStandardError)
      << moved.toJson().dump();
  EXPECT_GT(moved.meanSquare, 8.0 * moved.meanSquareStandardError);
}

TEST(Lighting, DemodulatingDividesByTheAlbedoAndLeavesOutDarkOrUnknownAlbedo) {
  const float nan = std::nanf("");
  const Image radiance = rgb(3, 1, {0.2f, 0.4f, 0.6f, 1.0f, 1.0f, 1.0f, 0.5f, 0.5f, 0.5f});
  const Image albedo = rgb(3, 1, {0.5f, 0.8f, 0.25f, 0.5f, 0.01f, 0.5f, nan, 0.5f, 0.5f});
  Image valid;
  const Image lighting = demodulate(radiance, albedo, 0.02f, &valid);
  EXPECT_FLOAT_EQ(lighting.at(0, 0, 0), 0.4f);
  EXPECT_FLOAT_EQ(lighting.at(0, 0, 1), 0.5f);
  EXPECT_FLOAT_EQ(lighting.at(0, 0, 2), 2.4f);
  EXPECT_EQ(valid.pixels, (std::vector<float>{1.0f, 0.0f, 0.0f})) << "a channel below 2 %, a NaN";
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(lighting.at(1, 0, c), 0.0f);
    EXPECT_EQ(lighting.at(2, 0, c), 0.0f);
  }
  // A variance divides by the albedo's square.
  EXPECT_FLOAT_EQ(demodulate(radiance, albedo, 0.02f, nullptr, true).at(0, 0, 2), 0.6f / 0.0625f);
  EXPECT_THROW(demodulate(radiance, Image(3, 1, 1), 0.02f), Error);
}

// A textured surface under constant light, seen half a pixel further along: the output's change is
// the texture's contrast interpolated (a floor that has nothing to do with the light); its
// lighting's change is exactly zero.
TEST(Lighting, TextureDetailDropsOutOfTheLightingsChange) {
  const int w = 64;
  std::mt19937 random(3);
  std::uniform_real_distribution<float> texture(0.1f, 0.9f);
  Image albedo(w, 1, 3), radiance(w, 1, 3);
  for (int x = 0; x < w; ++x)
    for (int c = 0; c < 3; ++c) {
      albedo.at(x, 0, c) = texture(random);
      radiance.at(x, 0, c) = albedo.at(x, 0, c) * 2.5f / float(M_PI);  // E = 2.5 W/m^2
    }
  Reprojection halfPixel;
  halfPixel.width = w;
  halfPixel.height = 1;
  halfPixel.taps.resize(std::size_t(w));
  for (int x = 0; x + 1 < w; ++x) halfPixel.taps[std::size_t(x)] = taps({{x, 0.5f}, {x + 1, 0.5f}});
  const TemporalChange output = frameToFrameChange(radiance, radiance, halfPixel);
  Image valid;
  const Image lighting = demodulate(radiance, albedo, 0.02f, &valid);
  const TemporalChange light = frameToFrameChange(lighting, lighting, halfPixel, &valid);
  EXPECT_GT(*output.relative, 0.1);
  EXPECT_LT(*light.relative, 1e-6);
  EXPECT_EQ(light.pixels, w - 1);
}

TEST(Lighting, PixelsWithATapOntoALeftOutPixelAreLeftOut) {
  const Reprojection r = twoPixels(taps({{0, 0.5f}, {1, 0.5f}}), taps({{1, 1.0f}}));
  Image previousValid(2, 1, 1);
  previousValid.pixels = {0.0f, 1.0f};
  const Reprojection kept = withoutTapsOnto(r, previousValid);
  EXPECT_EQ(kept.taps[0].count, 0);
  EXPECT_EQ(kept.taps[1].count, 1);
  EXPECT_EQ(kept.matched(), 1);
  EXPECT_THROW(withoutTapsOnto(r, Image(3, 1, 1)), Error);
}

TEST(TemporalMetrics, BadInputsAreErrorsNamingTheProblem) {
  const Image a = test::patternImage(4, 4, 1);
  const Image small = test::patternImage(3, 4, 1);
  const Reprojection identity = Reprojection::identity(4, 4);
  EXPECT_THROW(
      {
        try {
          frameToFrameChange(a, small, identity);
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("but previous is 3x4"), std::string::npos)
              << e.what();
          throw;
        }
      },
      Error);
  EXPECT_THROW(frameToFrameChange(small, small, identity), Error);  // reprojection's size
  Image nan = a;
  nan.pixels[5] = std::nanf("");
  EXPECT_THROW(frameToFrameChange(a, nan, identity), Error);
  Reprojection outside = identity;
  outside.taps[0].pixel[0] = 16;
  EXPECT_THROW(frameToFrameChange(a, a, outside), Error);
  Reprojection unseen = identity;
  for (auto& t : unseen.taps) t.count = 0;
  EXPECT_THROW(frameToFrameChange(a, a, unseen), Error);

  Image negative(4, 4, 3, 0.1f);
  negative.pixels[7] = -1.0f;
  const Image variance(4, 4, 3, 0.1f);
  EXPECT_THROW(temporalError(a, a, {a, a, &negative, &variance}, identity), Error);
  EXPECT_THROW(temporalError(a, a, {a, a, &variance, nullptr}, identity), Error);
  Image infinite = variance;
  infinite.pixels[0] = INFINITY;  // fewer than 2 samples: no variance estimate
  EXPECT_THROW(temporalError(a, a, {a, a, &infinite, &variance}, identity), Error);
}

}  // namespace
}  // namespace lpvlab

#include "framework/io/image.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

using Strings = std::vector<std::string>;

// Distinct, non-round values in every pixel and channel, so a swapped channel, a flipped row or
// a half-float conversion would show.
Image pattern(int w, int h, int c, float seed) {
  Image image(w, h, c);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < c; ++k)
        image.at(x, y, k) = seed + x * 0.1234567f + y * 1.7654321f + k / 3.0f;
  return image;
}

const NamedImage* find(const std::vector<NamedImage>& aovs, const std::string& name) {
  for (const NamedImage& aov : aovs)
    if (aov.name == name) return &aov;
  return nullptr;
}

std::vector<NamedImage> sampleAovs() {
  return {{"direct", pattern(7, 5, 3, 0.5f)},
          {"depth", pattern(7, 5, 1, 10.0f)},
          {"indirect", pattern(7, 5, 3, -2.0f)},
          {"mask", pattern(7, 5, 1, 1e-7f)}};
}

TEST(Exr, RoundTripIsExact) {
  test::TempDir dir;
  const auto aovs = sampleAovs();
  writeExr(dir.file("frame.exr"), aovs);
  const std::vector<NamedImage> back = readExr(dir.file("frame.exr"));
  ASSERT_EQ(back.size(), aovs.size());
  for (const NamedImage& aov : aovs) {
    const NamedImage* read = find(back, aov.name);
    ASSERT_NE(read, nullptr) << aov.name;
    EXPECT_EQ(read->image.width, 7);
    EXPECT_EQ(read->image.height, 5);
    EXPECT_EQ(read->image.channels, aov.image.channels);
    EXPECT_EQ(read->image.pixels, aov.image.pixels) << aov.name;
  }
  EXPECT_EQ(dir.entries(), Strings{"frame.exr"});
}

TEST(Exr, ChannelNamesTypeAndMetadataInTheFile) {
  test::TempDir dir;
  writeExr(dir.file("frame.exr"), sampleAovs(), {{"lpvlab:config_hash", "0123456789abcdef"}});
  auto in = OIIO::ImageInput::open(dir.file("frame.exr"));
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  Strings names(spec.channelnames.begin(), spec.channelnames.end());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (Strings{"depth.Z", "direct.B", "direct.G", "direct.R", "indirect.B",
                            "indirect.G", "indirect.R", "mask.Y"}));
  EXPECT_EQ(spec.format, OIIO::TypeDesc::FLOAT);
  EXPECT_EQ(spec.get_string_attribute("lpvlab:config_hash"), "0123456789abcdef");
  EXPECT_EQ(spec.get_string_attribute("compression"), "zip");
}

TEST(Exr, MismatchedSizesAreAnError) {
  test::TempDir dir;
  EXPECT_THROW(writeExr(dir.file("bad.exr"), {{"a", Image(4, 4, 3)}, {"b", Image(4, 3, 3)}}),
               Error);
  EXPECT_EQ(dir.entries(), Strings{});
}

TEST(Exr, ReadingAMissingFileNamesIt) {
  test::TempDir dir;
  try {
    readExr(dir.file("absent.exr"));
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(dir.file("absent.exr")), std::string::npos) << e.what();
  }
}

// The 8-bit value stored for one pixel of a one-pixel image.
int pngValue(const test::TempDir& dir, float linear, float exposure, bool tonemap) {
  const std::string path = dir.file("pixel.png");
  writePng(path, Image(1, 1, 3, linear), exposure, tonemap ? ToneCurve::Reinhard : ToneCurve::Clamp);
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw Error(OIIO::geterror());
  unsigned char rgb[3];
  in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, rgb);
  EXPECT_EQ(rgb[0], rgb[1]);
  EXPECT_EQ(rgb[0], rgb[2]);
  return rgb[0];
}

// Expected bytes: round(255 * srgb(display)), e.g. srgb(0.5) * 255 = 187.52, srgb(2/3) = 213.18.
TEST(Png, ExposureAndToneCurve) {
  test::TempDir dir;
  EXPECT_EQ(pngValue(dir, 1.0f, 0.0f, true), 188);    // 1 / (1 + 1) = 0.5
  EXPECT_EQ(pngValue(dir, 1.0f, 1.0f, true), 213);    // 2 / (1 + 2) = 2/3
  EXPECT_EQ(pngValue(dir, 0.5f, 0.0f, false), 188);   // clamp leaves 0.5
  EXPECT_EQ(pngValue(dir, 0.25f, 1.0f, false), 188);  // 0.25 * 2 = 0.5
  EXPECT_EQ(pngValue(dir, 0.7f, 1.0f, false), 255);   // 1.4 clamps to 1
  EXPECT_EQ(pngValue(dir, 0.002f, 0.0f, false), 7);   // linear segment: 12.92 * 0.002 * 255
  EXPECT_EQ(pngValue(dir, -3.0f, 0.0f, true), 0);     // negative shows as black
}

// The logarithmic curve (seed 004, 3.8): luminance Y to ln(1 + Y / 0.18) / ln(1 + 2^white), the
// colour scaled with it. Middle grey shows at 0.1 of white (10 stops), white at 2^10 middle greys,
// anything brighter saturates; black stays black; a colour keeps its hue below white.
TEST(Png, LogarithmicCurve) {
  test::TempDir dir;
  const auto pixel = [&](glm::vec3 linear, float whiteStops) {
    Image image(1, 1, 3, 0.0f);
    for (int c = 0; c < 3; ++c) image.pixels[c] = linear[c];
    writePng(dir.file("log.png"), image, 0.0f, ToneCurve::Logarithmic, whiteStops);
    auto in = OIIO::ImageInput::open(dir.file("log.png"));
    unsigned char rgb[3];
    in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, rgb);
    return glm::ivec3(rgb[0], rgb[1], rgb[2]);
  };
  // The sRGB encoding (IEC 61966-2-1), written out again as the test's own oracle.
  const auto expected = [](double display) {
    const double encoded = display <= 0.0031308 ? 12.92 * display : 1.055 * std::pow(display, 1.0 / 2.4) - 0.055;
    return int(std::lround(encoded * 255.0));
  };
  const double logWhite = std::log1p(1024.0);
  EXPECT_EQ(pixel(glm::vec3(0.18f), 10.0f), glm::ivec3(expected(std::log(2.0) / logWhite)));
  EXPECT_EQ(pixel(glm::vec3(0.18f * 1024.0f), 10.0f), glm::ivec3(255));
  EXPECT_EQ(pixel(glm::vec3(1e6f), 10.0f), glm::ivec3(255));
  EXPECT_EQ(pixel(glm::vec3(0.0f), 10.0f), glm::ivec3(0));
  EXPECT_EQ(pixel(glm::vec3(0.18f * 16.0f), 4.0f), glm::ivec3(255));  // another white point
  // A colour: luminance 1.8 maps to ln(11) / ln(1025), each channel scaled by it over 1.8.
  const glm::vec3 colour(3.0f, 1.5f, 0.6f);
  const double y = 0.2126 * 3.0 + 0.7152 * 1.5 + 0.0722 * 0.6;
  const double factor = std::log1p(y / 0.18) / logWhite / y;
  EXPECT_EQ(pixel(colour, 10.0f), glm::ivec3(expected(3.0 * factor), expected(1.5 * factor), expected(0.6 * factor)));
}

TEST(Png, SizeAndLayout) {
  test::TempDir dir;
  Image image(7, 5, 3, 0.0f);
  image.at(6, 0, 0) = 1.0f;  // top-right red
  writePng(dir.file("frame.png"), image, 0.0f, ToneCurve::Clamp);
  auto in = OIIO::ImageInput::open(dir.file("frame.png"));
  ASSERT_TRUE(in) << OIIO::geterror();
  EXPECT_EQ(in->spec().width, 7);
  EXPECT_EQ(in->spec().height, 5);
  EXPECT_EQ(in->spec().nchannels, 3);
  std::vector<unsigned char> bytes(7 * 5 * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data()));
  EXPECT_EQ(bytes[6 * 3 + 0], 255);
  EXPECT_EQ(bytes[6 * 3 + 1], 0);
  EXPECT_EQ(bytes[0], 0);
}

TEST(Png, NonFinitePixelIsAnErrorAndWritesNothing) {
  test::TempDir dir;
  for (float bad :
       {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    Image image(7, 5, 3, 0.5f);
    image.at(3, 2, 1) = bad;
    try {
      writePng(dir.file("frame.png"), image);
      FAIL() << "expected an Error";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(dir.file("frame.png")), std::string::npos) << message;
      EXPECT_NE(message.find("(3, 2)"), std::string::npos) << message;
    }
    EXPECT_EQ(dir.entries(), Strings{});
  }
}

}  // namespace
}  // namespace lpvlab

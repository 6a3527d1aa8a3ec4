// `lpvlab compare` on images whose differences are known: a test 0.1 brighter than a reference of
// 0.5 on every covered pixel (depth > 0; one background column left out) has RMSE 0.1, block
// nRMSE 0.2, a ratio of means 1.2 and a relative difference 0.1 / (0.5 + 5e-4); --threshold gates
// on them with exit code 3; --out writes the signed and relative differences, a PNG of the
// relative one with its colour bar and one of HDR-FLIP; --aov A=B compares
// a run's layer with a reference's of another name.

#include <filesystem>
#include <vector>

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "executable_support.h"
#include "framework/experiment/run_outputs.h"
#include "framework/io/image.h"
#include "framework/metrics/metrics.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

constexpr int kSize = 16;

Image constant(float value, int channels = 3) { return Image(kSize, kSize, channels, value); }

// The reference: indirect (and indirect1, as a reference cache has it) 0.5; depth 1, but 0 in
// column 0 (background).
void writeImages(const test::TempDir& dir) {
  Image depth = constant(1.0f, 1);
  for (int y = 0; y < kSize; ++y) depth.at(0, y, 0) = 0.0f;
  writeExr(dir.file("reference.exr"),
           {{"indirect", constant(0.5f)}, {"indirect1", constant(0.5f)}, {"depth", depth}});
  Image brighter = constant(0.6f);
  for (int y = 0; y < kSize; ++y)
    for (int c = 0; c < 3; ++c) brighter.at(0, y, c) = 9.0f;  // on the background: not counted
  writeExr(dir.file("test.exr"), {{"indirect", brighter}, {"depth", depth}});
}

TEST(CompareCommand, KnownDifferencesGiveTheirFigures) {
  test::TempDir dir;
  writeImages(dir);
  const test::LpvlabResult r = test::runLpvlab("compare test.exr reference.exr --aov indirect --json",
                                               dir.path(), dir.path());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json a = nlohmann::json::parse(r.out)["aovs"]["indirect"];
  EXPECT_NEAR(a["metrics"]["rmse"].get<double>(), 0.1, 1e-6);
  EXPECT_NEAR(a["metrics"]["block_nrmse"].get<double>(), 0.2, 1e-6);
  EXPECT_NEAR(a["mean_ratio"].get<double>(), 1.2, 1e-6);
  EXPECT_NEAR(a["relative_difference"]["mean"].get<double>(), 0.1 / 0.5005, 1e-6);
  EXPECT_EQ(a["metrics"]["pixels"].get<int>(), kSize * (kSize - 1));
  // Both FLIPs, as the metrics library gives them on the same images (metrics_test and
  // hdr_flip_test check the library). HDR-FLIP sees 0.5 and 0.6 at the one exposure that shows
  // 0.5 at 0.85, on the tone curve's shoulder, which brings them closer than LDR-FLIP's middle
  // grey does.
  const std::vector<NamedImage> t = readExr(dir.file("test.exr")), ref = readExr(dir.file("reference.exr"));
  const Image mask = coverageMask(*findAovOrNull(ref, "depth"));
  const MetricSet expected = computeMetrics(*findAovOrNull(t, "indirect"), *findAovOrNull(ref, "indirect"), &mask);
  EXPECT_NEAR(a["metrics"]["flip"].get<double>(), expected.flip, 1e-9);
  EXPECT_NEAR(a["metrics"]["hdr_flip"].get<double>(), expected.hdrFlip, 1e-9);
  EXPECT_GT(expected.hdrFlip, 0.0);
  EXPECT_LT(expected.hdrFlip, expected.flip);
  // The text table has the same figures, one row per AOV.
  const test::LpvlabResult text =
      test::runLpvlab("compare test.exr reference.exr --aov indirect", dir.path(), dir.path());
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_NE(text.out.find("block_nrmse"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("2.000e-01"), std::string::npos) << text.out;
}

TEST(CompareCommand, ThresholdsGateWithExitCode3) {
  test::TempDir dir;
  writeImages(dir);
  const auto compare = [&](const std::string& bounds) {
    return test::runLpvlab("compare test.exr reference.exr --aov indirect " + bounds, dir.path(), dir.path());
  };
  EXPECT_EQ(compare("--threshold rmse=0.2 --threshold block_nrmse=0.25").exitCode, 0);
  const test::LpvlabResult over = compare("--threshold rmse=0.2 --threshold block_nrmse=0.1");
  EXPECT_EQ(over.exitCode, 3);
  EXPECT_NE(over.err.find("indirect block_nrmse"), std::string::npos) << over.err;
  EXPECT_EQ(over.err.find("rmse 0.1"), std::string::npos) << "rmse is within its bound: " << over.err;
  // A figure compare does not have, or a bound that is no number: one error line, exit 1.
  const test::LpvlabResult unknown = compare("--threshold speed=1");
  EXPECT_EQ(unknown.exitCode, 1);
  EXPECT_NE(unknown.err.find("block_nrmse"), std::string::npos) << unknown.err;
  EXPECT_EQ(compare("--threshold rmse=-1").exitCode, 1);
  EXPECT_EQ(compare("--threshold rmse=abc").exitCode, 1);
}

TEST(CompareCommand, OutWritesTheDifferencesAndLayersPairUp) {
  test::TempDir dir;
  writeImages(dir);
  const test::LpvlabResult r = test::runLpvlab(
      "compare test.exr reference.exr --aov indirect=indirect1 --out diff", dir.path(), dir.path());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::vector<NamedImage> layers = readExr(dir.file("diff/difference.exr"));
  const Image* signedDifference = findAovOrNull(layers, "indirect_signed");
  const Image* relative = findAovOrNull(layers, "indirect_relative");
  ASSERT_TRUE(signedDifference && relative);
  EXPECT_NEAR(signedDifference->at(5, 5, 1), 0.1f, 1e-6f);
  EXPECT_EQ(signedDifference->at(0, 5, 1), 0.0f) << "background pixels are 0";
  EXPECT_NEAR(relative->at(5, 5, 2), 0.1f / 0.5005f, 1e-6f);
  // Writing there again replaces the differences and says so; two comparisons of one test layer
  // would write its layers twice, which is refused.
  const test::LpvlabResult again = test::runLpvlab(
      "compare test.exr reference.exr --aov indirect --out diff", dir.path(), dir.path());
  EXPECT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.err.find("replaced an earlier"), std::string::npos) << again.err;
  const test::LpvlabResult twice = test::runLpvlab(
      "compare test.exr reference.exr --aov indirect --aov indirect=indirect1 --out diff2", dir.path(),
      dir.path());
  EXPECT_EQ(twice.exitCode, 1);
  EXPECT_NE(twice.err.find("twice"), std::string::npos) << twice.err;
  EXPECT_FALSE(std::filesystem::exists(dir.file("diff2/difference.exr")));
  // The PNG of the relative difference, with its colour bar: every covered pixel has the 99th
  // percentile's value, so the ramp's top (magma's pale yellow, sRGB 252 253 191); the background
  // column mid grey; the bar (after a 2-pixel gap, 8 wide) pale yellow at the top, black at the
  // bottom.
  auto in = OIIO::ImageInput::open(dir.file("diff/indirect_relative.png"));
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  ASSERT_EQ(spec.width, kSize + 2 + 8);
  ASSERT_EQ(spec.height, kSize);
  std::vector<unsigned char> png(std::size_t(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, png.data()));
  auto pixel = [&](int x, int y, int c) { return int(png[(std::size_t(y) * spec.width + x) * spec.nchannels + c]); };
  const int paleYellow[3] = {252, 253, 191};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(pixel(5, 5, c), paleYellow[c], 1) << c;
    EXPECT_NEAR(pixel(0, 5, c), 128, 1) << "background, channel " << c;
    EXPECT_NEAR(pixel(spec.width - 1, 0, c), paleYellow[c], 1) << "bar top, channel " << c;
    EXPECT_LE(pixel(spec.width - 1, kSize - 1, c), 4) << "bar bottom, channel " << c;
  }
  // HDR-FLIP's map: a constant reference spans one exposure, the one that shows it at 0.85.
  EXPECT_TRUE(std::filesystem::exists(dir.file("diff/indirect_hdr_flip.png")));
  const nlohmann::json flip = nlohmann::json::parse(
      test::runLpvlab("compare test.exr reference.exr --aov indirect --out diff3 --json", dir.path(),
                      dir.path()).out)["aovs"]["indirect"]["hdr_flip_png"];
  EXPECT_DOUBLE_EQ(flip["exposures"]["start_stops"].get<double>(),
                   flip["exposures"]["stop_stops"].get<double>());
  EXPECT_EQ(flip["exposures"]["count"].get<int>(), 2);
  // A layer the reference lacks is named.
  const test::LpvlabResult missing =
      test::runLpvlab("compare test.exr reference.exr --aov indirect=indirect2", dir.path(), dir.path());
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("no AOV 'indirect2'"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace lpvlab

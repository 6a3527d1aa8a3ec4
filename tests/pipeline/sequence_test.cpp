// Animated experiments rendered as sequences (framework/experiment/sequence.h): a sequence of one
// frame is the static run, every frame is what a static run of that frame's scene renders (so
// moving lights and meshes reach the GPU as the animation says), an interrupted sequence resumes
// at its first missing frame, and the video holds every frame.
#include "framework/experiment/sequence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>

#include "error_support.h"
#include "framework/experiment/run.h"
#include "framework/experiment/sweep.h"
#include "framework/io/child_process.h"
#include "framework/io/image.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

// A small Cornell box experiment (both backends' defaults: "auto") with `animation` appended.
fs::path writeExperiment(const fs::path& dir, const std::string& animation) {
  fs::create_directories(dir);
  std::ofstream(dir / "e.toml")
      << "[output]\nwidth = 40\nheight = 32\n[grid]\nresolution = 12\n"
         "[propagation]\niterations = 6\n[timing]\nwarmup = 0\nrepeats = 1\n"
         "[light_maps]\nrsm_resolution = 32\nshadow_resolution = 128\n"
      << animation;
  return dir / "e.toml";
}

// The largest difference between two runs' AOVs.
float largestDifference(const std::vector<NamedImage>& a, const std::vector<NamedImage>& b) {
  float largest = 0.0f;
  for (const NamedImage& aov : a) {
    const Image& other = findAov(b, aov.name);
    EXPECT_EQ(other.pixels.size(), aov.image.pixels.size()) << aov.name;
    for (std::size_t i = 0; i < std::min(other.pixels.size(), aov.image.pixels.size()); ++i)
      largest = std::max(largest, std::abs(other.pixels[i] - aov.image.pixels[i]));
  }
  return largest;
}

const char* kMovingBlockAndLight = R"(
[animation]
frames = 3
fps = 2
video = false
[[animation.meshes]]
meshes = ["short block"]
[[animation.meshes.keys]]
frame = 0
translation = [0, 0, 0]
[[animation.meshes.keys]]
frame = 2
translation = [0.12, 0, 0.05]
rotation_deg = [0, 40, 0]
[[animation.lights]]
light = "spot"
[[animation.lights.keys]]
frame = 0
intensity = 20
[[animation.lights.keys]]
frame = 2
intensity = 35
position = [0.25, 0.5, 0.3]
)";

TEST(Sequence, EveryFrameIsWhatAStaticRunOfThatFrameRenders) {
  const GlContext& context = test::glTestContext();
  const fs::path dir = fs::temp_directory_path() / "lpvlab_sequence_frames";
  fs::remove_all(dir);
  const fs::path file = writeExperiment(dir, kMovingBlockAndLight);
  Experiment sequence = loadExperiment(file.string());
  ASSERT_TRUE(sequence.animation.movesGeometry() && sequence.animation.movesLights());
  const nlohmann::json manifest = runExperiment(sequence, context, (dir / "run").string());
  EXPECT_EQ(manifest["sequence"]["frames"].get<int>(), 3);
  EXPECT_EQ(manifest["timing"]["samples"]["gpu_ms"]["total"].size(), 3u);

  for (int frame : {0, 2}) {
    // The same experiment, its scene moved to the frame's time and rendered statically.
    Experiment still = loadExperiment(file.string(), {"animation.frames=1"});
    Animation motion = still.animation;
    applyAnimation(motion, motion.frameTime(frame), still.scene, still.camera);
    still.animation = Animation{};  // a static run of the moved scene
    runExperiment(still, context, (dir / ("still" + std::to_string(frame))).string());
    const auto framed = readExr((dir / "run" / (frameStem(frame, 3) + ".exr")).string());
    const auto statically =
        readExr((dir / ("still" + std::to_string(frame)) / "images.exr").string());
    EXPECT_EQ(largestDifference(framed, statically), 0.0f) << "frame " << frame;
  }
  // And the frames differ: the block and the light did move.
  const auto first = readExr((dir / "run" / (frameStem(0, 3) + ".exr")).string());
  const auto last = readExr((dir / "run" / (frameStem(2, 3) + ".exr")).string());
  EXPECT_GT(largestDifference(first, last), 1e-3f);
  fs::remove_all(dir);
}

// The change of the direct light between two frames of a moving block (its shadow leaving some
// of the floor and covering another part), LPV's rasterised against the path tracer's.
TEST(Sequence, AMovingBlocksShadowMovesTheSameWayInThePipelineAndThePathTracer) {
  const GlContext& context = test::glTestContext();
  const fs::path dir = fs::temp_directory_path() / "lpvlab_sequence_reference";
  fs::remove_all(dir);
  const fs::path file = writeExperiment(dir, R"(
[reference]
compare = true
samples = 96
[animation]
frames = 3
fps = 1
video = false
[[animation.meshes]]
meshes = ["short block"]
interpolation = "linear"
[[animation.meshes.keys]]
frame = 0
translation = [0, 0, 0]
[[animation.meshes.keys]]
frame = 2
translation = [0.15, 0, 0.12]
)");
  Experiment e = loadExperiment(file.string());
  e.reference.cacheDir = (dir / "cache").string();
  e.reference.showProgress = false;
  const nlohmann::json manifest = runExperiment(e, context, (dir / "run").string());
  const auto& records = manifest["sequence"]["frame_records"];
  ASSERT_EQ(records.size(), 3u);
  // Each frame has its own reference (the scene differs), and its own comparison.
  std::set<std::string> keys;
  for (const auto& record : records) keys.insert(record["reference"]["key"].get<std::string>());
  EXPECT_EQ(keys.size(), 3u);
  EXPECT_TRUE(manifest["reference"]["comparison"]["direct_vs_direct"]["metrics"].contains("flip"));

  const auto directOf = [&](const std::vector<NamedImage>& aovs) {
    return findAov(aovs, "direct");
  };
  const Image lpv0 = directOf(readExr((dir / "run" / (frameStem(0, 3) + ".exr")).string()));
  const Image lpv2 = directOf(readExr((dir / "run" / (frameStem(2, 3) + ".exr")).string()));
  const Image ref0 =
      directOf(readExr(records[0]["reference"]["directory"].get<std::string>() + "/images.exr"));
  const Image ref2 =
      directOf(readExr(records[2]["reference"]["directory"].get<std::string>() + "/images.exr"));
  // Pearson correlation of the two changes, over every pixel channel: the shadow moved where the
  // tracer says it did (a block left in place, or moved elsewhere, correlates near zero).
  double sumA = 0, sumB = 0, sumAA = 0, sumBB = 0, sumAB = 0;
  const std::size_t n = lpv0.pixels.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double a = lpv2.pixels[i] - lpv0.pixels[i], b = ref2.pixels[i] - ref0.pixels[i];
    sumA += a, sumB += b, sumAA += a * a, sumBB += b * b, sumAB += a * b;
  }
  const double covariance = sumAB / n - sumA / n * sumB / n;
  const double correlation =
      covariance / std::sqrt((sumAA / n - sumA / n * sumA / n) * (sumBB / n - sumB / n * sumB / n));
  EXPECT_GT(correlation, 0.8);
  std::cout
      << "[ sequence ] correlation of the direct light's change, LPV against the path tracer: "
      << correlation << "\n";

  // The summary has a row per frame, each with that frame's figures (the per-frame error curve).
  fs::remove_all(dir / "cache");
  const SummaryResult summary = writeSweepSummary(dir.string());
  EXPECT_EQ(summary.rows, 3);
  std::ifstream csv(dir / "summary.csv");
  std::string header, line;
  std::getline(csv, header);
  const auto split = [](const std::string& text) {
    std::vector<std::string> fields;
    std::size_t at = 0;
    for (std::size_t comma; (comma = text.find(',', at)) != std::string::npos; at = comma + 1)
      fields.push_back(text.substr(at, comma - at));
    fields.push_back(text.substr(at));
    return fields;
  };
  const std::vector<std::string> columns = split(header);
  const auto flip = std::find(columns.begin(), columns.end(), "metric.indirect_vs_indirect1.flip");
  ASSERT_NE(flip, columns.end()) << header;
  std::vector<double> values;
  while (std::getline(csv, line))
    values.push_back(std::stod(split(line).at(std::size_t(flip - columns.begin()))));
  ASSERT_EQ(values.size(), 3u);
  for (std::size_t f = 0; f < 3; ++f)
    EXPECT_NEAR(values[f],
                records[f]["reference"]["comparison"]["indirect_vs_indirect1"]["metrics"]["flip"]
                    .get<double>(),
                1e-6 * std::abs(values[f]) + 1e-12);
  EXPECT_NE(values[0], values[2]);  // per frame, not the sequence's mean repeated
  fs::remove_all(dir);
}

TEST(Sequence, OneFrameOfACameraPathIsTheStaticRunFromThatCamera) {
  const GlContext& context = test::glTestContext();
  const fs::path dir = fs::temp_directory_path() / "lpvlab_sequence_one";
  fs::remove_all(dir);
  const fs::path path = writeExperiment(dir, R"(
[animation]
frames = 1
[animation.camera]
fov_deg = 38
[[animation.camera.keys]]
frame = 0
position = [0.278, 0.273, -0.5]
look_at = [0.278, 0.273, 0.3]
)");
  Experiment one = loadExperiment(path.string());
  const nlohmann::json manifest = runExperiment(one, context, (dir / "sequence").string());
  EXPECT_FALSE(manifest["outputs"].contains("video"));  // one frame: no video
  fs::create_directories(dir / "static");
  std::ofstream(dir / "static" / "e.toml")
      << "[output]\nwidth = 40\nheight = 32\n[grid]\nresolution = 12\n[propagation]\niterations = "
         "6\n"
         "[timing]\nwarmup = 0\nrepeats = 1\n[light_maps]\nrsm_resolution = 32\nshadow_resolution "
         "= 128\n"
         "[camera]\nposition = [0.278, 0.273, -0.5]\nlook_at = [0.278, 0.273, 0.3]\nfov_deg = 38\n";
  Experiment still = loadExperiment((dir / "static" / "e.toml").string());
  // The same far plane as the path's (it covers the path; [camera]'s default covers the camera).
  still.camera.nearPlane = one.camera.nearPlane;
  still.camera.farPlane = one.camera.farPlane;
  runExperiment(still, context, (dir / "static" / "run").string());
  EXPECT_EQ(largestDifference(readExr((dir / "sequence" / (frameStem(0, 1) + ".exr")).string()),
                              readExr((dir / "static" / "run" / "images.exr").string())),
            0.0f);
  fs::remove_all(dir);
}

TEST(Sequence, AnInterruptedSequenceResumesAtItsFirstMissingFrameAndMakesTheVideo) {
  const GlContext& context = test::glTestContext();
  const fs::path dir = fs::temp_directory_path() / "lpvlab_sequence_resume";
  fs::remove_all(dir);
  const bool haveFfmpeg = !findProgram("ffmpeg").empty();
  if (!haveFfmpeg && std::getenv("CI"))
    FAIL() << "ffmpeg is missing in CI (scripts/install-deps.sh installs it)";
  if (!haveFfmpeg) GTEST_SKIP() << "ffmpeg is not installed (scripts/install-deps.sh installs it)";
  const fs::path file = writeExperiment(dir, R"(
[animation]
frames = 5
fps = 10
[animation.camera]
[[animation.camera.keys]]
frame = 0
position = [0.278, 0.273, -0.8]
look_at = [0.278, 0.273, 0.3]
[[animation.camera.keys]]
frame = 4
position = [0.2, 0.3, -0.7]
look_at = [0.3, 0.25, 0.3]
)");
  const fs::path run = dir / "run";
  Experiment whole = loadExperiment(file.string());
  runExperiment(whole, context, run.string());
  const auto frame1 = readExr((run / (frameStem(1, 5) + ".exr")).string());
  const auto frame3 = readExr((run / (frameStem(3, 5) + ".exr")).string());
  const auto written1 = fs::last_write_time(run / (frameStem(1, 5) + ".exr"));

  // As a kill after frame 2 leaves it: frames 3 and 4 without records (one half-written), no
  // manifest, no video.
  fs::remove(run / (frameStem(3, 5) + ".json"));
  fs::remove(run / (frameStem(4, 5) + ".json"));
  fs::remove(run / (frameStem(4, 5) + ".exr"));
  fs::remove(run / "manifest.json");
  fs::remove(run / "video.mp4");
  Experiment again = loadExperiment(file.string());
  const nlohmann::json manifest = runExperiment(again, context, run.string());
  EXPECT_EQ(manifest["sequence"]["resumed_at_frame"].get<int>(), 3);
  EXPECT_EQ(fs::last_write_time(run / (frameStem(1, 5) + ".exr")), written1);  // not rendered again
  EXPECT_EQ(largestDifference(readExr((run / (frameStem(1, 5) + ".exr")).string()), frame1), 0.0f);
  EXPECT_EQ(largestDifference(readExr((run / (frameStem(3, 5) + ".exr")).string()), frame3), 0.0f);
  EXPECT_EQ(manifest["sequence"]["frame_records"].size(), 5u);
  EXPECT_EQ(manifest["timing"]["samples"]["wall_ms"]["total"].size(), 5u);
  for (int f = 0; f < 5; ++f)
    EXPECT_EQ(manifest["sequence"]["frame_records"][std::size_t(f)]["frame"].get<int>(), f);

  // The video: 5 frames at 10 fps, as ffprobe reads it.
  ASSERT_TRUE(fs::exists(run / "video.mp4"));
  const fs::path probe = dir / "probe.txt";
  const int status =
      runProgram({"sh", "-c",
                  "ffprobe -v error -count_frames -select_streams v:0 "
                  "-show_entries stream=nb_read_frames,r_frame_rate "
                  "-of csv=p=0 '" +
                      (run / "video.mp4").string() + "' > '" + probe.string() + "'"});
  ASSERT_EQ(status, 0);
  std::string line;
  std::getline(std::ifstream(probe) >> std::ws, line);
  EXPECT_EQ(line, "10/1,5");

  // Another configuration into the same directory is refused, not mixed into the sequence.
  Experiment changed = loadExperiment(file.string(), {"propagation.iterations=7"});
  const std::string message = test::errorOf([&] { runExperiment(changed, context, run.string()); });
  EXPECT_NE(message.find("a frame of another configuration"), std::string::npos) << message;
  fs::remove_all(dir);
}

TEST(Sequence, AMissingFfmpegIsOneErrorBeforeAnyFrame) {
  const GlContext& context = test::glTestContext();
  const fs::path dir = fs::temp_directory_path() / "lpvlab_sequence_noffmpeg";
  fs::remove_all(dir);
  const fs::path file = writeExperiment(dir, "[animation]\nframes = 2\n");
  Experiment e = loadExperiment(file.string());
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", (dir / "empty").c_str(), 1);
  const std::string message = test::errorOf([&] { runExperiment(e, context, (dir / "run").string()); });
  setenv("PATH", path.c_str(), 1);
  EXPECT_NE(message.find("key 'animation.video': the ffmpeg program is not installed"),
            std::string::npos)
      << message;
  EXPECT_FALSE(fs::exists(dir / "run" / (frameStem(0, 2) + ".json")));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lpvlab

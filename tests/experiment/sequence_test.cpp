// Animated experiments rendered as sequences (framework/experiment/sequence.h): a sequence of one
// frame is the static run, every frame is what a static run of that frame's scene renders (so
// moving lights and meshes reach the GPU as the animation says), an interrupted sequence resumes
// at its first missing frame, and the video holds every frame.
#include "sweep_support.h"
#include "framework/experiment/sequence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "error_support.h"
#include "framework/experiment/run.h"
#include "framework/experiment/sweep_summary.h"
#include "framework/io/child_process.h"
#include "framework/io/image.h"
#include "framework/math/cascade_placement.h"
#include "framework/metrics/temporal.h"
#include "framework/reference/reprojection.h"
#include "framework/scene/scene_loader.h"
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
  EXPECT_EQ(manifest["timing"]["samples"]["stage_ms"]["total"].size(), 3u);

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
  test::writeSweepIndex(dir, {"run"});
  const SummaryResult summary = writeSweepSummary(dir.string());
  EXPECT_EQ(summary.rows, 3);
  std::ifstream csv(dir / "summary.csv");
  std::string header, line;
  std::getline(csv, header);
  const auto split = [](const std::string& text) {  // CSV: a quoted field may hold commas
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '"') {
        if (quoted && i + 1 < text.size() && text[i + 1] == '"') fields.back() += text[++i];
        else quoted = !quoted;
      } else if (text[i] == ',' && !quoted) {
        fields.emplace_back();
      } else {
        fields.back() += text[i];
      }
    }
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
  // And each frame's temporal error (none for frame 0, which has no frame before it).
  const auto temporal =
      std::find(columns.begin(), columns.end(), "temporal.error.direct_vs_direct.relative");
  ASSERT_NE(temporal, columns.end()) << header;
  std::ifstream again(dir / "summary.csv");
  std::getline(again, line);
  for (std::size_t f = 0; f < 3; ++f) {
    ASSERT_TRUE(std::getline(again, line));
    const std::string field = split(line).at(std::size_t(temporal - columns.begin()));
    if (f == 0) {
      EXPECT_EQ(field, "");
      continue;
    }
    const nlohmann::json& error = records[f]["temporal"]["error"]["direct_vs_direct"];
    EXPECT_FALSE(records[f]["temporal"]["at_rest"].get<bool>());  // the block moved
    EXPECT_NEAR(std::stod(field), error["relative"].get<double>(), 1e-6 * std::stod(field));
    // The per-frame references have seeds of their own, so their noise is independent and its
    // estimate is subtracted.
    EXPECT_GT(error["noise_mean_square"].get<double>(), 0.0);
  }
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

// Nothing moves: every frame is the one before, at every pixel (docs/animation.md, "Temporal
// metrics": flicker at rest is zero for a static camera).
TEST(Sequence, ASequenceAtRestHasNoTemporalChange) {
  const GlContext& context = test::glTestContext();
  const fs::path dir = fs::temp_directory_path() / "lpvlab_sequence_rest";
  fs::remove_all(dir);
  const fs::path file = writeExperiment(dir, "[animation]\nframes = 3\nvideo = false\n");
  Experiment still = loadExperiment(file.string());
  const nlohmann::json manifest = runExperiment(still, context, (dir / "run").string());
  const nlohmann::json& records = manifest["sequence"]["frame_records"];
  EXPECT_FALSE(records[0].contains("temporal"));  // nothing before it
  for (std::size_t f : {1u, 2u}) {
    const nlohmann::json& t = records[f]["temporal"];
    EXPECT_TRUE(t["at_rest"].get<bool>());
    EXPECT_EQ(t["reprojected_fraction"].get<double>(), 1.0);
    for (const char* aov : {"direct", "indirect"}) {
      EXPECT_GT(t["change"][aov]["level"].get<double>(), 0.0) << aov;
      // Zero up to float rounding (a kernel that summed in another order could round differently).
      EXPECT_LE(t["change"][aov]["rms"].get<double>(),
                1e-6 * t["change"][aov]["level"].get<double>())
          << aov;
    }
  }
  EXPECT_EQ(manifest["sequence"]["temporal"]["frames_at_rest"].get<int>(), 2);
  EXPECT_LE(
      manifest["sequence"]["temporal"]["flicker_at_rest"]["indirect"]["max_relative"].get<double>(),
      1e-6);
  fs::remove_all(dir);
}

// A camera inside the box, above the tall block, faces the back wall head-on and moves sideways
// by one pixel's footprint on the wall: the wall's pixels then reproject onto pixel centres, where
// the temporal change has no interpolation error. What follows the camera (finer cascade levels,
// a directional light's view) may move with it, and then the light at rest changes.
class SubPixelCameraMove {
public:
  static constexpr int kSize = 96;

  // `settings`: the experiment's TOML before its [animation] table.
  SubPixelCameraMove(const fs::path& dir, const std::string& settings) : dir_(dir) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    Camera box = makeCornellBox().cameras.front();
    box.position = {0.278f, 0.45f, 0.25f};  // above the tall block, which stands at z = 0.25-0.46
    const float wallDepth = 0.5592f - box.position.z;  // the back wall, seen head-on
    footprint_ = 2.0f * wallDepth * std::tan(box.verticalFov / 2.0f) / float(kSize);
    std::ostringstream file;
    file.precision(9);
    file << "[output]\nwidth = " << kSize << "\nheight = " << kSize << "\n"
         << settings
         << "[timing]\nwarmup = 0\n[animation]\nframes = 2\nfps = 1\nvideo = false\n"
            "[animation.camera]\ninterpolation = \"linear\"\n";
    for (int frame = 0; frame < 2; ++frame) {
      const float x = box.position.x + float(frame) * footprint_;
      file << "[[animation.camera.keys]]\nframe = " << frame << "\nposition = [" << x << ", "
           << box.position.y << ", " << box.position.z << "]\nlook_at = [" << x << ", "
           << box.position.y << ", 0.55]\n";
    }
    std::ofstream(dir / "e.toml") << file.str();
  }
  ~SubPixelCameraMove() { fs::remove_all(dir_); }

  float footprint() const { return footprint_; }
  Experiment load(const std::string& override) const {
    return loadExperiment((dir_ / "e.toml").string(), {override});
  }

  // The relative change of the indirect light from frame 0 to 1: on the pixels that reproject
  // onto pixel centres, and as the manifest records it (every reprojected pixel).
  struct Change {
    double onCentres = 0.0;
    double recorded = 0.0;
    double lighting = 0.0;  // the recorded change of the indirect light over the albedo
  };
  Change run(Experiment& e, const GlContext& context, const std::string& name) const {
    const fs::path run = dir_ / name;
    const nlohmann::json manifest = runExperiment(e, context, run.string());
    const auto frame0 = readExr((run / (frameStem(0, 2) + ".exr")).string());
    const auto frame1 = readExr((run / (frameStem(1, 2) + ".exr")).string());
    const Camera before = cameraAt(e.animation, 0.0, e.camera);
    const Camera after = cameraAt(e.animation, 1.0, e.camera);
    const Reprojection reprojection =
        reprojectThroughDepth({after, findAov(frame1, "depth"), findAov(frame1, "normal")},
                              {before, findAov(frame0, "depth"), findAov(frame0, "normal")});
    Image onCentres(kSize, kSize, 1);
    int count = 0;
    for (std::size_t p = 0; p < reprojection.taps.size(); ++p)
      count += (onCentres.pixels[p] = reprojection.taps[p].count == 1);
    EXPECT_GT(count, kSize * kSize / 8) << "the back wall's pixels reproject onto pixel centres";
    const nlohmann::json& t = manifest["sequence"]["frame_records"][1]["temporal"];
    EXPECT_TRUE(t["at_rest"].get<bool>());
    return {*frameToFrameChange(findAov(frame1, "indirect"), findAov(frame0, "indirect"),
                                reprojection, &onCentres)
                 .relative,
            t["change"]["indirect"]["relative"].get<double>(),
            t["change"]["indirect_lighting"]["relative"].get<double>()};
  }

private:
  fs::path dir_;
  float footprint_ = 0.0f;
};

// Checks that what snaps stays put (zero change, up to float rounding: the same world point is
// rebuilt from another pixel's depth, and a position within 1/1000 pixel of a centre counts as
// on it) and what follows every move flickers.
void expectSnappingRemovesTheFlicker(const std::map<bool, SubPixelCameraMove::Change>& change,
                                     const std::string& what) {
  EXPECT_LT(change.at(true).onCentres, 1e-4);
  EXPECT_GT(change.at(false).onCentres, 20.0 * change.at(true).onCentres);
  // Over every reprojected pixel (interpolation included), the unsnapped one flickers more, in
  // the output and in its lighting (the box's albedo is constant per wall, so the two differ only
  // at the walls' edges).
  EXPECT_GT(change.at(false).recorded, change.at(true).recorded);
  EXPECT_GT(change.at(false).lighting, 20.0 * change.at(true).lighting);
  std::cout << "[ sequence ] " << what << ": relative change of the indirect light at rest, "
            << "snapped " << change.at(true).recorded << ", unsnapped " << change.at(false).recorded
            << "; on the pixels reprojected onto pixel centres, snapped "
            << change.at(true).onCentres << ", unsnapped " << change.at(false).onCentres << "\n";
}

// The finer cascade level covers the back wall and the move is less than a cell of it: snapped
// levels do not move, unsnapped levels follow the camera (thesis 6.10: snapping "removes
// flickering when the camera moves").
TEST(Sequence, SnappedCascadesDoNotFlickerUnderASubCellCameraMoveAndUnsnappedOnesDo) {
  const GlContext& context = test::glTestContext();
  // Coarse cells of 5 cm, the grid reaching 12 cm behind the wall; the finer level (2.5 cm cells,
  // 30 cm wide) is centred 30 cm ahead of the eye, so the wall (at z = 0.56) is well inside it,
  // past its band of blending with the coarse level, and it follows the eye.
  const SubPixelCameraMove move(
      fs::temp_directory_path() / "lpvlab_sequence_snap",
      "[grid]\norigin = [-0.02, -0.02, -0.02]\ncell_size = 0.05\ncells = [12, 12, 14]\n"
      "[cascades]\nlevels = 2\ncarry = false\nview_shift = 1.0\nblend_cells = 0.5\n"
      "[occlusion]\ntype = \"none\"\n");
  std::map<bool, SubPixelCameraMove::Change> change;
  for (bool snap : {true, false}) {
    Experiment e = move.load(std::string("cascades.snap=") + (snap ? "true" : "false"));
    const auto levelsAt = [&](const Camera& c) {
      return placeCascadeLevels(e.settings.grid, 2, c.position, c.forward,
                                e.settings.cascades.viewShift, snap);
    };
    const Camera before = cameraAt(e.animation, 0.0, e.camera);
    const Camera after = cameraAt(e.animation, 1.0, e.camera);
    // What the test is about: the move stays within a cell of the finest level, so snapping
    // keeps it in place, and without snapping it moves.
    ASSERT_EQ(levelsAt(before)[0].origin == levelsAt(after)[0].origin, snap);
    ASSERT_LT(move.footprint(), levelsAt(before)[0].cellSize);
    change[snap] = move.run(e, context, snap ? "snapped" : "unsnapped");
  }
  expectSnappingRemovesTheFlicker(change, "cascades");
}

// A sun shining in through the box's open front, its view a 40 cm box following the camera
// (thesis 6.2's shadow camera): snapped to whole texels, a sub-texel move leaves it in place;
// unsnapped it follows, the RSM and shadow map are resampled, and the light at rest changes.
TEST(Sequence,
     ASnappedFollowingSunViewDoesNotFlickerUnderASubTexelCameraMoveAndAnUnsnappedOneDoes) {
  const GlContext& context = test::glTestContext();
  const SubPixelCameraMove move(
      fs::temp_directory_path() / "lpvlab_sequence_sun_snap",
      "[scene]\nreplace_lights = true\n[[lights]]\ntype = \"directional\"\n"
      "direction = [0.25, -0.4, 1.0]\nintensity = 20.0\n"
      "[light_maps]\nrsm_resolution = 64\nshadow_resolution = 256\ndirectional = \"camera\"\n"
      "directional_width = 0.4\n[grid]\nresolution = 16\n[occlusion]\ntype = \"none\"\n");
  std::map<bool, SubPixelCameraMove::Change> change;
  for (bool snap : {true, false}) {
    Experiment e =
        move.load(std::string("light_maps.directional_snap=") + (snap ? "true" : "false"));
    const auto viewAt = [&](const Camera& c) {
      const LightViews views =
          buildLightViews(e.scene.lights, e.scene.bounds(), directionalFollow(e.settings, c));
      return views.views.at(0).clipFromWorld;
    };
    // What the test is about: the move is less than a texel, so snapping keeps the view in
    // place, and without snapping it moves.
    ASSERT_EQ(viewAt(cameraAt(e.animation, 0.0, e.camera)) ==
                  viewAt(cameraAt(e.animation, 1.0, e.camera)),
              snap);
    ASSERT_LT(move.footprint(), e.settings.directional.followWidth / 64.0f);
    change[snap] = move.run(e, context, snap ? "snapped" : "unsnapped");
  }
  expectSnappingRemovesTheFlicker(change, "sun view following the camera");
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
  const nlohmann::json uninterrupted = runExperiment(whole, context, run.string());
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
  // Frame 3's temporal figures, against frame 2 read back from its files, are those of the
  // uninterrupted run, which had frame 2 in memory.
  for (int f : {3, 4})
    EXPECT_EQ(manifest["sequence"]["frame_records"][std::size_t(f)]["temporal"],
              uninterrupted["sequence"]["frame_records"][std::size_t(f)]["temporal"])
        << "frame " << f;
  EXPECT_TRUE(manifest["sequence"]["frame_records"][3]["temporal"]["at_rest"].get<bool>());

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

// A GV history (geometry_volume's `history`) makes each frame depend on the frames before: a
// resumed sequence renders those again, unwritten, and its frames are the uninterrupted run's.
// The camera turns inside the box, so the history holds surfaces the later frames no longer see,
// and its frames differ from those without it (else this would test nothing).
TEST(Sequence, AResumedSequenceWithAGvHistoryRendersTheUninterruptedFrames) {
  const GlContext& context = test::glTestContext();
  const fs::path dir = fs::temp_directory_path() / "lpvlab_sequence_history";
  fs::remove_all(dir);
  const fs::path file = writeExperiment(dir, R"(
[occlusion]
type = "geometry_volume"
sources = ["camera"]
history = true
[animation]
frames = 4
fps = 4
video = false
[animation.camera]
[[animation.camera.keys]]
frame = 0
position = [0.45, 0.3, 0.25]
look_at = [0.0, 0.25, 0.35]
[[animation.camera.keys]]
frame = 3
position = [0.3, 0.3, 0.2]
look_at = [0.5, 0.25, 0.56]
)");
  const fs::path run = dir / "run";
  Experiment whole = loadExperiment(file.string());
  runExperiment(whole, context, run.string());
  const auto frame3 = readExr((run / (frameStem(3, 4) + ".exr")).string());
  Experiment without = loadExperiment(file.string(), {"occlusion.history=false"});
  runExperiment(without, context, (dir / "without").string());
  EXPECT_GT(largestDifference(readExr((dir / "without" / (frameStem(3, 4) + ".exr")).string()),
                              frame3),
            0.0f)
      << "the history changes what the last frame's GV blocks";

  // As a kill after frame 1 leaves it.
  for (int f : {2, 3}) fs::remove(run / (frameStem(f, 4) + ".json"));
  fs::remove(run / "manifest.json");
  Experiment again = loadExperiment(file.string());
  const nlohmann::json manifest = runExperiment(again, context, run.string());
  EXPECT_EQ(manifest["sequence"]["resumed_at_frame"].get<int>(), 2);
  EXPECT_EQ(largestDifference(readExr((run / (frameStem(3, 4) + ".exr")).string()), frame3), 0.0f);
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
  const std::string message =
      test::errorOf([&] { runExperiment(e, context, (dir / "run").string()); });
  setenv("PATH", path.c_str(), 1);
  EXPECT_NE(message.find("key 'animation.video': the ffmpeg program is not installed"),
            std::string::npos)
      << message;
  EXPECT_FALSE(fs::exists(dir / "run" / (frameStem(0, 2) + ".json")));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lpvlab

// The reference cache: what the key covers, reuse without rendering, deterministic continuation
// of a cached reference with too few samples, resuming from saved state, and bad input.

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/reference/reference_cache.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

class ReferenceCache : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("lpvlab_cache_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    scene_ = makeCornellBox();
    camera_ = scene_.cameras.front();
    request_.width = 16;
    request_.height = 16;
    request_.threads = 2;
    request_.cacheDir = dir_.string();
    request_.showProgress = false;
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  Scene scene_;
  Camera camera_;
  ReferenceRequest request_;
};

TEST_F(ReferenceCache, KeyCoversWhatDeterminesThePixelsAndNotTheStoppingRule) {
  const std::string key = referenceKey(scene_, camera_, request_);
  EXPECT_EQ(key.size(), 16u);
  EXPECT_EQ(referenceKey(scene_, camera_, request_), key);
  ReferenceRequest moreSamples = request_;
  moreSamples.target.samples *= 4;
  moreSamples.threads = 1;
  EXPECT_EQ(referenceKey(scene_, camera_, moreSamples), key);

  ReferenceRequest r = request_;
  r.width = 17;
  EXPECT_NE(referenceKey(scene_, camera_, r), key);
  r = request_;
  r.tracer.seed = 2;
  EXPECT_NE(referenceKey(scene_, camera_, r), key);
  r = request_;
  r.tracer.skyRadiance = glm::vec3(0.1f);
  EXPECT_NE(referenceKey(scene_, camera_, r), key);
  r = request_;
  r.tracer.sampler = SampleSequence::Sobol;
  EXPECT_NE(referenceKey(scene_, camera_, r), key);
  Camera moved = camera_;
  moved.position.x += 0.01f;
  EXPECT_NE(referenceKey(scene_, moved, request_), key);
  Scene brighter = scene_;
  brighter.lights[0].intensity *= 2.0f;
  EXPECT_NE(referenceKey(brighter, camera_, request_), key);
  Scene recoloured = scene_;
  recoloured.materials[0].baseColor.r = 0.5f;
  EXPECT_NE(referenceKey(recoloured, camera_, request_), key);
}

TEST_F(ReferenceCache, ReuseContinuationAndResumeAreDeterministic) {
  request_.target.samples = 4;
  const Reference first = ensureReference(scene_, camera_, request_);
  EXPECT_FALSE(first.reused);
  EXPECT_EQ(first.samples, 4);
  for (const char* file : {"images.exr", "manifest.json", "state.bin"})
    EXPECT_TRUE(fs::exists(fs::path(first.directory) / file)) << file;

  // Enough samples cached: reused, nothing rendered, same pixels.
  request_.target.samples = 3;
  const Reference again = ensureReference(scene_, camera_, request_);
  EXPECT_TRUE(again.reused);
  EXPECT_EQ(again.samples, 4);
  EXPECT_EQ(findAov(again.aovs, "combined").pixels, findAov(first.aovs, "combined").pixels);

  // Too few: continued from the cached sums to 8, equal bit for bit to 8 rendered at once.
  request_.target.samples = 8;
  const Reference continued = ensureReference(scene_, camera_, request_);
  EXPECT_FALSE(continued.reused);
  EXPECT_EQ(continued.samples, 8);
  ReferenceRequest fresh = request_;
  fresh.cacheDir = (dir_ / "fresh").string();
  const Reference direct = ensureReference(scene_, camera_, fresh);
  for (const char* name : {"direct", "indirect", "indirect1", "combined", "combined_variance"})
    EXPECT_EQ(findAov(continued.aovs, name).pixels, findAov(direct.aovs, name).pixels) << name;

  // A saved state without images (an interrupted rendering) is resumed, not restarted.
  fs::remove(fs::path(continued.directory) / "images.exr");
  request_.target.samples = 8;
  const Reference resumed = ensureReference(scene_, camera_, request_);
  EXPECT_EQ(resumed.samples, 8);
  EXPECT_EQ(findAov(resumed.aovs, "combined").pixels, findAov(direct.aovs, "combined").pixels);
}

TEST_F(ReferenceCache, StateRoundTripsAndCorruptStateIsNamed) {
  Accumulator acc(3, 2);
  acc.samples = 5;
  for (std::size_t i = 0; i < acc.sum.size(); ++i) acc.sum[i] = 0.5 * double(i);
  fs::create_directories(dir_);
  const std::string path = (dir_ / "state.bin").string();
  saveAccumulator(path, acc, 12.5);
  double seconds = 0.0;
  const Accumulator back = loadAccumulator(path, &seconds);
  EXPECT_EQ(back.samples, 5);
  EXPECT_EQ(back.sum, acc.sum);
  EXPECT_DOUBLE_EQ(seconds, 12.5);

  fs::resize_file(path, fs::file_size(path) / 2);
  try {
    loadAccumulator(path);
    FAIL() << "a truncated state loaded";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("state.bin"), std::string::npos) << e.what();
  }
  std::ofstream(path) << "not a state";
  EXPECT_THROW(loadAccumulator(path), Error);
}

TEST_F(ReferenceCache, ARequestWithoutAnyBudgetIsAnError) {
  request_.target = ReferenceTarget{0, 0.0, 0.0};
  try {
    ensureReference(scene_, camera_, request_);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no sample budget"), std::string::npos) << e.what();
  }
}

TEST_F(ReferenceCache, ATimeBudgetStopsRendering) {
  request_.target = ReferenceTarget{0, 0.2, 0.0};
  const Reference r = ensureReference(scene_, camera_, request_);
  EXPECT_GE(r.seconds, 0.2);
  EXPECT_GT(r.samples, 0);
}

TEST_F(ReferenceCache, TheManifestRecordsTheEngineAndTheKeyLeavesItOut) {
  request_.target = ReferenceTarget{2, 0.0, 0.0};
  const std::string narrowest = supportedInstructionSets().front();
  request_.tracer.engine = {narrowest, 1};
  const Reference traced = ensureReference(scene_, camera_, request_);
  EXPECT_EQ(traced.manifest["last_session"]["engine"]["isa"], narrowest);
  EXPECT_EQ(traced.manifest["last_session"]["engine"]["packet_width"], 1);
  // Another engine: the same key, so the cached reference is reused, not traced again.
  request_.tracer.engine = {"auto", 0};
  EXPECT_EQ(referenceKey(scene_, camera_, request_), traced.key);
  EXPECT_TRUE(ensureReference(scene_, camera_, request_).reused);
}

}  // namespace
}  // namespace lpvlab

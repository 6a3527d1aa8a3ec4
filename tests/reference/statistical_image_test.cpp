// The statistical image test on a real scene: an independent, noisy rendering of the Cornell box
// (another seed) against a stored low-noise reference read back from the reference cache, both
// with their variances. With nothing wrong, the rejections at a Sidak-corrected family level are
// as few as chance allows; biases of 10% (in the mean z) and 50% (per pixel) are caught.

#include <filesystem>

#include <gtest/gtest.h>

#include "framework/io/image.h"
#include "framework/reference/reference_cache.h"
#include "framework/reference/statistical_compare.h"
#include "framework/scene/scene_loader.h"
#include "instruction_sets.h"

namespace lpvlab {
namespace {

// The stored reference is traced on the widest instruction set; each set's independent rendering
// must agree with it statistically.
class StatisticalImage : public testing::PerInstructionSet {
protected:
  void SetUp() override {
    PerInstructionSet::SetUp();
#ifdef LPVLAB_SANITIZED
    // The comparison runs the furnace tests' code again at 64x64 and many samples: under the
    // sanitizers (-O0) two minutes per set, so there once, on the widest set (the furnace tests
    // cover the narrow query width's code).
    if (!IsSkipped() && isa() != supportedInstructionSets().back())
      GTEST_SKIP() << "under the sanitizers the statistical image runs on the widest set only";
#endif
  }
};

TEST_P(StatisticalImage, IndependentRenderingAgreesWithTheStoredReference) {
  const auto cache = std::filesystem::temp_directory_path() /
                     ("lpvlab_statistical_image_" + testing::instructionSetName({isa(), 0}));
  std::filesystem::remove_all(cache);
  const Scene scene = makeCornellBox();
  const Camera& camera = scene.cameras.front();
  ReferenceRequest request;
  request.width = request.height = 24;
  request.target.samples = 4096;
  request.cacheDir = cache.string();
  request.showProgress = false;
  const Reference reference = ensureReference(scene, camera, request);
  const std::vector<NamedImage> stored = readExr(reference.directory + "/images.exr");

  TracerSettings settings = tracerSettings();
  settings.seed = 2;
  const PathTracer tracer(scene, camera, 24, 24, settings);
  Accumulator noisy(24, 24);
  tracer.render(noisy, 512, 0);
  const std::vector<NamedImage> test = noisy.images();

  for (const char* name : {"combined", "direct", "indirect", "indirect1"}) {
    const std::string variance = std::string(name) + "_variance";
    const ComparisonResult result = compareImages(findAov(test, name), findAov(test, variance),
                                                  findAov(stored, name), findAov(stored, variance));
    EXPECT_GT(result.tests, 24 * 24);
    // Chance alone rejects about alpha = 0.01 tests in all; the spot's cone edge, where few
    // samples see the lit sliver, lets sample variances run low, so allow a couple.
    EXPECT_LE(result.rejected, 2) << name << ": expected " << result.expectedRejected
                                  << ", threshold " << result.threshold << ", max |z| " << result.maxAbsZ;
    EXPECT_LT(std::abs(result.meanZ), 0.2) << name;

    // Negative controls: a 10% bias is too small for one pixel's noise but shifts the mean z over
    // the image; a 50% bias is rejected pixel by pixel.
    for (float bias : {1.1f, 1.5f}) {
      Image biased = findAov(test, name);
      for (float& v : biased.pixels) v *= bias;
      const ComparisonResult control = compareImages(biased, findAov(test, variance),
                                                     findAov(stored, name), findAov(stored, variance));
      if (bias < 1.2f) EXPECT_GT(control.meanZ, 0.2) << name << ": a 10% bias must shift the mean z";
      else EXPECT_GT(control.rejected, 20) << name << ": a 50% bias must be rejected per pixel";
    }
  }
  std::filesystem::remove_all(cache);
}

LPVLAB_PER_INSTRUCTION_SET(StatisticalImage);

}  // namespace
}  // namespace lpvlab

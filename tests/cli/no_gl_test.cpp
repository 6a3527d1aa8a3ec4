// gl.backend = "none" (framework/gl/context.h): a run that makes no GL context and loads no GL
// library, every stage on the CPU (the raster passes by ray casting, framework/raster), in its own
// process (the test binaries hold a GL context, so only a separate lpvlab shows a run without).
//   - it runs, says so (the manifest's libraries.gl_backend and gl_renderer, every stage timed by
//     the CPU wall clock, every raster pass by Embree), and its images are bit for bit those of a
//     run with GL whose raster passes and strategies run on the CPU (the same kernels);
//   - what needs GL is refused with one error naming the key that chose it, before any reference
//     is rendered: compute.backend or compute.raster "gl", the strategies that draw with GL (sky
//     injection's columns, subsurface rendering's RSM: by their table and type), radiosity's
//     hemicube (indirect.form_factors), light-field particles; radiosity with ray-cast form
//     factors runs.

#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "executable_support.h"
#include "framework/io/image.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

const std::string kSmall = " -s output.width=40 -s output.height=32 -s timing.warmup=0 -s timing.repeats=1"
                           " -s grid.resolution=12 -s propagation.iterations=8";
const std::string kNoGl = " -s gl.backend='\"none\"'";

nlohmann::json manifestOf(const fs::path& run) {
  return nlohmann::json::parse(test::readFile(run / "manifest.json"));
}

TEST(NoGl, RunsEveryStageOnTheCpuAndGivesTheImagesOfARunWithGl) {
  test::TempDir dir;
  const test::LpvlabResult none = test::runLpvlab("run --out none" + kSmall + kNoGl, dir.path(), dir.path());
  ASSERT_EQ(none.exitCode, 0) << none.err;
  EXPECT_NE(none.err.find("on none (no GL) (none)"), std::string::npos) << none.err;
  const nlohmann::json m = manifestOf(dir.path() / "none");
  EXPECT_EQ(m["libraries"]["gl_backend"], "none");
  EXPECT_EQ(m["libraries"]["gl_renderer"], "none (no GL)");
  EXPECT_EQ(m["compute"]["backend"], "cpu");
  for (const char* pass : {"gbuffer", "rsm", "shadow_maps"})
    EXPECT_EQ(m["compute"]["raster"]["passes"][pass], "embree") << pass;
  for (const auto& [stage, clock] : m["timing"]["clock"].items())
    EXPECT_NE(clock, "gl_timer_query") << stage << ": a GL clock in a run without GL";

  const test::LpvlabResult gl = test::runLpvlab(
      "run --out gl" + kSmall + " -s compute.backend='\"cpu\"' -s compute.raster='\"embree\"'", dir.path(), dir.path());
  ASSERT_EQ(gl.exitCode, 0) << gl.err;
  const std::vector<NamedImage> noneAovs = readExr((dir.path() / "none" / "images.exr").string());
  const std::vector<NamedImage> glAovs = readExr((dir.path() / "gl" / "images.exr").string());
  for (const std::string aov : {"direct", "indirect", "albedo", "normal", "depth"}) {
    const Image& a = findAov(noneAovs, aov);
    const Image& b = findAov(glAovs, aov);
    ASSERT_EQ(a.pixels.size(), b.pixels.size()) << aov;
    EXPECT_EQ(a.pixels, b.pixels) << aov << ": the same kernels on the same inputs";
    double sum = 0.0;
    for (float v : a.pixels) sum += v;
    if (aov == "direct" || aov == "indirect") {
      EXPECT_GT(sum, 0.0) << aov << ": all black";
    }
  }
}

TEST(NoGl, WhatNeedsGlIsRefusedNamingIt) {
  test::TempDir dir;
  const struct {
    std::string file, args, names;
  } cases[] = {
      {"", " -s compute.backend='\"gl\"'", "compute.backend"},
      {"", " -s compute.raster='\"gl\"'", "compute.raster"},
      {"", " -s 'injection.also=[{type=\"sky_columns\"}]' -s 'sky.radiance=[0.1,0.1,0.1]'"
       " -s reference.compare=true",
       "[injection.also[0]] type = \"sky_columns\" needs GL"},
      {LPVLAB_SOURCE_DIR "/experiments/ablation_subsurface.toml", "",
       "[rendering.also[0]] type = \"subsurface\" needs GL"},
      {"", " -s indirect.method='\"radiosity\"' -s reference.compare=true", "key 'indirect.form_factors'"},
  };
  for (const auto& c : cases) {
    const test::LpvlabResult r = test::runLpvlab("run " + c.file + " --out out" + kSmall + kNoGl + c.args,
                                                     dir.path(), dir.path());
    EXPECT_NE(r.exitCode, 0) << c.args;
    EXPECT_EQ(r.err.rfind("lpvlab: error: "), r.err.find("lpvlab: error: ")) << "one error:\n" << r.err;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << c.args << ":\n" << r.err;
    EXPECT_NE(r.err.find("none"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out" / "manifest.json")) << c.args;
    EXPECT_EQ((r.out + r.err).find("spp"), std::string::npos) << "a reference rendered first:\n" << r.out;
  }
  const test::LpvlabResult rays = test::runLpvlab(
      "run --out rays" + kSmall + kNoGl + " -s indirect.method='\"radiosity\"' -s indirect.form_factors='\"rays\"'"
      " -s indirect.patch_size=0.2 -s indirect.rays=64", dir.path(), dir.path());
  EXPECT_EQ(rays.exitCode, 0) << rays.err;
  EXPECT_EQ(manifestOf(dir.path() / "rays")["libraries"]["gl_backend"], "none");
  const test::LpvlabResult particles = test::runLpvlab(
      "run " LPVLAB_SOURCE_DIR "/experiments/particles_cornell.toml --out p" + kSmall + kNoGl, dir.path(), dir.path());
  EXPECT_NE(particles.exitCode, 0);
  EXPECT_NE(particles.err.find("gl.backend"), std::string::npos) << particles.err;
  EXPECT_NE(particles.err.find("light field"), std::string::npos) << particles.err;
}

}  // namespace
}  // namespace lpvlab

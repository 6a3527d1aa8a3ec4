// The fit reads each scene file once (SceneCache) and builds the strategies per rendering; its
// renderings are the images a plain run of the same view gives (an experiment file loaded and
// rendered by the pipeline, as `lpvlab run` does), for views of different scenes, in any order.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "fit/fit_test_support.h"
#include "framework/experiment/experiment.h"
#include "framework/fit/fit_evaluator.h"
#include "framework/pipeline/pipeline.h"
#include "gl/gl_test_context.h"

namespace lpvlab {
namespace {

// The tables of the second scene's view: the shared OBJ Cornell box (no lights of its own).
const std::string kObjScene =
    "scene = { file = \"shared:scenes/cornell_box/CornellBox-Original.obj\" }\n"
    "lights = [{ name = \"lamp\", type = \"point\", position = [0.0, 1.5, 0.0], intensity = 2.0 }]\n"
    "camera = { position = [0.0, 1.0, 3.9], look_at = [0.0, 1.0, 0.0], fov_deg = 39.3 }\n";
const std::string kLeftCamera =
    "camera = { position = [0.08, 0.35, -0.45], look_at = [0.36, 0.24, 0.40], fov_deg = 45.0 }\n";

Image plainRun(const std::string& path) {
  Experiment e = loadExperiment(path);
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  return findAov(pipeline.readOutputs(), "indirect");
}

void expectSameImage(const Image& fit, const Image& plain, const std::string& view) {
  ASSERT_EQ(fit.pixels.size(), plain.pixels.size()) << view;
  double largest = 0.0;
  for (float v : plain.pixels) largest = std::max(largest, double(std::abs(v)));
  ASSERT_GT(largest, 0.0) << view;
  // Injection adds VPLs with float atomics in any order: two runs agree to rounding only.
  for (std::size_t i = 0; i < fit.pixels.size(); ++i)
    ASSERT_NEAR(fit.pixels[i], plain.pixels[i], 1e-5 * largest) << view << ", value " << i;
}

TEST(FitSceneCache, RenderingsEqualPlainRunsAndEachSceneIsReadOnce) {
  test::glTestContext();
  test::FitFiles files("scene-cache");
  const std::string base = test::smallCornellBox(8);
  const std::string fit = files.write(
      "fit.toml", base + "[fit]\nparameters = [{ key = \"propagation.damping\" }]\n"
                         "[[fit.views]]\nname = \"main\"\n"
                         "[[fit.views]]\nname = \"obj\"\n" + kObjScene +
                         "[[fit.held_out]]\nname = \"left\"\n" + kLeftCamera);
  const FitSpec spec = readFitSpec(fit);
  std::vector<FitView> views;
  for (const bool heldOut : {false, true})
    for (const FitViewSpec& v : heldOut ? spec.heldOut : spec.views)
      views.push_back(FitView{v.name, heldOut, spec.viewTable(v), Image(64, 64, 3)});
  FitEvaluator evaluator(spec, views);

  // The same views as experiment files of their own, with the parameter's value written in.
  const std::string withDamping = base.substr(0, base.find("[propagation]")) + "[propagation]\ndamping = 0.9\n" +
                                  base.substr(base.find("[propagation]") + std::string("[propagation]\n").size());
  const std::string main = files.write("main.toml", withDamping);
  const std::string obj = files.write("obj.toml", kObjScene + withDamping);
  const std::string left = files.write("left.toml", kLeftCamera + withDamping);

  const Image mainFit = evaluator.render(evaluator.views()[0], {0.9}).indirect;
  const Image objFit = evaluator.render(evaluator.views()[1], {0.9}).indirect;
  const Image leftFit = evaluator.render(evaluator.views()[2], {0.9}).indirect;
  const Image mainAgain = evaluator.render(evaluator.views()[0], {0.9}).indirect;
  // The parameter still acts: the strategies are rebuilt per rendering.
  const Image mainOther = evaluator.render(evaluator.views()[0], {0.5}).indirect;
  EXPECT_EQ(evaluator.scenes().loads(), 2) << "the built-in box and the OBJ, each read once";

  expectSameImage(mainFit, plainRun(main), "main");
  expectSameImage(objFit, plainRun(obj), "obj");
  expectSameImage(leftFit, plainRun(left), "left");
  expectSameImage(mainAgain, mainFit, "main again");
  double sum09 = 0.0, sum05 = 0.0;
  for (std::size_t i = 0; i < mainFit.pixels.size(); ++i) sum09 += mainFit.pixels[i], sum05 += mainOther.pixels[i];
  EXPECT_LT(sum05, 0.9 * sum09);
}

}  // namespace
}  // namespace lpvlab

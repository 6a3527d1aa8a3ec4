#pragma once
// Fits on synthetic targets: the small Cornell box's fit file (fit_test_support.h) with one
// fitted view, and targets rendered by lpvlab's own pipeline at known constants plus seeded
// Gaussian noise of 2% of the mean (a path-traced reference has noise too).

#include <random>
#include <string>
#include <vector>

#include "fit/fit_test_support.h"
#include "framework/fit/fit_evaluator.h"
#include "framework/fit/fit_spec.h"

namespace lpvlab::test {

// The small Cornell box with `iterations` propagation steps, the [fit] table's body `fit`
// (parameters and settings) and one fitted view, "main".
inline FitSpec smallFitSpec(const FitFiles& files, int iterations, const std::string& fit) {
  return readFitSpec(files.write("fit.toml", smallCornellBox(iterations) + "[fit]\n" + fit +
                                                 "[[fit.views]]\nname = \"main\"\n"));
}

// The fit file's views with targets rendered by the pipeline itself at `truth`, plus noise.
inline std::vector<FitView> syntheticViews(const FitSpec& spec, const std::vector<double>& truth) {
  std::vector<FitView> views;
  for (const FitViewSpec& v : spec.views) {
    FitView view{v.name, false, spec.viewTable(v), Image(64, 64, 3)};
    views.push_back(std::move(view));
  }
  FitEvaluator renderer(spec, views);
  std::mt19937_64 random(20261121);
  for (FitView& view : views) {
    const ViewRender r = renderer.render(view, truth);
    double mean = 0.0;
    for (float v : r.indirect.pixels) mean += v;
    mean /= double(r.indirect.pixels.size());
    std::normal_distribution<double> noise(0.0, 0.02 * mean);
    view.target = r.indirect;
    for (float& v : view.target.pixels) v = float(v + noise(random));
  }
  return views;
}

}  // namespace lpvlab::test

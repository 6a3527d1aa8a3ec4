#pragma once
// Helpers of the indirect-method tests: running a method through the pipeline (on the plates
// scene of many_lights/plates_scene.h, whose geometry term is bounded), per-pixel statistics over
// independent runs, and the pixels away from edges.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/experiment/experiment.h"
#include "framework/io/image.h"
#include "framework/pipeline/pipeline.h"
#include "framework/reference/path_tracer.h"
#include "gl/gl_test_context.h"
#include "many_lights/plates_scene.h"

namespace lpvlab::test {

// One frame of the built-in default experiment with `overrides` (e.g. indirect.method=...), on
// `scene` seen by `camera` when given; its AOVs and the method's statistics.
struct MethodRun {
  std::vector<NamedImage> aovs;
  nlohmann::json statistics;
  const Image& indirect() const { return findAov(aovs, "indirect"); }
};

inline MethodRun runMethod(const std::vector<std::string>& overrides, const Scene* scene = nullptr,
                           const Camera* camera = nullptr) {
  glTestContext();
  Experiment e = loadExperiment("", overrides);
  if (scene) e.scene = *scene;
  if (camera) e.camera = *camera;
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  MethodRun run{pipeline.readOutputs(), nlohmann::json::object()};
  run.statistics = pipeline.method().statistics();
  return run;
}

// Per-pixel mean of independent estimates and the variance of that mean (sample variance / n).
struct MeanImage {
  Image mean, varianceOfMean;
};

inline MeanImage meanOf(const std::vector<Image>& runs) {
  const Image& first = runs.front();
  MeanImage out{Image(first.width, first.height, first.channels),
                Image(first.width, first.height, first.channels)};
  const double n = double(runs.size());
  for (std::size_t i = 0; i < first.pixels.size(); ++i) {
    double sum = 0.0, squares = 0.0;
    for (const Image& run : runs) sum += run.pixels[i], squares += double(run.pixels[i]) * run.pixels[i];
    const double mean = sum / n;
    out.mean.pixels[i] = float(mean);
    out.varianceOfMean.pixels[i] = float(std::max(0.0, (squares - n * mean * mean) / (n - 1.0)) / n);
  }
  return out;
}

// Pixels whose 3x3 neighbourhood sees one flat surface (no silhouette, crease or background):
// where a G-buffer pixel's centre and a path tracer's pixel average see the same thing.
inline std::vector<bool> awayFromEdges(const std::vector<NamedImage>& aovs) {
  const Image& depth = findAov(aovs, "depth");
  const Image& normal = findAov(aovs, "normal");
  std::vector<bool> keep(std::size_t(depth.width) * depth.height, false);
  for (int y = 1; y + 1 < depth.height; ++y)
    for (int x = 1; x + 1 < depth.width; ++x) {
      bool flat = depth.at(x, y, 0) > 0.0f;
      for (int dy = -1; dy <= 1 && flat; ++dy)
        for (int dx = -1; dx <= 1 && flat; ++dx) {
          const float d = depth.at(x + dx, y + dy, 0), d0 = depth.at(x, y, 0);
          double dot = 0.0;
          for (int c = 0; c < 3; ++c) dot += normal.at(x + dx, y + dy, c) * normal.at(x, y, c);
          flat = d > 0.0f && std::abs(d - d0) < 0.1f * d0 && dot > 0.999;
        }
      keep[std::size_t(y) * depth.width + x] = flat;
    }
  return keep;
}

// `variance` with NaN where `keep` is false: compareImages leaves those values untested.
inline Image onlyWhere(const Image& variance, const std::vector<bool>& keep) {
  Image out = variance;
  for (std::size_t p = 0; p < keep.size(); ++p)
    if (!keep[p])
      for (int c = 0; c < out.channels; ++c) out.pixels[p * out.channels + c] = std::nanf("");
  return out;
}

// The mean over the kept pixels' channels of each run, their mean and its standard error, and
// the same mean of `target`: whether the runs scatter about the target as a whole (the per-pixel
// z scores of one image are correlated, all runs' pixels sharing their VPLs, so their mean is no
// such test).
struct ImageMeans {
  double runs = 0.0, standardError = 0.0, target = 0.0;
};

inline double keptMean(const Image& image, const std::vector<bool>& keep) {
  double sum = 0.0;
  int values = 0;
  for (std::size_t p = 0; p < keep.size(); ++p)
    for (int c = 0; c < 3 && keep[p]; ++c) sum += image.pixels[p * 3 + c], ++values;
  return sum / values;
}

inline ImageMeans imageMeans(const std::vector<Image>& runs, const Image& target,
                             const std::vector<bool>& keep) {
  ImageMeans out;
  std::vector<double> means;
  for (const Image& run : runs) means.push_back(keptMean(run, keep));
  const double n = double(means.size());
  for (double m : means) out.runs += m / n;
  double spread = 0.0;
  for (double m : means) spread += (m - out.runs) * (m - out.runs) / (n - 1.0);
  out.standardError = std::sqrt(spread / n);
  out.target = keptMean(target, keep);
  return out;
}

}  // namespace lpvlab::test

// The LPV pipeline's rasterised, shadow-mapped direct light against the path tracer's `direct` on
// the built-in Cornell box, pixel by pixel, at a Sidak-corrected level. They may differ only
// where the rasteriser and the tracer see different things inside one pixel: along silhouettes
// (the tracer averages the pixel, the rasteriser takes its centre) and along shadow edges (the
// shadow map's resolution and filtering). The test reports the fraction rejected and requires the
// rejected pixels to lie on such edges.

#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "framework/experiment/experiment.h"
#include "framework/pipeline/pipeline.h"
#include "framework/reference/path_tracer.h"
#include "framework/reference/statistical_compare.h"
#include "pipeline_test_support.h"

namespace lpvlab {
namespace {

double luminance(const Image& image, int x, int y) {
  return 0.2126 * image.at(x, y, 0) + 0.7152 * image.at(x, y, 1) + 0.0722 * image.at(x, y, 2);
}

// Whether (x, y) is within `radius` pixels of an edge: a depth jump, a change of normal, or a
// jump in the rasterised direct light (a shadow boundary).
bool nearEdge(const Image& depth, const Image& normal, const Image& direct, int x, int y, int radius) {
  const double d0 = depth.at(x, y, 0), l0 = luminance(direct, x, y);
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const int u = x + dx, v = y + dy;
      if (u < 0 || v < 0 || u >= depth.width || v >= depth.height) return true;
      const double d = depth.at(u, v, 0);
      if ((d == 0.0) != (d0 == 0.0) || std::abs(d - d0) > 0.02 * std::max(d, d0)) return true;
      double dot = 0.0;
      for (int c = 0; c < 3; ++c) dot += normal.at(u, v, c) * normal.at(x, y, c);
      if (dot < 0.99) return true;
      const double l = luminance(direct, u, v);
      if (std::abs(l - l0) > 0.2 * std::max(l, l0)) return true;
    }
  return false;
}

TEST(ReferenceAgreement, RasterisedDirectLightMatchesThePathTracerAwayFromEdges) {
  test::glTestContext();
  Experiment e = loadExperiment("", {"output.width=96", "output.height=96", "grid.resolution=8",
                                     "propagation.iterations=1", "timing.warmup=0"});
  ShaderCompiler shaders;
  Pipeline pipeline(e.scene, e.camera, e.settings, std::move(e.method), shaders);
  pipeline.renderFrame();
  const std::vector<NamedImage> lpv = pipeline.readOutputs();

  const PathTracer tracer(e.scene, e.camera, e.settings.width, e.settings.height, e.reference.tracer);
  Accumulator acc(e.settings.width, e.settings.height);
  tracer.render(acc, 64, 0);
  const std::vector<NamedImage> pt = acc.images();

  // Float rasterisation against a double-precision tracer: allow 1e-4 relative rounding.
  const ComparisonResult result =
      compareToExact(findAov(pt, "direct"), findAov(pt, "direct_variance"), findAov(lpv, "direct"), 0.01, 1e-4);
  const Image& depth = findAov(lpv, "depth");
  const Image& normal = findAov(lpv, "normal");
  const Image& direct = findAov(lpv, "direct");

  int rejectedPixels = 0, rejectedAwayFromEdges = 0;
  for (int y = 0; y < direct.height; ++y)
    for (int x = 0; x < direct.width; ++x) {
      if (!result.rejectedAt(x, y)) continue;
      ++rejectedPixels;
      if (!nearEdge(depth, normal, direct, x, y, 2)) ++rejectedAwayFromEdges;
    }
  const double fraction = double(rejectedPixels) / double(direct.width * direct.height);
  std::cout << "direct: LPV raster vs path tracer (64 spp): " << rejectedPixels << " of "
            << direct.width * direct.height << " pixels rejected (" << 100.0 * fraction
            << "%) at |z| > " << result.threshold << ", " << rejectedAwayFromEdges
            << " of them away from edges; mean z " << result.meanZ << "\n";
  EXPECT_LT(fraction, 0.10);
  EXPECT_LE(rejectedAwayFromEdges, std::max(2, rejectedPixels / 20));
}

}  // namespace
}  // namespace lpvlab

// The VPLs' visibility kinds against each other on the plates scene (a floating cube shadows the
// floor from the VPLs on the ceiling): shadow maps per VPL approach exact rays, imperfect shadow
// maps with dense points approach shadow maps, and pull-push keeps light from leaking through
// the holes of sparse points.

#include <cmath>
#include <iostream>

#include "method_test_support.h"

namespace lpvlab {
namespace {

std::vector<std::string> common(const std::string& method, std::vector<std::string> more) {
  std::vector<std::string> out = {"output.width=64", "output.height=48", "indirect.method=" + method,
                                  "indirect.light_paths=48", "indirect.one_bounce=true"};
  out.insert(out.end(), more.begin(), more.end());
  return out;
}

// Mean over the pixels away from edges of |a - b|, relative to b's mean there.
double relativeDifference(const test::MethodRun& a, const test::MethodRun& b) {
  const std::vector<bool> keep = test::awayFromEdges(b.aovs);
  double difference = 0.0, sum = 0.0;
  for (std::size_t p = 0; p < keep.size(); ++p)
    for (int c = 0; c < 3 && keep[p]; ++c) {
      difference += std::abs(a.indirect().pixels[p * 3 + c] - b.indirect().pixels[p * 3 + c]);
      sum += b.indirect().pixels[p * 3 + c];
    }
  return difference / sum;
}

TEST(VplVisibility, ShadowMapsApproachRaysAndImperfectOnesApproachShadowMaps) {
  const Scene scene = test::platesScene();
  const Camera camera = test::platesCamera();
  const auto run = [&](const std::string& method, std::vector<std::string> more) {
    return test::runMethod(common(method, more), &scene, &camera);
  };
  const test::MethodRun rays = run("instant_radiosity", {"indirect.visibility=\"rays\""});
  const test::MethodRun none = run("instant_radiosity", {"indirect.visibility=\"none\""});
  const test::MethodRun maps64 = run("instant_radiosity", {"indirect.visibility=\"shadow_maps\"",
                                                           "indirect.shadow_map_size=64"});
  const test::MethodRun maps32 = run("instant_radiosity", {"indirect.visibility=\"shadow_maps\"",
                                                           "indirect.shadow_map_size=32"});
  const test::MethodRun ism = run("imperfect_shadow_maps", {"indirect.shadow_map_size=32",
                                                            "indirect.points_per_vpl=16384"});
  const double unshadowed = relativeDifference(none, rays);
  const double mapped = relativeDifference(maps64, rays);
  const double imperfect = relativeDifference(ism, maps32);
  std::cout << "mean |difference| relative to the reference image: no visibility vs rays "
            << unshadowed << ", shadow maps 64^2 vs rays " << mapped
            << ", imperfect (16384 points) vs shadow maps 32^2 " << imperfect << "\n";
  EXPECT_GT(unshadowed, 0.05);  // the cube's shadow matters here
  EXPECT_LT(mapped, 0.2 * unshadowed);
  // Splats keep a texel's nearest point, so occluders grow by up to a texel at their silhouettes
  // and imperfect maps shadow more than exact ones (about 5% of the light here, whatever the
  // bias): closer to exact maps than no visibility is, by a wide margin, not equal to them.
  EXPECT_LT(imperfect, 0.5 * unshadowed);
  EXPECT_GT(ism.statistics["imperfect_shadow_maps"]["splats"].get<double>(), 0.0);
}

// With few points most texels are holes: left as holes (no pull-push) the VPLs see through them
// and light leaks into the cube's shadow; pull-push fills them from neighbouring depths.
TEST(VplVisibility, PullPushStopsLightLeakingThroughHoles) {
  const Scene scene = test::platesScene();
  const Camera camera = test::platesCamera();
  const auto run = [&](int levels) {
    return test::runMethod(common("imperfect_shadow_maps",
                                  {"indirect.shadow_map_size=32", "indirect.points_per_vpl=256",
                                   "indirect.pull_push_levels=" + std::to_string(levels)}),
                           &scene, &camera);
  };
  const test::MethodRun holes = run(0), filled = run(5);
  const test::MethodRun rays = test::runMethod(common("instant_radiosity", {}), &scene, &camera);
  const auto& h = holes.statistics["imperfect_shadow_maps"];
  const auto& f = filled.statistics["imperfect_shadow_maps"];
  std::cout << "256 points per VPL: holes " << h["hole_fraction_before_pull_push"] << " -> "
            << h["hole_fraction_after_pull_push"] << " without pull-push, "
            << f["hole_fraction_after_pull_push"] << " with; difference to rays "
            << relativeDifference(holes, rays) << " and " << relativeDifference(filled, rays) << "\n";
  EXPECT_GT(h["hole_fraction_before_pull_push"].get<double>(), 0.5);
  EXPECT_EQ(h["hole_fraction_after_pull_push"], h["hole_fraction_before_pull_push"]);
  EXPECT_EQ(f["hole_fraction_after_pull_push"].get<double>(), 0.0);
  EXPECT_LT(relativeDifference(filled, rays), relativeDifference(holes, rays));
}

}  // namespace
}  // namespace lpvlab

// The Delaunay triangulation of incremental instant radiosity's VPLs (CGAL, through
// framework/many_lights/disk_triangulation.h): the densest pair, the largest empty circle, the
// nearest point, on configurations whose answers are known.

#include <cmath>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/many_lights/disk_triangulation.h"

namespace lpvlab {
namespace {

TEST(DiskTriangulation, FindsTheDensestPairAndTheLargestEmptyCircle) {
  DiskTriangulation t;
  EXPECT_EQ(t.densest().first, -1);
  EXPECT_EQ(t.largestEmptyCircle().first, glm::dvec2(0.0));  // nothing yet: the centre
  t.insert({0.0, 0.0}, 7);
  // One point at the centre: every rim point is 1 away.
  EXPECT_NEAR(t.largestEmptyCircle().second, 1.0, 1e-12);
  // A square of four points around it: the largest empty circles are centred on the rim between
  // two corners, (1, 0) and its turns, sqrt(0.5) from the nearest corners (the rim samples find
  // them to within pi / samples).
  t.insert({0.5, 0.5}, 1);
  t.insert({-0.5, 0.5}, 2);
  t.insert({-0.5, -0.5}, 3);
  t.insert({0.5, -0.5}, 4);
  const auto [centre, radius] = t.largestEmptyCircle(1024);
  EXPECT_NEAR(glm::length(centre), 1.0, 1e-9);
  EXPECT_LE(radius, std::sqrt(0.5) + 1e-12);
  EXPECT_GT(radius, std::sqrt(0.5) - M_PI / 1024);
  // A fifth point close to a corner: the densest place.
  t.insert({0.56, 0.5}, 5);
  const auto [id, edge] = t.densest();
  EXPECT_NEAR(edge, 0.06, 1e-12);
  EXPECT_TRUE(id == 1 || id == 5);
  EXPECT_EQ(t.nearest({0.1, -0.05}), 7);
  EXPECT_EQ(t.nearest({-0.6, -0.4}), 3);
  t.remove(5);
  EXPECT_NEAR(t.densest().second, std::sqrt(0.5), 1e-12);
  EXPECT_EQ(t.size(), 5u);
  EXPECT_THROW(t.insert({0.0, 0.0}, 8), Error);  // on id 7
}

}  // namespace
}  // namespace lpvlab

// The reprojection of the temporal metrics (framework/reference/reprojection.h) on depth images of
// planes whose geometry is known: CameraRays' projection inverts its rays, a camera that did not
// move maps every pixel onto itself, a sideways move of one pixel's footprint shifts every pixel
// by one column, and points the previous frame did not see get no taps.

#include "framework/reference/reprojection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "framework/core/error.h"
#include "framework/reference/camera_rays.h"

namespace lpvlab {
namespace {

constexpr int kWidth = 48, kHeight = 32;

Camera lookingDownZ(glm::vec3 position) {
  Camera camera;
  camera.position = position;
  camera.forward = {0, 0, -1};
  camera.up = {0, 1, 0};
  camera.verticalFov = 0.8f;
  return camera;
}

// The depth and normal AOVs of a camera that sees the planes dot(n, p) = d given (the nearest in
// front of it per pixel), as the G-buffer writes them: view depth, and the normal facing the
// camera.
struct Plane {
  glm::vec3 normal;
  float distance;
  // Only points with |x| <= halfWidth are on it (a finite panel in front of a wall).
  float halfWidth = INFINITY;
};
struct Aovs {
  Image depth{kWidth, kHeight, 1}, normal{kWidth, kHeight, 3};
};
Aovs render(const Camera& camera, const std::vector<Plane>& planes) {
  const CameraRays rays(camera, kWidth, kHeight);
  Aovs aovs;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const glm::vec3 d = rays.direction(float(x) + 0.5f, float(y) + 0.5f);
      float best = INFINITY;
      glm::vec3 normal{0.0f};
      for (const Plane& plane : planes) {
        const float t =
            (plane.distance - glm::dot(plane.normal, rays.origin())) / glm::dot(plane.normal, d);
        const glm::vec3 p = rays.origin() + t * d;
        if (t > 0.0f && t < best && std::abs(p.x) <= plane.halfWidth) {
          best = t;
          normal = glm::dot(plane.normal, d) < 0.0f ? plane.normal : -plane.normal;
        }
      }
      if (!std::isfinite(best)) continue;
      aovs.depth.at(x, y, 0) = rays.viewDepth(rays.origin() + best * d);
      for (int c = 0; c < 3; ++c) aovs.normal.at(x, y, c) = normal[c];
    }
  return aovs;
}

const Plane kWall{{0, 0, 1}, -5.0f};  // z = -5, facing the camera
const Plane kTilted{glm::normalize(glm::vec3(1, 0.3f, 1)), -3.0f};

TEST(CameraRays, ImagePositionInvertsTheRaysAndSurfacePointTheirDepth) {
  Camera camera = lookingDownZ({0.3f, -0.2f, 1.0f});
  orientCamera(camera, {1.0f, 0.5f, -4.0f}, {0, 1, 0});
  const CameraRays rays(camera, kWidth, kHeight);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> px(0.0f, float(kWidth)), py(0.0f, float(kHeight)),
      depth(0.1f, 50.0f);
  for (int i = 0; i < 200; ++i) {
    const float x = px(random), y = py(random), d = depth(random);
    const glm::vec3 p = rays.surfacePoint(x, y, d);
    EXPECT_NEAR(rays.viewDepth(p), d, 1e-5f * d);
    const std::optional<glm::vec2> back = rays.imagePosition(p);
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(back->x, x, 1e-3f);
    EXPECT_NEAR(back->y, y, 1e-3f);
  }
  EXPECT_FALSE(rays.imagePosition(camera.position - camera.forward).has_value());  // behind
}

TEST(Reprojection, ACameraThatDidNotMoveMapsEveryPixelOntoItself) {
  Camera camera = lookingDownZ({0.1f, 0.2f, 0.0f});
  orientCamera(camera, {0.7f, -0.4f, -5.0f}, {0, 1, 0});
  const Aovs aovs = render(camera, {kWall, kTilted});
  const Reprojection r =
      reprojectThroughDepth({camera, aovs.depth, aovs.normal}, {camera, aovs.depth, aovs.normal});
  int seen = 0;
  for (std::size_t p = 0; p < r.taps.size(); ++p) {
    if (aovs.depth.pixels[p] == 0.0f) {
      EXPECT_EQ(r.taps[p].count, 0);
      continue;
    }
    ++seen;
    ASSERT_EQ(r.taps[p].count, 1) << "pixel " << p;
    EXPECT_EQ(r.taps[p].pixel[0], std::int32_t(p));
    EXPECT_EQ(r.taps[p].weight[0], 1.0f);
  }
  EXPECT_GT(seen, kWidth * kHeight / 2);
}

// The camera moves sideways by `pixels` times one pixel's footprint on the wall: a point of the
// wall the camera sees at column x now was at column x + pixels before.
Reprojection movedSideways(float pixels, const std::vector<Plane>& planes, Aovs* after = nullptr) {
  const Camera before = lookingDownZ({0, 0, 0});
  const float footprint = 2.0f * 5.0f * std::tan(before.verticalFov / 2.0f) / float(kHeight);
  const Camera now = lookingDownZ({pixels * footprint, 0, 0});
  const Aovs a = render(before, planes), b = render(now, planes);
  if (after) *after = b;
  return reprojectThroughDepth({now, b.depth, b.normal}, {before, a.depth, a.normal});
}

TEST(Reprojection, AMoveOfOnePixelsFootprintShiftsTheWallByOneColumn) {
  const Reprojection r = movedSideways(1.0f, {kWall});
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const Reprojection::Taps& t = r.taps[std::size_t(y * kWidth + x)];
      if (x == kWidth - 1) {  // seen at column kWidth: outside the previous image
        EXPECT_EQ(t.count, 0);
        continue;
      }
      ASSERT_EQ(t.count, 1) << x << ", " << y;
      EXPECT_EQ(t.pixel[0], y * kWidth + x + 1);
    }
}

TEST(Reprojection, AMoveOfHalfAPixelGivesTwoEqualTaps) {
  const Reprojection r = movedSideways(0.5f, {kWall});
  const Reprojection::Taps& t = r.taps[std::size_t(10 * kWidth + 20)];
  ASSERT_EQ(t.count, 2);
  EXPECT_EQ(t.pixel[0], 10 * kWidth + 20);
  EXPECT_EQ(t.pixel[1], 10 * kWidth + 21);
  EXPECT_NEAR(t.weight[0], 0.5f, 1e-3f);
  EXPECT_NEAR(t.weight[0] + t.weight[1], 1.0f, 1e-6f);
}

// A panel 3 m in front of the wall hides part of it from the first camera; after a sideways
// move the wall beside the panel's edge comes into view. A pixel gets taps exactly when the
// previous camera saw its point at the four pixels around where it projects (checked here by
// comparing depths, independently of the tolerances), and those taps see that surface.
TEST(Reprojection, PointsHiddenBeforeGetNoTaps) {
  const Plane panel{{0, 0, 1}, -2.0f, 0.5f};
  const Camera before = lookingDownZ({0, 0, 0});
  const float footprint = 2.0f * 5.0f * std::tan(before.verticalFov / 2.0f) / float(kHeight);
  // 6.3 footprints at the wall, 15.75 at the panel: no point lands on a pixel centre, so every
  // pixel has four taps or none.
  const Camera after = lookingDownZ({6.3f * footprint, 0, 0});
  const Aovs previous = render(before, {kWall, panel}), now = render(after, {kWall, panel});
  const Reprojection r = reprojectThroughDepth({after, now.depth, now.normal},
                                               {before, previous.depth, previous.normal});
  const CameraRays raysBefore(before, kWidth, kHeight), raysNow(after, kWidth, kHeight);
  int disoccluded = 0, wall = 0, onPanel = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t p = std::size_t(y * kWidth + x);
      const glm::vec3 point =
          raysNow.surfacePoint(float(x) + 0.5f, float(y) + 0.5f, now.depth.pixels[p]);
      const glm::vec2 at = *raysBefore.imagePosition(point);
      const int x0 = int(std::floor(at.x - 0.5f)), y0 = int(std::floor(at.y - 0.5f));
      if (x0 < 0 || y0 < 0 || x0 + 1 >= kWidth || y0 + 1 >= kHeight) continue;  // the border
      bool seen = true;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
          seen = seen && std::abs(previous.depth.at(x0 + i, y0 + j, 0) -
                                  raysBefore.viewDepth(point)) < 0.01f;
      EXPECT_EQ(r.taps[p].count > 0, seen) << x << ", " << y;
      if (!seen) ++disoccluded;
      if (seen) (now.depth.pixels[p] > 4.0f ? wall : onPanel) += 1;
    }
  EXPECT_GT(disoccluded, 5 * kHeight);  // a band beside the panel, on every row
  EXPECT_GT(wall, 0);
  EXPECT_GT(onPanel, 0);
}

TEST(Reprojection, BadAovsAreErrors) {
  const Camera camera = lookingDownZ({0, 0, 0});
  const Aovs aovs = render(camera, {kWall});
  const Image small(kWidth - 1, kHeight, 1);
  EXPECT_THROW(
      reprojectThroughDepth({camera, small, aovs.normal}, {camera, aovs.depth, aovs.normal}),
      Error);
  Aovs nan = aovs;
  nan.depth.pixels[3] = NAN;
  EXPECT_THROW(
      reprojectThroughDepth({camera, aovs.depth, aovs.normal}, {camera, nan.depth, nan.normal}),
      Error);
  Camera broken = camera;
  broken.up = broken.forward;
  EXPECT_THROW(
      reprojectThroughDepth({camera, aovs.depth, aovs.normal}, {broken, aovs.depth, aovs.normal}),
      Error);
}

}  // namespace
}  // namespace lpvlab

#include "framework/reference/reprojection.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/core/error.h"
#include "framework/reference/camera_rays.h"

namespace lpvlab {

namespace {

constexpr const char* kWhere = "reprojectThroughDepth";

void requireAov(const Image& image, int channels, const char* name, int width, int height) {
  if (image.channels != channels || image.width != width || image.height != height)
    throwAt(kWhere, std::string(name) + " is " + std::to_string(image.width) + "x" +
                        std::to_string(image.height) + " with " + std::to_string(image.channels) +
                        " channels; " + std::to_string(width) + "x" + std::to_string(height) +
                        " with " + std::to_string(channels) + " expected");
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    if (!std::isfinite(image.pixels[i]))
      throwAt(kWhere, std::string(name) + " pixel " + std::to_string(i / std::size_t(channels)) +
                          " is not finite");
}

glm::vec3 normalAt(const Image& normal, std::size_t pixel) {
  return {normal.pixels[pixel * 3], normal.pixels[pixel * 3 + 1], normal.pixels[pixel * 3 + 2]};
}

// The pixel centres around image coordinate `position` along one axis of `size` pixels, with
// their weights: one centre when the position is within 1/1000 pixel of it, else two. False when
// the position lies outside the image.
struct AxisTaps {
  int index[2] = {0, 0};
  float weight[2] = {1.0f, 0.0f};
  int count = 1;
};
bool axisTaps(float position, int size, AxisTaps& taps) {
  if (!(position >= 0.0f && position <= float(size))) return false;
  // Between the image's edge and the outermost centre there is nothing to interpolate with: the
  // edge pixel alone.
  const float centre = std::clamp(position - 0.5f, 0.0f, float(size - 1));
  const float below = std::floor(centre);
  const float fraction = centre - below;
  constexpr float kSnap = 1e-3f;
  taps.index[0] = int(below);
  if (fraction <= kSnap || taps.index[0] + 1 >= size) {
    taps.count = 1;
  } else if (fraction >= 1.0f - kSnap) {
    taps.index[0] += 1;
    taps.count = 1;
  } else {
    taps.index[1] = taps.index[0] + 1;
    taps.weight[0] = 1.0f - fraction;
    taps.weight[1] = fraction;
    taps.count = 2;
  }
  if (taps.count == 1) taps.weight[0] = 1.0f;
  return true;
}

}  // namespace

Reprojection reprojectThroughDepth(const FrameGeometry& now, const FrameGeometry& before,
                                   const ReprojectionTolerances& tolerances) {
  const int width = now.depth.width, height = now.depth.height;
  requireAov(now.depth, 1, "the current frame's depth", width, height);
  requireAov(now.normal, 3, "the current frame's normal", width, height);
  requireAov(before.depth, 1, "the previous frame's depth", width, height);
  requireAov(before.normal, 3, "the previous frame's normal", width, height);
  const CameraRays raysNow(now.camera, width, height), raysBefore(before.camera, width, height);

  Reprojection result;
  result.width = width;
  result.height = height;
  result.taps.resize(std::size_t(width) * std::size_t(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t pixel = std::size_t(y) * std::size_t(width) + std::size_t(x);
      const float depth = now.depth.pixels[pixel];
      if (!(depth > 0.0f)) continue;
      const glm::vec3 p = raysNow.surfacePoint(float(x) + 0.5f, float(y) + 0.5f, depth);
      const glm::vec3 n = normalAt(now.normal, pixel);
      const std::optional<glm::vec2> seen = raysBefore.imagePosition(p);
      AxisTaps tx, ty;
      if (!seen || !axisTaps(seen->x, width, tx) || !axisTaps(seen->y, height, ty)) continue;
      Reprojection::Taps taps;
      bool sameSurface = true;
      for (int j = 0; j < ty.count && sameSurface; ++j)
        for (int i = 0; i < tx.count && sameSurface; ++i) {
          const std::size_t q =
              std::size_t(ty.index[j]) * std::size_t(width) + std::size_t(tx.index[i]);
          const float qDepth = before.depth.pixels[q];
          if (!(qDepth > 0.0f)) {
            sameSurface = false;
            break;
          }
          const glm::vec3 point =
              raysBefore.surfacePoint(float(tx.index[i]) + 0.5f, float(ty.index[j]) + 0.5f, qDepth);
          sameSurface =
              std::abs(glm::dot(n, point - p)) <= tolerances.planeTolerance * depth &&
              std::abs(glm::dot(n, normalAt(before.normal, q))) >= tolerances.minNormalCosine;
          taps.pixel[std::size_t(taps.count)] = std::int32_t(q);
          taps.weight[std::size_t(taps.count)] = tx.weight[i] * ty.weight[j];
          ++taps.count;
        }
      if (sameSurface) result.taps[pixel] = taps;
    }
  return result;
}

}  // namespace lpvlab

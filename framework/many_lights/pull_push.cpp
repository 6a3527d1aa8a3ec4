#include "framework/many_lights/pull_push.h"

#include <algorithm>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

bool defined(float v, float undefined) { return v != undefined; }

}  // namespace

int pullPush(float* map, int size, int maxLevels, float undefined, std::vector<float>& scratch) {
  if (size < 1 || (size & (size - 1)) != 0)
    throw Error("pull-push: the map's side must be a power of two (it is " + std::to_string(size) + ")");
  // The coarser levels live in `scratch`, one after the other.
  std::size_t total = 0;
  int possible = 0;
  for (int s = size / 2; s >= 1 && possible < maxLevels; s /= 2, ++possible) total += std::size_t(s) * s;
  scratch.resize(std::max<std::size_t>(total, 1));
  std::vector<float*> levels = {map};
  std::vector<int> sides = {size};

  // Pull.
  const auto allDefined = [&](const float* level, int side) {
    return std::all_of(level, level + std::size_t(side) * side,
                       [&](float v) { return defined(v, undefined); });
  };
  std::size_t offset = 0;
  while (int(levels.size()) - 1 < possible && !allDefined(levels.back(), sides.back())) {
    const float* fine = levels.back();
    const int fineSide = sides.back(), side = fineSide / 2;
    float* coarse = scratch.data() + offset;
    offset += std::size_t(side) * side;
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) {
        float sum = 0.0f;
        int count = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const float v = fine[std::size_t(2 * y + dy) * fineSide + (2 * x + dx)];
            if (defined(v, undefined)) sum += v, ++count;
          }
        coarse[std::size_t(y) * side + x] = count ? sum / float(count) : undefined;
      }
    levels.push_back(coarse);
    sides.push_back(side);
  }

  // Push.
  for (std::size_t level = levels.size() - 1; level > 0; --level) {
    const float* coarse = levels[level];
    float* fine = levels[level - 1];
    const int side = sides[level - 1], coarseSide = sides[level];
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) {
        float& v = fine[std::size_t(y) * side + x];
        if (!defined(v, undefined)) v = coarse[std::size_t(y / 2) * coarseSide + x / 2];
      }
  }
  return int(levels.size()) - 1;
}

}  // namespace lpvlab

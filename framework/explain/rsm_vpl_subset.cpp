#include "framework/explain/rsm_vpl_subset.h"

#include <cmath>

#include "framework/core/error.h"
#include "framework/reference/random.h"

namespace lpvlab {

namespace {

float fluxWeight(const glm::vec4& flux) { return flux.r + flux.g + flux.b; }

// The smallest block side whose blocks number at most `budget` over every view (a block without a
// covered texel gives no VPL, so the count is of blocks holding one).
int blockSideFor(const RsmImages& rsm, int views, int side, std::size_t budget) {
  for (int s = 1; s < side; s *= 2) {
    std::size_t blocks = 0;
    const int perSide = (side + s - 1) / s;
    std::vector<char> lit(std::size_t(perSide) * perSide);
    for (int view = 0; view < views; ++view) {
      std::fill(lit.begin(), lit.end(), 0);
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
          const std::size_t t = std::size_t(x) + std::size_t(side) * (std::size_t(y) + std::size_t(side) * view);
          if (rsm.flux->texels[t].w > 0.0f && fluxWeight(rsm.flux->texels[t]) > 0.0f)
            lit[std::size_t(y / s) * perSide + std::size_t(x / s)] = 1;
        }
      for (char l : lit) blocks += std::size_t(l);
    }
    if (blocks <= budget) return s;
  }
  return side;
}

}  // namespace

RsmVplSubset rsmVplSubset(const RsmImages& rsm, int views, int side, std::size_t budget,
                          std::uint64_t seed, std::uint64_t draw) {
  const std::size_t texels = std::size_t(views) * side * side;
  if (rsm.position->texels.size() != texels || rsm.normal->texels.size() != texels ||
      rsm.flux->texels.size() != texels)
    throw Error("explain: the RSM's images are not " + std::to_string(views) + " views of " +
                std::to_string(side) + "^2 texels");
  if (budget == 0) throw Error("explain: a VPL budget of 0");
  RsmVplSubset out;
  for (std::size_t t = 0; t < texels; ++t) out.coveredTexels += rsm.flux->texels[t].w > 0.0f ? 1 : 0;
  const int s = out.coveredTexels <= budget ? 1 : blockSideFor(rsm, views, side, budget);
  out.blockSide = s;
  std::uint64_t block = 0;
  for (int view = 0; view < views; ++view)
    for (int by = 0; by < side; by += s)
      for (int bx = 0; bx < side; bx += s, ++block) {
        // Pass 1: the block's total weight; pass 2: the texel where the draw lands.
        const auto texel = [&](int x, int y) {
          return std::size_t(x) + std::size_t(side) * (std::size_t(y) + std::size_t(side) * view);
        };
        double total = 0.0;
        for (int y = by; y < std::min(by + s, side); ++y)
          for (int x = bx; x < std::min(bx + s, side); ++x)
            if (rsm.flux->texels[texel(x, y)].w > 0.0f) total += fluxWeight(rsm.flux->texels[texel(x, y)]);
        if (!(total > 0.0)) continue;
        SampleRandom random(seed, block, draw);
        const double target = s == 1 ? 0.0 : double(random.uniform()) * total;
        double running = 0.0;
        std::size_t chosen = texels;  // the last lit texel, should rounding leave `target` unmet
        bool found = false;
        for (int y = by; y < std::min(by + s, side) && !found; ++y)
          for (int x = bx; x < std::min(bx + s, side) && !found; ++x) {
            const glm::vec4& flux = rsm.flux->texels[texel(x, y)];
            if (!(flux.w > 0.0f) || !(fluxWeight(flux) > 0.0f)) continue;
            running += fluxWeight(flux);
            chosen = texel(x, y);
            found = running > target;
          }
        // phi_i / p_i = phi_i * total / |phi_i|: the block's flux, in the chosen texel's colour.
        const glm::vec3 flux(rsm.flux->texels[chosen]);
        const float scale = s == 1 ? 1.0f : float(total / double(fluxWeight(rsm.flux->texels[chosen])));
        out.vpls.push_back(Vpl{glm::vec3(rsm.position->texels[chosen]),
                               glm::normalize(glm::vec3(rsm.normal->texels[chosen])), flux * scale, 1});
      }
  return out;
}

}  // namespace lpvlab

#pragma once
// The RSMs' VPLs as lpvlab explain's oracles use them (docs/explain.md). Every covered RSM texel
// is a VPL (vpl.h's units: the flux its surface patch reflects), and LPV injects them all; an
// exact gather of all of them at every pixel, with a shadow ray per pair, is out of reach
// (a 256^2 RSM per view, times 5 views, times 512^2 pixels is 10^11 rays). So where there are more
// covered texels than the budget, each view's map is cut into blocks of s x s texels (s the
// smallest side that brings the blocks under the budget) and each block gives one VPL: a covered
// texel chosen with probability proportional to its flux (p_i = |phi_i| / sum_j |phi_j|, |.| the
// sum over RGB), carrying phi_i / p_i, the block's whole flux. Its expected light at any receiver
// is the block's texels' light: an unbiased estimate of the whole RSM's gather, whose noise
// two independent draws (`draw`) measure.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "framework/many_lights/vpl.h"
#include "framework/pipeline/host_readback.h"

namespace lpvlab {

struct RsmVplSubset {
  std::vector<Vpl> vpls;
  int blockSide = 1;               // s: 1 when every covered texel is a VPL (no noise)
  std::size_t coveredTexels = 0;   // the RSMs' VPLs, all of them
};

// The subset of `rsm`'s covered texels (`views` layers of side x side texels) for draw number
// `draw` (independent draws for different numbers; the same draw is the same subset). `budget`:
// at most this many VPLs (>= 1). Throws an Error for images of different sizes.
RsmVplSubset rsmVplSubset(const RsmImages& rsm, int views, int side, std::size_t budget,
                          std::uint64_t seed, std::uint64_t draw);

}  // namespace lpvlab

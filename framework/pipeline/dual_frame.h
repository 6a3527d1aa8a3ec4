#pragma once
// Derivatives through a whole frame, forward mode: after a frame (Pipeline::renderDerivatives),
// the stages from the first one with a seeded parameter on are run again on dual numbers
// (framework/math/dual.h) by the strategies' CPU kernels instantiated on Dual, so the indirect
// image comes with its exact derivatives with respect to up to kDualSlots strategy parameters
// (the fit's automatic derivatives, framework/fit/fit_problem.h).
//
// What a stage before the first seeded one made is a constant here (the frame's float results:
// the G-buffer, the light maps, the injected grid). The stages' results on dual numbers:
//   occlusion    gvBlocking (its GV with derivatives; empty: the frame's GV, constant)
//   propagation  accumulated (from `injected`)
//   rendering    indirect (added to, as in a frame)
// One cascade level, as the fit renders.

#include <string>
#include <vector>

#include "framework/math/dual.h"
#include "framework/pipeline/frame.h"

namespace lpvlab {

// An image on dual numbers: RGB and the cascade weight per pixel, as HostImage's texels
// (bottom row first).
struct DualTexelImage {
  int width = 0, height = 0;
  std::vector<glm::vec<4, Dual>> texels;
};

struct DualFrame {
  Frame& frame;                    // the frame just rendered, in float
  std::vector<std::string> seeds;  // slot j's parameter, "<table>.<name>" (fit_spec.h's keys)
  std::string table;               // the experiment table of the strategy being called

  std::vector<Dual> injected;      // the injected grid (grid.glsl layout), constants
  std::vector<Dual> gvBlocking;    // the GV (geometry_volume.h layout) with derivatives, or empty
  std::vector<Dual> accumulated;   // after propagation: what rendering reads
  DualTexelImage* indirect = nullptr;  // RGB + cascade weight per pixel, bottom row first

  // The strategy's parameter `name` at `value`: derivative 1 in its slot if "<table>.<name>" is
  // seeded, else a constant.
  Dual parameter(const std::string& name, double value) const {
    for (std::size_t j = 0; j < seeds.size(); ++j)
      if (seeds[j] == table + "." + name) return Dual::parameter(value, int(j));
    return Dual(value);
  }
};

// Values as dual numbers without derivatives.
template <class T>
std::vector<Dual> constantDuals(const std::vector<T>& values) {
  return std::vector<Dual>(values.begin(), values.end());
}

}  // namespace lpvlab

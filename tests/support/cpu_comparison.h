#pragma once
// Comparing a propagation CPU kernel's grids with its GLSL kernel's, for the CPU kernels' tests
// (standard_cpu_test, standard_cpu_gv_test, directed_cpu_test, tetrahedral_cpu_test).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "grid_test_support.h"
#include "propagation_rig.h"

namespace lpvlab::test {

// A CPU kernel's current and accumulated grids after some iterations.
struct Propagated {
  std::vector<double> current, accumulated;
};

// max |a - b| over b's largest value; either of any scalar type (float, double).
template <class A, class B>
double maxRelativeDifference(const A& a, const B& b) {
  double largest = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, std::abs(double(a[i]) - double(b[i])));
    scale = std::max(scale, std::abs(double(b[i])));
  }
  return largest / scale;
}

// Two frames of the same strategy on GL and on the CPU backend, each rig given the frame's
// inputs by `load(rig, frame)`: the CPU's current grid is GL's within 2e-5 in both (so a CPU
// strategy that keeps state from frame to frame finds it again when its inputs change), and the
// second frame's differs from the first's by more than `changed` (so the inputs did change it).
inline void expectCpuFollowsGlAcrossFrames(PropagationRig& gl, PropagationRig& cpu,
                                           const std::function<void(PropagationRig&, int)>& load,
                                           double changed, const std::string& what) {
  Grid previous;
  for (int frame = 0; frame < 2; ++frame) {
    for (PropagationRig* rig : {&gl, &cpu}) {
      load(*rig, frame);
      rig->propagate();
    }
    const Grid glCurrent = gl.current(), cpuCurrent = cpu.current();
    EXPECT_LT(maxRelativeDifference(cpuCurrent, glCurrent), 2e-5) << "frame " << frame;
    if (frame == 1) {
      EXPECT_GT(maxRelativeDifference(previous, glCurrent), changed)
          << "the second frame's " << what << " changed the light";
    }
    previous = cpuCurrent;
  }
}

}  // namespace lpvlab::test

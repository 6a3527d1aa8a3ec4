#pragma once
// How a propagation step on the CPU adds to the running sum of every step (the accumulated grid,
// or the tetrahedral lattice's sum), shared by the standard and tetrahedral CPU kernels.

namespace lpvlab {

// What a step adds to the sum: its result (Target); nothing, leaving it to the next step
// (Deferred); or the previous step's deferred result, which is this one's source, and its own
// (SourceAndTarget). Pairing steps (Deferred, SourceAndTarget, ..., Target for an odd last one)
// reads and writes the sum every other step, the largest stream of the kernels' memory traffic,
// with the same sum up to float rounding.
enum class StepAccumulation { Target, Deferred, SourceAndTarget };

// How step `step` of `steps` accumulates when steps are paired.
inline StepAccumulation pairedAccumulation(int step, int steps) {
  if (step % 2 == 1) return StepAccumulation::SourceAndTarget;
  return step + 1 == steps ? StepAccumulation::Target : StepAccumulation::Deferred;
}

}  // namespace lpvlab

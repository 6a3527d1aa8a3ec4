#pragma once
// How every CPU-kernel benchmark reports: wall time (the kernels use every core), in
// milliseconds, the median of 5 repetitions (after each benchmark's own untimed warm-up).

#include <benchmark/benchmark.h>

namespace lpvlab {

inline benchmark::internal::Benchmark* medianOf5(benchmark::internal::Benchmark* b) {
  return b->UseRealTime()->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
}

}  // namespace lpvlab

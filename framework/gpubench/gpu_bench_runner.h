#pragma once
// Times one case on one shape: `warmup` untimed runs, then `repeats` timed ones, each after a
// reset() that is not timed. A run is timed with GL timestamp queries around its GL commands
// (framework/gl/gpu_timer.h): the GPU's time, not the CPU's. The checksum is of the last run's
// outputs (every run starts from the same inputs, so any run's would do).

#include <string>
#include <vector>

#include "framework/core/stats.h"
#include "framework/gpubench/gpu_bench_case.h"

namespace lpvlab {

struct GpuBenchResult {
  std::string name;          // the registered case
  GpuBenchShape shape;
  Summary ms;                // of the timed runs (median, quartiles, min, max)
  GpuBenchWork work;
  double checksum = 0.0;

  double unitsPerSecond() const { return ms.median > 0.0 ? work.units / (1e-3 * ms.median) : 0.0; }
  // The work model's bytes and multiply-adds over the median time.
  double bytesPerSecond() const { return unitsPerSecond() * work.bytesPerUnit; }
  double multiplyAddsPerSecond() const { return unitsPerSecond() * work.multiplyAddsPerUnit; }
};

GpuBenchResult runGpuBench(const std::string& name, const GpuBenchEntry& entry,
                           ShaderCompiler& shaders, const GpuBenchShape& shape, int warmup,
                           int repeats);

}  // namespace lpvlab

#include "framework/gpubench/gpu_bench_runner.h"

#include <memory>
#include <vector>

#include "framework/core/error.h"
#include "framework/core/stats.h"
#include "framework/gl/gpu_timer.h"
#include "framework/gl/resources.h"

namespace lpvlab {

GpuBenchResult runGpuBench(const std::string& name, const GpuBenchEntry& entry,
                           ShaderCompiler& shaders, const GpuBenchShape& shape, int warmup,
                           int repeats) {
  if (repeats < 1) throw Error("lpvlab-gpubench: repeats must be at least 1");
  std::unique_ptr<GpuBenchCase> bench = entry.make();
  bench->prepare(shaders, shape);
  GpuBenchResult result{.name = name, .shape = shape, .work = bench->work()};
  GpuTimer timer;
  std::vector<double> samples;
  for (int i = 0; i < warmup + repeats; ++i) {
    bench->reset();
    timer.begin("run");
    bench->run();
    timer.end();
    const double ms = timer.collectMs()["run"];
    if (i >= warmup) samples.push_back(ms);
  }
  checkGl("lpvlab-gpubench " + name);
  result.ms = summarize(samples);
  result.checksum = bench->checksum();
  return result;
}

}  // namespace lpvlab

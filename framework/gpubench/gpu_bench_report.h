#pragma once
// lpvlab-gpubench's results as a table (stdout) and as JSON (--json): per case and shape the
// median time and its quartiles, the throughput in the case's units per second, the work model's
// bytes and multiply-adds per unit with the rates they imply, and the checksum of the outputs.

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/gpubench/gpu_bench_runner.h"

namespace lpvlab {

// Where and how the results were timed.
struct GpuBenchMachine {
  std::string glBackend;    // "egl" or "osmesa"
  std::string glRenderer;   // GL_RENDERER
  std::string glVersion;    // GL_VERSION
  int warmup = 0;
  int repeats = 0;
};

void printGpuBenchHeader(std::ostream& out, const GpuBenchMachine& machine);
void printGpuBenchRow(std::ostream& out, const GpuBenchResult& result);
nlohmann::json gpuBenchJson(const GpuBenchMachine& machine,
                            const std::vector<GpuBenchResult>& results);

}  // namespace lpvlab

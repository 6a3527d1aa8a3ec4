#include "framework/gpubench/gpu_bench_case.h"

#include "framework/core/error.h"

namespace lpvlab {

std::map<std::string, GpuBenchEntry>& gpuBenchCases() {
  static std::map<std::string, GpuBenchEntry> cases;
  return cases;
}

const std::vector<float>& benchInput(const GpuBenchInputs& inputs, const std::string& name) {
  for (const auto& [n, values] : inputs)
    if (n == name) return values;
  throw Error("lpvlab-gpubench: no input '" + name + "'");
}

bool registerGpuBenchCase(const std::string& name, GpuBenchEntry entry) {
  if (!gpuBenchCases().emplace(name, std::move(entry)).second)
    throw Error("lpvlab-gpubench: the case '" + name + "' is registered twice");
  return true;
}

}  // namespace lpvlab

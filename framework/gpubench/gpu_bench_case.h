#pragma once
// What lpvlab-gpubench times (docs/gpu.md#gpubench): cases, each one GL kernel configuration of a
// strategy run alone on deterministic inputs. A variant registers its cases beside its strategy
// (variants/<family>/<name>_gpubench.cpp) with LPVLAB_REGISTER_GPU_BENCH, and runs its kernels
// through the same launcher its strategy does (e.g. variants/propagation/standard_gl.h), so the
// benchmark times what a frame runs. The benchmark knows no case by name.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "framework/gl/shader_compiler.h"

namespace lpvlab {

// What a case runs on: the grid's resolution and SH order (1-3), iterations (for iterated
// kernels), and the image (for per-pixel kernels).
struct GpuBenchShape {
  glm::ivec3 resolution{32};
  int shOrder = 1;
  int iterations = 32;
  glm::ivec2 image{1024, 1024};
};

// A case's work per run: `units` of `unit` ("cell-iteration", "pixel"), each with the work
// model's multiply-adds and bytes (the strategy's own GL work report).
struct GpuBenchWork {
  std::string unit;
  double units = 0.0;
  double multiplyAddsPerUnit = 0.0;
  double bytesPerUnit = 0.0;
};

// A named input array as reset() uploads it: a test gives a CPU kernel the same.
using GpuBenchInputs = std::vector<std::pair<std::string, std::vector<float>>>;

// The input named `name`; an Error when there is none.
const std::vector<float>& benchInput(const GpuBenchInputs& inputs, const std::string& name);

class GpuBenchCase {
public:
  virtual ~GpuBenchCase() = default;
  // Compiles its kernels and allocates its buffers for `shape`.
  virtual void prepare(ShaderCompiler& shaders, const GpuBenchShape& shape) = 0;
  // Uploads its inputs (gpu_bench_inputs.h: the same on every machine), before each timed run.
  virtual void reset() = 0;
  // The timed work: GL commands only, nothing read back.
  virtual void run() = 0;
  // Of its outputs after run(): benchChecksum (gpu_bench_inputs.h) summed over them.
  virtual double checksum() const = 0;
  virtual GpuBenchWork work() const = 0;
  virtual const GpuBenchInputs& inputs() const = 0;
};

struct GpuBenchEntry {
  std::string description;  // what the case runs
  std::string settings;     // the experiment keys that run the same kernels in lpvlab
  std::function<std::unique_ptr<GpuBenchCase>()> make;
};

// The registered cases by name (in name order).
std::map<std::string, GpuBenchEntry>& gpuBenchCases();
bool registerGpuBenchCase(const std::string& name, GpuBenchEntry entry);

}  // namespace lpvlab

#define LPVLAB_GPU_BENCH_CONCAT_INNER(a, b) a##b
#define LPVLAB_GPU_BENCH_CONCAT(a, b) LPVLAB_GPU_BENCH_CONCAT_INNER(a, b)
// LPVLAB_REGISTER_GPU_BENCH("name", "description", "settings", expression making the case)
#define LPVLAB_REGISTER_GPU_BENCH(name, description, settings, ...)                          \
  static const bool LPVLAB_GPU_BENCH_CONCAT(lpvlabGpuBench_, __LINE__) =                    \
      ::lpvlab::registerGpuBenchCase(                                                         \
          name, {description, settings,                                                       \
                 []() -> std::unique_ptr<::lpvlab::GpuBenchCase> { return __VA_ARGS__; }})

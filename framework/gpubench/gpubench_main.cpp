// lpvlab-gpubench: the LPV strategies' GL kernels timed alone on the GPU (docs/gpu.md#gpubench).
// A small executable (GL through EGL or OSMesa, both opened at run time; glslang linked
// statically) that one transfer takes to a GPU machine with its shaders
// (scripts/gpu-kernels.sh). It runs every registered case, or those --cases names, on each grid
// and SH order, and prints a row per run as it finishes, with the progress and an estimate of the
// time left on stderr.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "framework/core/atomic_file.h"
#include "framework/core/error.h"
#include "framework/core/install_layout.h"
#include "framework/gl/context.h"
#include "framework/gl/shader_compiler.h"
#include "framework/gpubench/gpu_bench_case.h"
#include "framework/gpubench/gpu_bench_report.h"
#include "framework/gpubench/gpu_bench_runner.h"

namespace lpvlab {
namespace {

struct Options {
  std::vector<int> grids{16, 32, 64, 128};
  std::vector<int> orders{1, 2, 3};
  int iterations = 32;
  int image = 1024;
  int warmup = 1;
  int repeats = 5;
  std::vector<std::string> cases;  // empty: all
  std::string backend = "auto";
  std::string json;
  std::string spirv;  // empty: spirvDirectory()'s search
  bool list = false;
};

// Where the SPIR-V is (lpvlab-compile-spirv's output): --spirv, else LPVLAB_SPIRV_DIR, else
// <bin>/../share/lpvlab/spirv (an installed prefix, the transfer of scripts/gpu-kernels.sh), else
// <bin>/spirv (a build tree).
std::filesystem::path spirvDirectory(const std::string& option) {
  if (!option.empty()) return option;
  if (const char* env = std::getenv("LPVLAB_SPIRV_DIR"); env && *env) return env;
  const std::filesystem::path bin = executablePath().parent_path();
  const std::filesystem::path installed = bin / ".." / "share" / "lpvlab" / "spirv";
  return std::filesystem::is_directory(installed) ? installed : bin / "spirv";
}

void checkOptions(const Options& o) {
  for (int g : o.grids)
    if (g < 1 || g > 512) throw Error("--grids: " + std::to_string(g) + " is not in 1..512");
  for (int order : o.orders)
    if (order < 1 || order > 3) throw Error("--orders: " + std::to_string(order) + " is not in 1..3");
  for (const std::string& name : o.cases)
    if (!gpuBenchCases().contains(name)) {
      std::string known;
      for (const auto& [n, entry] : gpuBenchCases()) known += (known.empty() ? "" : ", ") + n;
      throw Error("--cases: unknown case '" + name + "' (the cases: " + known + ")");
    }
}

void listCases() {
  for (const auto& [name, entry] : gpuBenchCases())
    std::cout << name << "\n    " << entry.description << "\n    in lpvlab: " << entry.settings
              << "\n";
}

// Seconds since `start`, and the estimated seconds left after `done` of `total` runs.
void progress(int done, int total, std::chrono::steady_clock::time_point start) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double left = done > 0 ? elapsed / done * (total - done) : 0.0;
  std::fprintf(stderr, "[%d/%d] %.0f s elapsed, about %.0f s left\n", done, total, elapsed, left);
}

int run(const Options& o) {
  std::vector<std::string> names = o.cases;
  if (names.empty())
    for (const auto& [name, entry] : gpuBenchCases()) names.push_back(name);
  std::unique_ptr<GlContext> context = GlContext::create(o.backend);
  ShaderCompiler shaders = ShaderCompiler::precompiled(spirvDirectory(o.spirv));
  const GpuBenchMachine machine{context->backend(), context->renderer(), context->version(),
                                o.warmup, o.repeats};
  printGpuBenchHeader(std::cout, machine);
  std::vector<GpuBenchResult> results;
  const int total = int(names.size() * o.grids.size() * o.orders.size());
  const auto start = std::chrono::steady_clock::now();
  for (const std::string& name : names)
    for (int order : o.orders)
      for (int grid : o.grids) {
        const GpuBenchShape shape{glm::ivec3(grid), order, o.iterations, glm::ivec2(o.image)};
        results.push_back(
            runGpuBench(name, gpuBenchCases().at(name), shaders, shape, o.warmup, o.repeats));
        printGpuBenchRow(std::cout, results.back());
        progress(int(results.size()), total, start);
      }
  if (!o.json.empty()) writeTextAtomically(o.json, gpuBenchJson(machine, results).dump(2) + "\n");
  return 0;
}

}  // namespace
}  // namespace lpvlab

int main(int argc, char** argv) {
  lpvlab::Options o;
  CLI::App app{"lpvlab-gpubench: the LPV strategies' GL kernels timed alone (docs/gpu.md)"};
  app.add_option("--grids", o.grids, "grid sizes n (n^3 cells)")->delimiter(',');
  app.add_option("--orders", o.orders, "SH orders (1-3)")->delimiter(',');
  app.add_option("--iterations", o.iterations, "propagation iterations per run")
      ->check(CLI::Range(1, 4096));
  app.add_option("--image", o.image, "image side in pixels, for per-pixel kernels")
      ->check(CLI::Range(1, 16384));
  app.add_option("--warmup", o.warmup, "untimed runs first")->check(CLI::Range(0, 100));
  app.add_option("--repeats", o.repeats, "timed runs (the median is reported)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--cases", o.cases, "cases to run (default: all; --list names them)")
      ->delimiter(',');
  app.add_option("--backend", o.backend, "GL context: auto, egl or osmesa")
      ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
  app.add_option("--json", o.json, "also write the results as JSON to this file");
  app.add_option("--spirv", o.spirv, "the folder of its SPIR-V (default: beside the executable)");
  app.add_flag("--list", o.list, "list the cases and exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "lpvlab-gpubench: error: " << e.what() << "\n";
    return 2;
  }
  try {
    lpvlab::checkOptions(o);
  } catch (const std::exception& e) {
    std::cerr << "lpvlab-gpubench: error: " << e.what() << "\n";
    return 2;
  }
  try {
    if (o.list) {
      lpvlab::listCases();
      return 0;
    }
    return lpvlab::run(o);
  } catch (const std::exception& e) {
    std::cerr << "lpvlab-gpubench: error: " << e.what() << "\n";
    return 1;
  }
}

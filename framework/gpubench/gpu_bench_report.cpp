#include "framework/gpubench/gpu_bench_report.h"

#include <cstdio>

#include "framework/gpubench/gpu_bench_case.h"

namespace lpvlab {
namespace {

std::string gridText(const glm::ivec3& r) {
  return r.x == r.y && r.y == r.z ? std::to_string(r.x) + "^3"
                                   : std::to_string(r.x) + "x" + std::to_string(r.y) + "x" +
                                         std::to_string(r.z);
}

}  // namespace

void printGpuBenchHeader(std::ostream& out, const GpuBenchMachine& m) {
  out << "lpvlab-gpubench " << LPVLAB_VERSION << " on " << m.glRenderer << " (" << m.glVersion
      << ", " << m.glBackend << ")\n"
      << "times: GL timestamp queries around each run's dispatches, median of " << m.repeats
      << " runs after " << m.warmup << " warm-up, inputs uploaded before each run (not timed)\n"
      << "work: the strategy's GL work model per unit; GB/s and Gmadd/s are those counts over the "
         "median time\n";
  char line[256];
  std::snprintf(line, sizeof(line), "%-34s %8s %2s %5s %10s %9s %-15s %10s %7s %7s %8s %8s  %s\n",
                "case", "grid", "L", "iter", "median ms", "IQR ms", "unit", "units/s",
                "B/unit", "madd/u", "GB/s", "Gmadd/s", "checksum");
  out << line;
}

void printGpuBenchRow(std::ostream& out, const GpuBenchResult& r) {
  char line[320];
  std::snprintf(line, sizeof(line),
                "%-34s %8s %2d %5d %10.3f %9.3f %-15s %10.3e %7.0f %7.0f %8.1f %8.1f  %.9e\n",
                r.name.c_str(), gridText(r.shape.resolution).c_str(), r.shape.shOrder,
                r.shape.iterations, r.ms.median, r.ms.q3 - r.ms.q1, r.work.unit.c_str(),
                r.unitsPerSecond(), r.work.bytesPerUnit, r.work.multiplyAddsPerUnit, 1e-9 * r.bytesPerSecond(),
                1e-9 * r.multiplyAddsPerSecond(), r.checksum);
  out << line << std::flush;
}

nlohmann::json gpuBenchJson(const GpuBenchMachine& m, const std::vector<GpuBenchResult>& results) {
  nlohmann::json rows = nlohmann::json::array();
  for (const GpuBenchResult& r : results) {
    const GpuBenchEntry& entry = gpuBenchCases().at(r.name);
    rows.push_back({{"case", r.name},
                    {"description", entry.description},
                    {"settings", entry.settings},
                    {"grid", {r.shape.resolution.x, r.shape.resolution.y, r.shape.resolution.z}},
                    {"sh_order", r.shape.shOrder},
                    {"iterations", r.shape.iterations},
                    {"image", {r.shape.image.x, r.shape.image.y}},
                    {"ms", r.ms.toJson()},
                    {"unit", r.work.unit},
                    {"units", r.work.units},
                    {"units_per_s", r.unitsPerSecond()},
                    {"bytes_per_unit", r.work.bytesPerUnit},
                    {"multiply_adds_per_unit", r.work.multiplyAddsPerUnit},
                    {"bytes_per_s", r.bytesPerSecond()},
                    {"multiply_adds_per_s", r.multiplyAddsPerSecond()},
                    {"checksum", r.checksum}});
  }
  return {{"tool", "lpvlab-gpubench"},
          {"version", LPVLAB_VERSION},
          {"gl", {{"backend", m.glBackend}, {"renderer", m.glRenderer}, {"version", m.glVersion}}},
          {"timing",
           {{"clock", "gl_timer_query"},
            {"how", "GL timestamp queries around each run's dispatches; inputs uploaded before "
                    "each run, not timed"},
            {"warmup", m.warmup},
            {"repeats", m.repeats}}},
          {"results", rows}};
}

}  // namespace lpvlab

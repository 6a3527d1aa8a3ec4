// `lpvlab bench`: per-stage times (medians after warm-up, each stage by its clock: GL timer
// queries, or the wall clock for a stage on the CPU backend) and propagation throughput
// (cell-iterations per second) for each grid resolution and iteration count. A benchmark prints
// figures; it asserts nothing.

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "framework/cli/commands.h"
#include "framework/core/atomic_file.h"
#include "framework/io/provenance.h"
#include "framework/experiment/experiment_renderer.h"
#include "framework/experiment/timing.h"
#include "framework/gl/context.h"

namespace lpvlab::cli {

int benchCommand(const Options& options) {
  std::unique_ptr<GlContext> context;
  ShaderCompiler shaders;
  std::ostringstream csv;
  csv << "grid,cells,iterations,stage,clock,median_ms,q1_ms,q3_ms,wall_median_ms\n";
  bool header = false;
  for (int grid : options.gridSizes) {
    for (int iterations : options.iterationCounts) {
      std::vector<std::string> overrides = options.overrides;
      overrides.push_back("grid.resolution=" + std::to_string(grid));
      overrides.push_back("grid.margin=0");
      overrides.push_back("propagation.iterations=" + std::to_string(iterations));
      Experiment e = loadExperiment(options.experiment, overrides);
      const std::vector<std::string> stages = e.method->stageNames();
      if (std::find(stages.begin(), stages.end(), "propagation") == stages.end())
        throw Error((options.experiment.empty() ? std::string("the built-in default")
                                                 : options.experiment) +
                    ": indirect.method = \"" + e.method->name() +
                    "\" has no propagation stage: lpvlab bench measures propagation over grid "
                    "sizes and iterations; time another method with lpvlab run or lpvlab sweep");
      if (!context) {
        context = GlContext::create(e.glBackend);
        std::cout << "lpvlab bench: " << e.name << " on " << context->renderer() << ", "
                  << e.warmupFrames << " warm-up + " << e.repeats << " repeats, medians (ms)\n";
      }
      ExperimentRenderer renderer(e, e.animation.frameTime(0), shaders);
      Pipeline& pipeline = renderer.pipeline();
      const TimingReport report = measureFrames(pipeline, e.warmupFrames, e.repeats);
      // Cell-iterations as the propagation's work report counts them (every cascade level's).
      double cellIterations = 0.0;
      for (const nlohmann::json& work : pipeline.workReport().at("propagation"))
        if (work.value("unit", "") == "cell-iteration") cellIterations += work.at("units").get<double>();
      const long long cells = iterations > 0 ? std::llround(cellIterations / iterations) : 0;
      if (!header) {
        std::cout << computeLine(pipeline.computeReport()) << "\n"
                  << clocksLine(report.clock, context->renderer(), hostInfo()["cpu"].get<std::string>())
                  << "\n";
        std::cout << std::setw(12) << "grid" << std::setw(6) << "iter";
        for (const auto& [stage, s] : report.stageMs) std::cout << std::setw(12) << stage;
        std::cout << std::setw(16) << "cell-it/s\n";
        header = true;
      }
      const glm::ivec3 r = e.settings.grid.resolution;
      std::cout << std::setw(12) << (std::to_string(r.x) + "x" + std::to_string(r.y) + "x" + std::to_string(r.z))
                << std::setw(6) << iterations << std::fixed << std::setprecision(3);
      for (const auto& [stage, s] : report.stageMs) {
        std::cout << std::setw(12) << s.median;
        csv << grid << "," << cells << "," << iterations << "," << stage << ","
            << report.clock.at(stage) << "," << s.median << ","
            << s.q1 << "," << s.q3 << "," << report.wallMs.at(stage).median << "\n";
      }
      const double propagationS = report.stageMs.at("propagation").median * 1e-3;
      std::cout << std::setw(15) << std::scientific << std::setprecision(3)
                << (propagationS > 0 ? cellIterations / propagationS : 0.0) << "\n"
                << std::flush;
    }
  }
  if (!options.csv.empty()) writeTextAtomically(options.csv, csv.str());
  return 0;
}

}  // namespace lpvlab::cli

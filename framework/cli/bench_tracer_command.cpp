// `lpvlab bench --tracer`: throughput of the reference path tracer on an experiment's scene and
// camera at its output size, for each Embree instruction set and query width asked for (default:
// the experiment's `reference.isa` and `reference.packet_width`): one warm-up pass, then
// `timing.repeats` timed passes of `--spp` samples per pixel; medians and quartiles of paths/s and
// rays/s. Prints figures only (and writes them with --csv).

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <thread>

#include "framework/cli/commands.h"
#include "framework/core/available_cores.h"
#include "framework/core/cpu_features.h"
#include "framework/core/error.h"
#include "framework/core/stats.h"
#include "framework/experiment/experiment.h"
#include "framework/core/atomic_file.h"

namespace lpvlab::cli {

namespace {

struct TracerFigures {
  std::string isa;
  int width;
  Summary paths, rays;
};

TracerFigures measure(const Experiment& e, const RayEngineSettings& engine, int samples) {
  TracerSettings settings = e.reference.tracer;
  settings.engine = engine;
  const PathTracer tracer(e.scene, e.camera, e.reference.width, e.reference.height, settings);
  Accumulator acc(e.reference.width, e.reference.height);
  tracer.render(acc, 1, e.reference.threads);  // warm-up: page in the scene, spin up threads
  std::vector<double> pathsPerSecond, raysPerSecond;
  for (int i = 0; i < e.repeats; ++i) {
    std::int64_t rays = 0;
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t paths = tracer.render(acc, samples, e.reference.threads, &rays);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    pathsPerSecond.push_back(double(paths) / s);
    raysPerSecond.push_back(double(rays) / s);
  }
  return {tracer.isa(), tracer.packetWidth(), summarize(pathsPerSecond), summarize(raysPerSecond)};
}

}  // namespace

int benchTracerCommand(const Options& options) {
  Experiment e = loadExperiment(options.experiment, options.overrides);
  std::vector<std::string> isas = options.tracerIsas;
  if (isas.empty()) isas = {e.reference.tracer.engine.isa};
  if (isas.size() == 1 && isas[0] == "all") isas = supportedInstructionSets();
  std::vector<int> widths = options.tracerWidths;
  if (widths.empty()) widths = {e.reference.tracer.engine.packetWidth};
  // Every value is checked before anything is measured or printed.
  for (const std::string& isa : isas)
    if (const std::string problem = instructionSetProblem(isa); !problem.empty())
      throw Error("bench --isa: " + problem + (isa == "all" ? " (all goes alone)" : ", or all"));
  for (int width : widths)
    if (const std::string problem = packetWidthProblem(width); !problem.empty())
      throw Error("bench --packet-width: " + problem);

  const int threads = e.reference.threads > 0 ? e.reference.threads : availableCores();
  std::cout << "lpvlab bench --tracer: " << e.name << " (" << e.scene.triangleCount() << " triangles), "
            << e.reference.width << "x" << e.reference.height << ", " << options.tracerSamples
            << " spp per pass, 1 warm-up + " << e.repeats << " passes, " << threads << " threads\n"
            << "isa      width  paths/s median (q1-q3)            rays/s median (q1-q3)             rays/path\n";
  std::ostringstream csv;
  csv << "scene,isa,packet_width,paths_per_s_median,paths_per_s_q1,paths_per_s_q3,"
         "rays_per_s_median,rays_per_s_q1,rays_per_s_q3\n";
  for (const std::string& isa : isas)
    for (int width : widths) {
      const TracerFigures f = measure(e, {isa, width}, options.tracerSamples);
      std::cout << std::left << std::setw(9) << f.isa << std::setw(7) << f.width << std::right
                << std::scientific << std::setprecision(3) << f.paths.median << " (" << f.paths.q1
                << "-" << f.paths.q3 << ")  " << f.rays.median << " (" << f.rays.q1 << "-"
                << f.rays.q3 << ")  " << std::fixed << std::setprecision(2)
                << f.rays.median / f.paths.median << "\n"
                << std::flush;
      csv << e.name << "," << f.isa << "," << f.width << "," << f.paths.median << "," << f.paths.q1
          << "," << f.paths.q3 << "," << f.rays.median << "," << f.rays.q1 << "," << f.rays.q3 << "\n";
    }
  if (!options.csv.empty()) writeTextAtomically(options.csv, csv.str());
  return 0;
}

}  // namespace lpvlab::cli

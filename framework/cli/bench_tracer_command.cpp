// `lpvlab bench --tracer`: throughput of the reference path tracer on an experiment's scene and
// camera at its output size: one warm-up pass, then `timing.repeats` timed passes of
// `--spp` samples per pixel; medians and quartiles of paths/s and rays/s. Prints figures only.

#include <chrono>
#include <iomanip>
#include <iostream>
#include <thread>

#include "framework/cli/commands.h"
#include "framework/core/stats.h"
#include "framework/experiment/experiment.h"

namespace lpvlab::cli {

int benchTracerCommand(const Options& options) {
  Experiment e = loadExperiment(options.experiment, options.overrides);
  const PathTracer tracer(e.scene, e.camera, e.reference.width, e.reference.height, e.reference.tracer);
  const int threads = e.reference.threads > 0 ? e.reference.threads : int(std::thread::hardware_concurrency());
  Accumulator acc(e.reference.width, e.reference.height);
  tracer.render(acc, 1, e.reference.threads);  // warm-up: page in the scene, spin up threads
  std::vector<double> pathsPerSecond, raysPerSecond;
  for (int i = 0; i < e.repeats; ++i) {
    std::int64_t rays = 0;
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t paths = tracer.render(acc, options.tracerSamples, e.reference.threads, &rays);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    pathsPerSecond.push_back(double(paths) / s);
    raysPerSecond.push_back(double(rays) / s);
  }
  const Summary paths = summarize(pathsPerSecond), rays = summarize(raysPerSecond);
  std::cout << "lpvlab bench --tracer: " << e.name << " (" << e.scene.triangleCount() << " triangles), "
            << e.reference.width << "x" << e.reference.height << ", " << options.tracerSamples
            << " spp per pass, 1 warm-up + " << e.repeats << " passes, " << threads << " threads\n"
            << std::scientific << std::setprecision(3)
            << "paths/s  median " << paths.median << "  (q1 " << paths.q1 << ", q3 " << paths.q3 << ")\n"
            << "rays/s   median " << rays.median << "  (q1 " << rays.q1 << ", q3 " << rays.q3 << ")\n"
            << std::fixed << std::setprecision(2) << "rays per path " << rays.median / paths.median << "\n";
  return 0;
}

}  // namespace lpvlab::cli

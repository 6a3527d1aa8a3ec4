#include <ctime>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "framework/cli/commands.h"
#include "framework/experiment/run.h"
#include "framework/io/atomic_file.h"

namespace lpvlab::cli {

namespace {

std::string defaultOutDir(const std::string& name) {
  const std::time_t now = std::time(nullptr);
  std::ostringstream s;
  s << "runs/" << name << "-" << std::put_time(std::gmtime(&now), "%Y%m%d-%H%M%S");
  return s.str();
}

}  // namespace

int runCommand(const Options& options) {
  Experiment experiment = loadExperiment(options.experiment, options.overrides);
  const std::string out = options.out.empty() ? defaultOutDir(experiment.name) : options.out;
  requireOutputDirectory(out, options.out.empty() ? "output directory" : "--out");
  const auto context = GlContext::create(experiment.glBackend);
  const Animation& animation = experiment.animation;
  std::cerr << "lpvlab: " << experiment.name << " on " << context->renderer() << " ("
            << context->backend() << "), " << experiment.warmupFrames << " warm-up + ";
  if (animation.animated())
    std::cerr << "a sequence of " << animation.frames << " frames at " << animation.fps << " fps\n";
  else
    std::cerr << experiment.repeats << " timed frames\n";
  const nlohmann::json manifest = runExperiment(experiment, *context, out);
  std::cerr << computeLine(manifest["compute"]) << "\n";
  const auto& gpu = manifest["timing"]["gpu_ms"];
  std::cout << "stage         gpu median ms  (q1-q3)\n";
  for (const auto& [stage, summary] : gpu.items())
    std::cout << std::left << std::setw(14) << stage << std::right << std::fixed
              << std::setprecision(3) << std::setw(10) << summary["median"].get<double>() << "  ("
              << summary["q1"].get<double>() << "-" << summary["q3"].get<double>() << ")\n";
  if (manifest.contains("propagation_cell_iterations_per_second"))
    std::cout << "propagation throughput: " << std::scientific << std::setprecision(3)
              << manifest["propagation_cell_iterations_per_second"].get<double>()
              << " cell-iterations/s\n";
  if (manifest.contains("indirect_method"))
    std::cout << "indirect method " << manifest["indirect_method"]["name"].get<std::string>()
              << ": " << manifest["indirect_method"]["statistics"].dump() << "\n";
  std::cout << "wrote " << out
            << (!animation.animated() ? "/{images.exr, combined.png, manifest.json}\n"
                : manifest["outputs"].contains("video") ? "/{frames/, video.mp4, manifest.json}\n"
                                                        : "/{frames/, manifest.json}\n");
  return 0;
}

}  // namespace lpvlab::cli

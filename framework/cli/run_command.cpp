#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/core/log.h"
#include "framework/core/error.h"

#include "framework/cli/commands.h"
#include "framework/experiment/experiment_renderer.h"
#include "framework/experiment/run.h"
#include "framework/core/atomic_file.h"

namespace lpvlab::cli {

namespace {

namespace fs = std::filesystem;

std::string defaultOutDir(const std::string& name) {
  const std::time_t now = std::time(nullptr);
  std::ostringstream s;
  s << "runs/" << name << "-" << std::put_time(std::gmtime(&now), "%Y%m%d-%H%M%S");
  return s.str();
}

// A directory holding a finished run (its manifest.json, written last) is not written over
// unless `force`: the new run's files would stand beside what the old one left (an error map
// without a comparison, a sequence's frames and video beside a single frame's images). With
// `force` what the old run wrote (its manifest's outputs) is removed first. A directory without
// a manifest (a sequence killed mid-way) is resumed as before.
void replaceFinishedRun(const fs::path& dir, bool force, const std::string& option) {
  const fs::path manifestPath = dir / "manifest.json";
  if (!fs::exists(manifestPath)) return;
  std::ifstream in(manifestPath);
  const nlohmann::json old = nlohmann::json::parse(in, nullptr, false);
  const std::string created =
      old.is_object() && old.contains("created_utc") && old["created_utc"].is_string()
          ? ", created " + old["created_utc"].get<std::string>()
          : "";
  if (!force)
    throw Error(option + " " + dir.string() + ": holds a finished run (manifest.json" + created +
                "); --force replaces it (removing the files it wrote first), or choose another "
                "directory");
  const nlohmann::json outputs =
      old.is_object() && old.contains("outputs") && old["outputs"].is_object() ? old["outputs"]
                                                                              : nlohmann::json::object();
  std::vector<fs::path> written = {"images.exr", "combined.png"};  // a run's, whatever it listed
  for (const char* key : {"exr", "png", "error_map", "video"})
    if (outputs.contains(key) && outputs[key].is_string()) {
      const std::string entry = outputs[key].get<std::string>();
      const fs::path name = entry.substr(0, entry.find(' '));  // "error_indirect.png (FLIP of ...)"
      if (name.has_filename() && name.filename() == name) written.push_back(name);
    }
  if (outputs.contains("grid") && outputs["grid"].is_object())  // --dump-grid's files
    for (const char* key : {"npy", "json"})
      if (outputs["grid"].contains(key) && outputs["grid"][key].is_string()) {
        const fs::path name = outputs["grid"][key].get<std::string>();
        if (name.has_filename() && name.filename() == name) written.push_back(name);
      }
  if (outputs.contains("frames")) fs::remove_all(dir / "frames");
  for (const fs::path& name : written) fs::remove(dir / name);
  fs::remove(manifestPath);
}

}  // namespace

int runCommand(const Options& options) {
  std::vector<std::string> overrides = options.overrides;
  if (options.dumpGrid) overrides.push_back("output.dump_grid=true");
  Experiment experiment = loadExperiment(options.experiment, overrides);
  const std::string out = options.out.empty() ? defaultOutDir(experiment.name) : options.out;
  requireOutputDirectory(out, options.out.empty() ? "output directory" : "--out");
  replaceFinishedRun(out, options.force, options.out.empty() ? "output directory" : "--out");
  const RunContext run = openRunContext(experiment);
  if (!run.note.empty()) log::info(run.note);
  const auto& context = run.context;
  const Animation& animation = experiment.animation;
  std::ostringstream starting;
  starting << experiment.name << " on " << context->renderer() << " (" << context->backend() << "), "
           << experiment.warmupFrames << " warm-up + ";
  if (animation.animated())
    starting << "a sequence of " << animation.frames << " frames at " << animation.fps << " fps";
  else
    starting << experiment.repeats << " timed frames";
  log::info(starting.str());
  log::debug("experiment " + (experiment.file.empty() ? std::string("(built-in default)") : experiment.file) +
             ", scene " + experiment.scene.source + ", output " + out);
  const nlohmann::json manifest = runExperiment(experiment, *context, out);
  log::info(computeLine(manifest["compute"]));
  if (log::shows(log::Level::Debug) && manifest["compute"].contains("raster"))
    log::debug("raster passes: " + manifest["compute"]["raster"].dump());
  if (manifest.contains("warnings"))  // also in the manifest, summary.csv and the report
    for (const auto& warning : manifest["warnings"]) log::warning(warning.get<std::string>());
  // Each stage's time by its own clock, named on its row: a CPU stage's is not a GPU time.
  const auto& timing = manifest["timing"];
  const std::map<std::string, std::string> clock = timing.value("clock", std::map<std::string, std::string>{});
  std::cout << clocksLine(clock, manifest["libraries"].value("gl_renderer", std::string("?")),
                          manifest["host"].value("cpu", std::string("?")))
            << "\n";
  std::cout << "stage         median ms  (q1-q3)          clock\n";
  // In the order the frame ran them, then the sums: the method's stages, the shared ones, all.
  for (const auto& entry : timing["stage_order"]) {
    const std::string stage = entry.get<std::string>();
    if (!timing["stage_ms"].contains(stage)) continue;
    const nlohmann::json& summary = timing["stage_ms"][stage];
    std::ostringstream spread;
    spread << std::fixed << std::setprecision(3) << "(" << summary["q1"].get<double>() << "-"
           << summary["q3"].get<double>() << ")";
    std::cout << std::left << std::setw(14) << stage << std::right << std::fixed
              << std::setprecision(3) << std::setw(9) << summary["median"].get<double>() << "  "
              << std::left << std::setw(22) << spread.str() << std::right << " "
              << clockLabel(clock.count(stage) ? clock.at(stage) : "") << "\n";
  }
  if (manifest.contains("propagation_cell_iterations_per_second"))
    std::cout << "propagation throughput: " << std::scientific << std::setprecision(3)
              << manifest["propagation_cell_iterations_per_second"].get<double>()
              << " cell-iterations/s\n";
  if (manifest.contains("indirect_method"))
    std::cout << "indirect method " << manifest["indirect_method"]["name"].get<std::string>()
              << ": " << manifest["indirect_method"]["statistics"].dump() << "\n";
  std::cout << "wrote " << out
            << (!animation.animated() ? (experiment.dumpGrid ? "/{images.exr, combined.png, grid.npy, grid.json, manifest.json}\n"
                                                             : "/{images.exr, combined.png, manifest.json}\n")
                : manifest["outputs"].contains("video") ? "/{frames/, video.mp4, manifest.json}\n"
                                                        : "/{frames/, manifest.json}\n");
  return 0;
}

}  // namespace lpvlab::cli

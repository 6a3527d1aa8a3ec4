// `lpvlab sweep FILE`: every configuration of FILE's [sweep] table runs as `lpvlab run` in a child
// process (its own GL context) into DIR/<id>/, from the resolved DIR/configs/<id>.toml; a
// configuration whose directory holds a manifest.json is complete and skipped, one without is
// removed and redone. `lpvlab summary DIR` rebuilds DIR/summary.csv.


#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "framework/core/log.h"
#include "framework/cli/child_runs.h"
#include "framework/cli/commands.h"
#include "framework/cli/slurm_script.h"
#include "framework/core/error.h"
#include "framework/core/install_layout.h"
#include "framework/core/parameters.h"
#include "framework/core/progress.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/experiment_file.h"
#include "framework/experiment/sweep_check.h"
#include "framework/experiment/sweep_expansion.h"
#include "framework/experiment/sweep_summary.h"
#include "framework/core/atomic_file.h"

namespace lpvlab::cli {

namespace {

namespace fs = std::filesystem;

// "FILE -s a=1 -s b=2": where a sweep came from, for the error that refuses another one.
std::string sourceText(const std::string& file, const std::vector<std::string>& overrides) {
  std::string text = file;
  for (const std::string& o : overrides) text += " -s " + o;
  return text;
}

// A sweep directory holds one sweep: resuming there is only for the sweep whose hash sweep.json
// records (another file, another -s, a changed base value or include all change it), or the
// summary would mix two sweeps' runs and a finished configuration could stand for a changed one.
// --force removes the old sweep's files (those its sweep.json names) first.
void resumeOnlyTheSameSweep(const fs::path& dir, const std::string& hash, const std::string& file,
                            const Options& options) {
  const fs::path indexPath = dir / "sweep.json";
  if (!fs::exists(indexPath)) return;
  nlohmann::json old;
  try {
    old = nlohmann::json::parse(std::ifstream(indexPath));
  } catch (const nlohmann::json::exception& e) {
    throw Error(indexPath.string() + ": not what lpvlab writes there (" + e.what() +
                "); choose another --out");
  }
  const std::string oldHash = old.is_object() ? old.value("sweep_hash", "") : "";
  if (oldHash == hash) return;
  if (!options.force) {
    std::vector<std::string> oldOverrides;
    if (old.is_object() && old.contains("overrides") && old["overrides"].is_array())
      for (const auto& o : old["overrides"])
        if (o.is_string()) oldOverrides.push_back(o.get<std::string>());
    const std::string oldFile =
        old.is_object() ? old.value("experiment_file", std::string("?")) : std::string("?");
    throw Error(std::string(options.out.empty() ? "sweep directory " : "--out ") + dir.string() +
                ": holds another sweep (" + sourceText(oldFile, oldOverrides) + ", sweep hash " +
                (oldHash.empty() ? std::string("not recorded") : oldHash) + "), not this one (" +
                sourceText(fs::absolute(file).lexically_normal().string(), options.overrides) +
                ", sweep hash " + hash + "); choose a new --out, or --force to replace it");
  }
  if (old.is_object() && old.contains("configurations") && old["configurations"].is_array())
    for (const auto& c : old["configurations"]) {
      const std::string id = c.is_object() ? c.value("id", "") : "";
      if (!id.empty() && id.find('/') == std::string::npos && id != "." && id != "..")
        fs::remove_all(dir / id);
    }
  for (const char* name : {"configs", "logs", "report"}) fs::remove_all(dir / name);
  for (const char* name : {"summary.csv", "sweep.json", "sweep.slurm", "references.slurm", "submit.sh"})
    fs::remove(dir / name);
  log::info("sweep: --force: removed the sweep that was in " + dir.string());
}

// What a summary left out, by name and why: every directory that gave no row.
void reportSkipped(const std::string& dir, const SummaryResult& summary) {
  const auto at = [&](const std::string& id) { return (fs::path(dir) / id).string(); };
  for (const std::string& id : summary.incomplete)
    log::info(at(id) + ": incomplete (no manifest.json), skipped");
  for (const auto& [id, why] : summary.dropped) log::warning(at(id) + ": no rows: " + why);
  for (const std::string& id : summary.foreign)
    log::warning(at(id) + ": not a configuration of this sweep (sweep.json), skipped");
}

// DIR/configs/<id>.toml for every configuration and DIR/sweep.json indexing them: what the
// sweep is (file, hash, overrides, swept keys), and each configuration's id, name and values.
void writeConfigurations(const fs::path& dir, const toml::table& root, const std::string& file,
                         const std::vector<SweepConfiguration>& configs, const std::string& hash,
                         const Options& options) {
  fs::create_directories(dir / "configs");
  nlohmann::json index = {{"experiment_file", fs::absolute(file).lexically_normal().string()},
                          {"sweep_hash", hash},
                          {"overrides", options.overrides},
                          {"swept_keys", sweptKeys(root, file)},
                          {"configurations", nlohmann::json::array()}};
  for (const SweepConfiguration& c : configs) {
    writeTextAtomically((dir / "configs" / (c.id + ".toml")).string(), configurationToml(root, file, c));
    nlohmann::json values = nlohmann::json::object();
    for (const auto& [k, v] : c.values) values[k] = v;
    index["configurations"].push_back(
        {{"id", c.id}, {"name", c.name}, {"overrides", c.overrides}, {"values", values}});
  }
  writeTextAtomically((dir / "sweep.json").string(), index.dump(2) + "\n");
}

// --emit slurm: the job scripts beside the configurations, and how to submit them.
void emitSlurm(const fs::path& dir, const std::string& exe, const std::string& stem,
               const std::vector<SweepConfiguration>& configs,
               const std::vector<std::string>& referenceKeys, const Options& options) {
  writeSlurmScripts(dir, exe, stem, configs, referenceKeys, options.slurm);
  const bool references = fs::exists(dir / "references.slurm");
  std::cout << "wrote " << (dir / "sweep.slurm").string() << " (" << configs.size() << " tasks"
            << (options.slurm.exclusive ? ", each on nodes of its own" : "")
            << (options.slurm.gres.empty() ? "" : ", each with " + options.slurm.gres +
                                                      " and gl.backend = \"egl\"")
            << "), "
            << (references ? (dir / "references.slurm").string() + " (renders the references first), "
                           : "")
            << (dir / "submit.sh").string() << " and " << (dir / "configs").string()
            << "/<id>.toml\n"
            << "submit: " << (dir / "submit.sh").string() << " [sbatch options]\n"
            << "then:   lpvlab summary " << dir.string() << "\n";
  if (!options.slurm.exclusive)
    std::cout << "note: tasks may share a node, which spoils timings; for a timing sweep emit "
                 "with --exclusive (as --jobs 1 does locally)\n";
}

// The sweep's options with --emit slurm's resolved: the references' resources default to the
// tasks', and with --gres every configuration runs GL through EGL (gl.backend = "egl"; another
// gl.backend given with -s is an error).
Options resolvedSlurmOptions(Options options) {
  if (options.emit != "slurm") return options;
  SlurmResources& refs = options.slurm.references;
  refs = options.slurm.tasks;
  if (options.refCpus) refs.cpusPerTask = *options.refCpus;
  if (options.refMem) refs.memory = *options.refMem;
  if (options.refTime) refs.time = *options.refTime;
  checkSlurmOptions(options.slurm);
  if (!options.slurm.gres.empty()) {
    for (const std::string& o : options.overrides) {
      std::string value = o.rfind("gl.backend=", 0) == 0 ? o.substr(11) : "egl";
      std::erase_if(value, [](char c) { return c == '"' || c == '\'' || c == ' '; });
      if (value != "egl")
        throw Error("--gres " + options.slurm.gres + ": the runs use the GPU through EGL, but -s " +
                    o + " asks for another GL backend");
    }
    options.overrides.push_back("gl.backend=\"egl\"");
  }
  return options;
}

// The sweep directory can be written and holds no single run.
void checkDirectory(const fs::path& dir, const Options& options) {
  requireOutputDirectory(dir.string(), options.out.empty() ? "sweep directory" : "--out");
  // A run's directory would get the sweep's runs and summary beside the run's own files.
  if (fs::exists(dir / "manifest.json") && !fs::exists(dir / "sweep.json"))
    throw Error((options.out.empty() ? "sweep directory " : "--out ") + dir.string() +
                ": holds a single run (manifest.json), not a sweep; choose another directory");
}

}  // namespace

int sweepCommand(const Options& given) {
  const Options options = resolvedSlurmOptions(given);
  const std::string file = options.experiment;
  const std::string stem = fs::path(file).stem().string();
  const fs::path dir = options.out.empty() ? fs::path("runs") / (stem + "-sweep") : fs::path(options.out);
  const std::string exe = executablePath().string();  // the bundle's: its wrapper script

  toml::table root = readExperimentTable(file);
  for (const std::string& o : options.overrides) applyOverride(root, o);
  const std::vector<SweepConfiguration> configs = expandSweep(root, file, options.overrides);
  // Nothing is written before every configuration loads: an unknown swept key or a bad swept
  // value is reported against the user's file and its [sweep] table.
  checkDirectory(dir, options);
  const std::vector<std::string> referenceKeys = checkConfigurations(root, file, configs);
  const std::string hash = sweepHash(root, file);
  resumeOnlyTheSameSweep(dir, hash, file, options);
  writeConfigurations(dir, root, file, configs, hash, options);
  if (options.emit == "slurm") {
    emitSlurm(dir, exe, stem, configs, referenceKeys, options);
    return 0;
  }

  std::vector<const SweepConfiguration*> pending;
  for (const SweepConfiguration& c : configs)
    if (!fs::exists(dir / c.id / "manifest.json")) pending.push_back(&c);
  log::info("sweep " + stem + ": " + std::to_string(configs.size()) + " configurations, " +
            std::to_string(configs.size() - pending.size()) + " complete, " + std::to_string(pending.size()) +
            " to run, " + std::to_string(options.jobs) + " at a time, into " + dir.string());
  std::vector<ChildRun> runs;
  for (const SweepConfiguration* c : pending)
    runs.push_back({(dir / "configs" / (c->id + ".toml")).string(), dir / c->id, c->id + " (" + c->name + ")"});
  std::vector<const SweepConfiguration*> failed;
  for (const std::size_t index : runChildren(exe, runs, options.jobs, "sweep")) failed.push_back(pending[index]);

  const SummaryResult summary = writeSweepSummary(dir.string());
  reportSkipped(dir.string(), summary);
  std::cout << "wrote " << (dir / "summary.csv").string() << ": " << summary.rows << " rows from "
            << summary.complete.size() << " runs\n";
  if (!failed.empty()) {
    std::string which;
    for (const SweepConfiguration* c : failed)
      which += "\n  " + c->id + " (" + c->name + "): " + (dir / c->id / "error.log").string();
    log::error(std::to_string(failed.size()) + " of " + std::to_string(configs.size()) +
               " configurations failed:" + which);
    return 1;
  }
  return 0;
}

int summaryCommand(const Options& options) {
  const SummaryResult summary = writeSweepSummary(options.out);
  reportSkipped(options.out, summary);
  std::cout << "wrote " << (fs::path(options.out) / "summary.csv").string() << ": " << summary.rows
            << " rows from " << summary.complete.size() << " runs\n";
  return 0;
}

}  // namespace lpvlab::cli

// `lpvlab tune FILE [--budget-ms X | --error E] [--out DIR] [--jobs N]`: the configuration of
// FILE's [tune.space] with the least error within a frame-time budget, or the fastest within an
// error, by successive halving (framework/tune/, docs/tuning.md). Every candidate is measured at
// the first rung against a cheap reference; each rung keeps the best 1 / eta for the next, better
// reference; the chosen one and the baseline (the file as it is) are then measured on the
// held-out views. Each measurement is an `lpvlab run` in a child process into
// DIR/rung<r>/<candidate>/<view>/, so an interrupted tune resumes where it stopped. Writes
// DIR/tune.json (every figure), DIR/pareto.csv and DIR/chosen.toml (the chosen overrides, for
// `include`).

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "framework/cli/analysis_program.h"
#include "framework/cli/child_runs.h"
#include "framework/cli/tune_fit.h"
#include "framework/cli/commands.h"
#include "framework/core/atomic_file.h"
#include "framework/core/error.h"
#include "framework/core/hash.h"
#include "framework/core/parameters.h"
#include "framework/core/install_layout.h"
#include "framework/core/log.h"
#include "framework/experiment/experiment_file.h"
#include "framework/experiment/sweep_check.h"
#include "framework/experiment/sweep_expansion.h"
#include "framework/experiment/work_columns.h"
#include "framework/io/provenance.h"
#include "framework/tune/successive_halving.h"
#include "framework/tune/tune_space.h"

namespace lpvlab::cli {

namespace {

namespace fs = std::filesystem;

// One measurement: a candidate on a view at a rung's reference.
struct Measurement {
  const TuneCandidate* candidate;
  const NamedView* view;
  int rung;
  fs::path directory;
  std::string config;  // its resolved experiment file
};

// The overrides every measurement of rung `rung` adds to its candidate's.
std::vector<std::string> rungOverrides(const TuneSpec& spec, int rung) {
  const bool last = rung + 1 == int(spec.rungs.size());
  return {"reference.compare=true", "reference.samples=" + std::to_string(spec.rungs[std::size_t(rung)]),
          "reference.seconds=0.0", "reference.relative_error=0.0", "timing.warmup=1",
          std::string("timing.repeats=") + (last ? "5" : "2")};
}

Measurement measurement(const TuneSpec& spec, const fs::path& dir, const TuneCandidate& c,
                        const NamedView& view, int rung, const std::string& group) {
  std::vector<std::string> overrides = c.overrides;
  for (const std::string& o : rungOverrides(spec, rung)) overrides.push_back(o);
  const SweepConfiguration configuration{c.id, c.name(), overrides, {}};
  const std::string name = group + "_" + c.id + "_" + view.name;
  const fs::path config = dir / "configs" / (name + ".toml");
  fs::create_directories(config.parent_path());
  writeTextAtomically(config.string(), configurationToml(withView(spec.base, view), spec.file, configuration));
  return {&c, &view, rung, dir / group / c.id / view.name, config.string()};
}

// Runs those not finished yet; returns how many failed.
std::size_t runMeasurements(const std::vector<Measurement>& all, int jobs, const std::string& what) {
  std::vector<ChildRun> pending;
  for (const Measurement& m : all)
    if (!fs::exists(m.directory / "manifest.json"))
      pending.push_back({m.config, m.directory, m.candidate->id + " on " + m.view->name});
  log::info(what + ": " + std::to_string(all.size()) + " runs, " + std::to_string(all.size() - pending.size()) +
            " already done");
  return pending.empty() ? 0 : runChildren(executablePath().string(), pending, jobs, what).size();
}

// time = "gpu-estimate": per finished run (by its directory) the estimate in ms of its indirect
// method's GL kernels on spec.gpu, from the work its manifest counted. The analysis package
// computes it (analysis/gpu_estimate.py), the same estimate as `lpvlab report --time
// gpu-estimate`; `words` says how it was estimated.
struct GpuEstimates {
  std::map<std::string, double> ms;
  std::string words;
};

GpuEstimates estimateGpuTimes(const TuneSpec& spec, const std::vector<Measurement>& all, const fs::path& stem) {
  std::vector<std::map<std::string, double>> rows;
  std::vector<std::string> directories;
  std::set<std::string> columns;
  for (const Measurement& m : all) {
    std::ifstream in(m.directory / "manifest.json");
    const nlohmann::json manifest = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    if (!manifest.is_object()) continue;
    std::map<std::string, double> row;
    for (const auto& [key, value] : workColumns(manifest))
      if (key.rfind("gpu_work.", 0) == 0) row[key] = value, columns.insert(key);
    const nlohmann::json::json_pointer order("/configuration/grid/sh_order");
    row["param.grid.sh_order"] = manifest.contains(order) ? manifest[order].get<double>() : 1.0;
    rows.push_back(row);
    directories.push_back(m.directory.string());
  }
  columns.insert("param.grid.sh_order");
  std::ostringstream csv;
  csv << "id";
  for (const std::string& c : columns) csv << "," << c;
  csv << "\n" << std::setprecision(17);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    csv << i;
    for (const std::string& c : columns)
      if (rows[i].count(c)) csv << "," << rows[i].at(c);
      else csv << ",";
    csv << "\n";
  }
  const fs::path csvPath = stem.string() + ".csv", jsonPath = stem.string() + ".json";
  fs::create_directories(csvPath.parent_path());
  writeTextAtomically(csvPath.string(), csv.str());
  const int status = runAnalysisProgram("gpu-estimate", {csvPath.string(), "--gpu", spec.gpu, "--out", jsonPath.string()});
  if (status != 0)
    throw Error("tune: the GPU estimate of " + csvPath.string() + " failed (exit " + std::to_string(status) +
                "; its message is above)");
  std::ifstream in(jsonPath);
  const nlohmann::json result = nlohmann::json::parse(in, nullptr, false);
  if (!result.is_object() || !result.contains("runs")) throw Error(jsonPath.string() + ": not the GPU estimate's output");
  GpuEstimates out{{}, result.value("words", "")};
  for (std::size_t i = 0; i < directories.size(); ++i)
    if (const auto& ms = result["runs"][std::to_string(i)]; ms.is_number()) out.ms[directories[i]] = ms.get<double>();
  return out;
}

// A finished run's error and median time (with time = "gpu-estimate" its estimate), or nullopt
// where it failed or lacks the figure.
std::optional<std::pair<double, double>> figures(const TuneSpec& spec, const fs::path& runDir,
                                                 const GpuEstimates& estimates) {
  std::ifstream in(runDir / "manifest.json");
  if (!in) return std::nullopt;
  const nlohmann::json m = nlohmann::json::parse(in, nullptr, false);
  const nlohmann::json::json_pointer error("/reference/comparison/" + spec.pair + "/metrics/" + spec.metric);
  if (m.is_discarded() || !m.contains(error) || !m[error].is_number()) return std::nullopt;
  if (spec.time == "gpu-estimate") {
    const auto ms = estimates.ms.find(runDir.string());
    if (ms == estimates.ms.end()) return std::nullopt;
    return std::make_pair(m[error].get<double>(), ms->second);
  }
  const nlohmann::json::json_pointer ms("/timing/stage_ms/" + spec.time + "/median");
  if (!m.contains(ms)) return std::nullopt;
  return std::make_pair(m[error].get<double>(), m[ms].get<double>());
}

// The measurements' figures: their GPU estimates first with time = "gpu-estimate" (into
// DIR/estimates/<what>.{csv,json}).
GpuEstimates estimatesOf(const TuneSpec& spec, const std::vector<Measurement>& all, const fs::path& stem) {
  return spec.time == "gpu-estimate" ? estimateGpuTimes(spec, all, stem) : GpuEstimates{};
}

// time = "gpu-estimate": the GPU is one the estimate knows, before anything runs (an estimate of
// no runs, in a directory of its own that is then removed).
void checkGpu(const TuneSpec& spec) {
  const fs::path scratch = fs::temp_directory_path() / ("lpvlab-tune-gpu-" + Hasher().text(spec.file).text(spec.gpu).hex());
  try {
    estimateGpuTimes(spec, {}, scratch / "check");
  } catch (const Error&) {
    fs::remove_all(scratch);
    throw Error(spec.file + ": key 'tune.gpu': '" + spec.gpu + "': the GPU estimate refused it (its message is above)");
  }
  fs::remove_all(scratch);
}

// Per candidate, the mean over its views; candidates with a failed view are left out (named).
std::vector<RungResult> results(const TuneSpec& spec, const std::vector<Measurement>& all,
                                const GpuEstimates& estimates) {
  std::map<std::string, std::vector<std::pair<double, double>>> byCandidate;
  std::map<std::string, bool> failed;
  for (const Measurement& m : all) {
    const auto f = figures(spec, m.directory, estimates);
    if (f) byCandidate[m.candidate->id].push_back(*f);
    else failed[m.candidate->id] = true;
  }
  std::vector<RungResult> out;
  for (const auto& [id, list] : byCandidate) {
    if (failed.count(id)) continue;
    RungResult r{id, 0.0, 0.0};
    for (const auto& [error, ms] : list) r.error += error / double(list.size()), r.ms += ms / double(list.size());
    out.push_back(r);
  }
  const std::string time = spec.time == "gpu-estimate" ? "GPU estimate" : spec.time + " time";
  for (const auto& [id, _] : failed)
    log::warning("candidate " + id + ": a run failed or has no " + spec.pair + "." + spec.metric + " or " + time +
                 " (its error.log): left out");
  return out;
}

std::string tomlOfOverrides(const TuneCandidate& c) {
  std::map<std::string, std::vector<std::string>> tables;
  for (const std::string& o : c.overrides) {
    const auto dot = o.find('.'), equals = o.find('=');
    tables[o.substr(0, dot)].push_back(o.substr(dot + 1, equals - dot - 1) + " = " + o.substr(equals + 1));
  }
  std::string out;
  for (const auto& [table, lines] : tables) {
    out += "\n[" + table + "]\n";
    for (const std::string& line : lines) out += line + "\n";
  }
  return out;
}

nlohmann::json toJson(const RungResult& r, const TuneGoal& goal) {
  return {{"id", r.id}, {"error", r.error}, {"ms", r.ms}, {"feasible", goal.feasible(r)}};
}

// The tune's identity: its file with the -s overrides ([tune] included) and the command line's
// goal. A directory resumes only the tune that started there.
std::string tuneHash(const Options& options) {
  toml::table root = readExperimentTable(options.experiment);
  for (const std::string& o : options.overrides) applyOverride(root, o);
  std::ostringstream goal;
  goal << std::setprecision(17) << options.tuneBudgetMs.value_or(-1.0) << "," << options.tuneError.value_or(-1.0);
  return Hasher().text(sweepHash(root, options.experiment)).text(goal.str()).hex();
}

void claimDirectory(const fs::path& dir, const std::string& hash, const Options& options) {
  const fs::path state = dir / "tune_state.json";
  if (fs::exists(state)) {
    std::ifstream in(state);
    const nlohmann::json old = nlohmann::json::parse(in, nullptr, false);
    const bool same = old.is_object() && old.value("hash", "") == hash;
    const bool done = fs::exists(dir / "tune.json");
    if (!same || done) {
      if (!options.force)
        throw Error((options.out.empty() ? "output directory " : "--out ") + dir.string() + ": holds " +
                    (same ? "this tune, finished (tune.json)" : "another tune (another file, -s or goal)") +
                    "; --force replaces it, or choose another directory");
      for (const char* name : {"configs", "rungs", "held_out", "estimates", "fit", "fitted"}) fs::remove_all(dir / name);
      for (const char* name : {"tune.json", "pareto.csv", "chosen.toml", "tune_state.json"}) fs::remove(dir / name);
    }
  } else if (fs::exists(dir) && !fs::is_empty(dir) && !options.force) {
    throw Error((options.out.empty() ? "output directory " : "--out ") + dir.string() +
                ": not empty and not a tune's; choose another directory");
  }
  fs::create_directories(dir);
  writeTextAtomically(state.string(), nlohmann::json{{"hash", hash}, {"file", options.experiment}}.dump(2) + "\n");
}

// Every candidate's configuration loads (on every view), before anything runs.
void checkCandidates(const TuneSpec& spec, const std::vector<TuneCandidate>& candidates) {
  std::vector<SweepConfiguration> configurations;
  for (const TuneCandidate& c : candidates) {
    std::vector<std::string> overrides = c.overrides;
    for (const std::string& o : rungOverrides(spec, 0)) overrides.push_back(o);
    configurations.push_back({c.id, c.name(), overrides, {}});
  }
  for (const NamedView& view : spec.views) checkConfigurations(withView(spec.base, view), spec.file, configurations);
}

struct RungRecord {
  int samples;
  std::vector<RungResult> results;
  std::vector<std::string> promoted;
  TuneGoal goal;  // the spec's, with budget_ms = "baseline" the baseline's time at this rung
  std::string estimateWords;  // time = "gpu-estimate": how the times were estimated
};

void printTable(const std::vector<RungResult>& results, const std::map<std::string, const TuneCandidate*>& byId,
                const TuneGoal& goal, const TuneSpec& spec) {
  std::cout << "  " << std::left << std::setw(12) << "candidate" << std::right << std::setw(12)
            << spec.metric << std::setw(18) << (spec.time + " ms") << "  configuration\n";
  std::vector<RungResult> sorted = results;
  std::stable_sort(sorted.begin(), sorted.end(), [&](const RungResult& a, const RungResult& b) { return goal.better(a, b); });
  for (const RungResult& r : sorted)
    std::cout << "  " << std::left << std::setw(12) << r.id << std::right << std::fixed << std::setprecision(4)
              << std::setw(12) << r.error << std::setprecision(3) << std::setw(18) << r.ms << "  "
              << (goal.feasible(r) ? "" : "(over the goal) ") << byId.at(r.id)->name() << "\n";
}

// The chosen configuration and the baseline on the held-out views, at the last rung's reference:
// per view {view: {chosen: error, baseline: error, ratio}}.
nlohmann::json measureHeldOut(const TuneSpec& spec, const fs::path& dir, const TuneCandidate& chosen,
                              const TuneCandidate& baseline, const Options& options) {
  nlohmann::json out = nlohmann::json::object();
  if (spec.heldOut.empty()) return out;
  const int last = int(spec.rungs.size()) - 1;
  std::vector<Measurement> all;
  for (const NamedView& view : spec.heldOut)
    for (const TuneCandidate* c : {&chosen, &baseline})
      all.push_back(measurement(spec, dir, *c, view, last, "held_out"));
  runMeasurements(all, options.jobs, "tune: held-out views");
  const GpuEstimates estimates = estimatesOf(spec, all, dir / "estimates" / "held_out");
  for (const Measurement& m : all) {
    const auto f = figures(spec, m.directory, estimates);
    nlohmann::json& entry = out[m.view->name];
    const std::string who = m.candidate == &chosen ? "chosen" : "baseline";
    entry[who] = f ? nlohmann::json{{"error", f->first}, {"ms", f->second}} : nlohmann::json(nullptr);
  }
  for (auto& [view, entry] : out.items())
    if (entry.contains("chosen") && entry.contains("baseline") && !entry["chosen"].is_null() &&
        !entry["baseline"].is_null() && entry["chosen"]["error"].get<double>() > 0.0)
      entry["baseline_over_chosen"] = entry["baseline"]["error"].get<double>() / entry["chosen"]["error"].get<double>();
  return out;
}

void writePareto(const fs::path& dir, const std::vector<RungRecord>& rungs,
                 const std::map<std::string, const TuneCandidate*>& byId) {
  std::ostringstream csv;
  csv << "rung,samples,id,error,ms,feasible,pareto,configuration\n";
  for (std::size_t r = 0; r < rungs.size(); ++r) {
    std::set<std::string> front;
    for (const RungResult& p : paretoFront(rungs[r].results)) front.insert(p.id);
    for (const RungResult& x : rungs[r].results)
      csv << r + 1 << "," << rungs[r].samples << "," << x.id << "," << std::setprecision(9) << x.error << ","
          << x.ms << "," << rungs[r].goal.feasible(x) << "," << front.count(x.id) << ",\"" << byId.at(x.id)->name() << "\"\n";
  }
  writeTextAtomically((dir / "pareto.csv").string(), csv.str());
}

// What the time is: "method time", "total time", "GPU-estimated method time on h100_sxm".
std::string timeWords(const TuneSpec& spec) {
  return spec.time == "gpu-estimate" ? "GPU-estimated method time on " + spec.gpu : spec.time + " time";
}

std::string goalWords(const TuneSpec& spec) {
  std::ostringstream budget;
  if (spec.budgetMs) budget << *spec.budgetMs;
  const std::string metric = spec.pair + "." + spec.metric;
  if (!spec.budgetMs) return "the least " + timeWords(spec) + " within " + metric + " " + std::to_string(*spec.maxError);
  return "the least " + metric + " within " +
         (spec.budgetIsBaseline ? "the baseline's " + timeWords(spec) : budget.str() + " ms of " + timeWords(spec));
}

// [tune.fit]: the chosen candidate's constants fitted (tune_fit.h), then the fitted configuration
// measured on the tuned views at the last rung as the candidates were. It replaces the chosen one
// where it is within the goal and more accurate: the fit minimises its own residual, not the
// tune's metric, so it can make the metric worse. Returns the final choice (`fitted` when it
// replaced it); records both in `result` ("chosen", "fit").
const TuneCandidate& refineByFit(const TuneSpec& spec, const fs::path& dir, const TuneCandidate& chosen,
                                 const RungResult& chosenResult, const TuneGoal& goal, const Options& options,
                                 TuneCandidate& fitted, nlohmann::json& result) {
  const int last = int(spec.rungs.size()) - 1;
  TuneFit fit = fitChosenConstants(spec, dir, chosen.overrides, rungOverrides(spec, last));
  fitted = {"fitted", fit.overrides};
  std::vector<Measurement> all;
  for (const NamedView& view : spec.views) all.push_back(measurement(spec, dir, fitted, view, last, "fitted"));
  runMeasurements(all, options.jobs, "tune: the fitted constants on the tuned views");
  const std::vector<RungResult> measured = results(spec, all, estimatesOf(spec, all, dir / "estimates" / "fitted"));
  fit.record["overrides"] = fitted.overrides;
  fit.record["before"] = toJson(chosenResult, goal);
  fit.record["after"] = measured.empty() ? nlohmann::json(nullptr) : toJson(measured.front(), goal);
  const bool adopted = !measured.empty() && goal.feasible(measured.front()) && measured.front().error < chosenResult.error;
  fit.record["adopted"] = adopted;
  result["fit"] = fit.record;
  result["candidates"]["fitted"] = fitted.overrides;
  result["chosen"] = toJson(adopted ? measured.front() : chosenResult, goal);
  result["chosen"]["from"] = chosen.id;
  std::ostringstream after;
  after << std::setprecision(4) << (measured.empty() ? 0.0 : measured.front().error);
  std::cout << "[tune.fit] " << chosen.id << " with fitted constants: " << spec.metric << " " << std::setprecision(4)
            << chosenResult.error << " -> " << (measured.empty() ? std::string("failed") : after.str())
            << (adopted ? " (adopted)\n" : " (not adopted: not more accurate within the goal)\n");
  return adopted ? fitted : chosen;
}

int writeTuneOutputs(const TuneSpec& spec, const fs::path& dir,
                     const std::map<std::string, const TuneCandidate*>& byId,
                     const std::vector<RungRecord>& rungs, const Options& options) {
  const TuneGoal& last = rungs.back().goal;
  const std::optional<RungResult> best = choose(rungs.back().results, last);
  const std::string goalText = goalWords(spec);
  nlohmann::json result = {{"file", spec.file}, {"goal", goalText}, {"metric", spec.pair + "." + spec.metric},
                           {"time", spec.time}, {"eta", spec.eta}, {"host", hostInfo()},
                           {"created_utc", utcTimestamp()}, {"lpvlab", lpvlabRevision()},
                           {"clock", "each run's own (its manifest's timing.clock): CPU wall clock or GL timer queries"}};
  if (spec.time == "gpu-estimate") {
    result["clock"] = rungs.back().estimateWords;  // "... (...; an estimate from counted work, not a measurement)"
    result["gpu"] = spec.gpu;
  }
  for (const RungRecord& r : rungs) {
    nlohmann::json rung = {{"samples", r.samples}, {"promoted", r.promoted}, {"results", nlohmann::json::array()}};
    if (r.goal.budgetMs) rung["budget_ms"] = *r.goal.budgetMs;
    for (const RungResult& x : r.results) rung["results"].push_back(toJson(x, r.goal));
    result["rungs"].push_back(rung);
  }
  for (const auto& [id, c] : byId) result["candidates"][id] = c->overrides;
  writePareto(dir, rungs, byId);
  std::cout << "\nlast rung (" << rungs.back().samples << " spp references), best first:\n";
  printTable(rungs.back().results, byId, last, spec);
  if (!best) {
    result["chosen"] = nullptr;
    writeTextAtomically((dir / "tune.json").string(), result.dump(2) + "\n");
    log::warning("no candidate meets the goal (" + goalText + "); wrote " + (dir / "tune.json").string());
    return 3;
  }
  result["chosen"] = toJson(*best, last);
  TuneCandidate fitted;
  const TuneCandidate& chosen = spec.fit ? refineByFit(spec, dir, *byId.at(best->id), *best, last, options, fitted, result)
                                         : *byId.at(best->id);
  result["chosen"]["overrides"] = chosen.overrides;
  result["held_out"] = measureHeldOut(spec, dir, chosen, *byId.at("baseline"), options);
  writeTextAtomically((dir / "chosen.toml").string(),
                      "# lpvlab tune " + spec.file + ": " + goalText + "\n# chosen " + chosen.id + ": " +
                          chosen.name() + "\n# use: include = [\"" + fs::absolute(dir / "chosen.toml").string() +
                          "\"]\n" + tomlOfOverrides(chosen));
  writeTextAtomically((dir / "tune.json").string(), result.dump(2) + "\n");
  std::cout << "chosen " << chosen.id << ": " << chosen.name() << "\n";
  for (const auto& [view, entry] : result["held_out"].items())
    if (entry.contains("baseline_over_chosen"))
      std::cout << "held out " << view << ": " << spec.metric << " " << std::setprecision(4)
                << entry["chosen"]["error"].get<double>() << " (baseline " << entry["baseline"]["error"].get<double>()
                << ", " << std::setprecision(2) << entry["baseline_over_chosen"].get<double>() << "x lower)\n";
  std::cout << "wrote " << dir.string() << "/{tune.json, pareto.csv, chosen.toml}\n";
  return 0;
}

}  // namespace

int tuneCommand(const Options& options) {
  const TuneSpec spec = readTuneSpec(options.experiment, options.overrides, options.tuneBudgetMs, options.tuneError);
  const fs::path dir = options.out.empty() ? fs::path("runs") / (fs::path(spec.file).stem().string() + "-tune")
                                           : fs::path(options.out);
  requireOutputDirectory(dir.string(), options.out.empty() ? "output directory" : "--out");
  const std::vector<TuneCandidate> candidates = drawCandidates(spec);
  checkCandidates(spec, candidates);
  if (spec.time == "gpu-estimate") checkGpu(spec);
  claimDirectory(dir, tuneHash(options), options);
  const TuneGoal goal{spec.budgetMs, spec.maxError};
  std::map<std::string, const TuneCandidate*> byId;
  for (const TuneCandidate& c : candidates) byId[c.id] = &c;

  std::vector<const TuneCandidate*> alive;
  for (const TuneCandidate& c : candidates) alive.push_back(&c);
  std::vector<RungRecord> rungs;
  for (int rung = 0; rung < int(spec.rungs.size()); ++rung) {
    std::vector<Measurement> all;
    for (const TuneCandidate* c : alive)
      for (const NamedView& view : spec.views)
        all.push_back(measurement(spec, dir, *c, view, rung, "rungs/" + std::to_string(rung)));
    const std::string what = "tune rung " + std::to_string(rung + 1) + "/" + std::to_string(spec.rungs.size()) +
                             " (" + std::to_string(spec.rungs[std::size_t(rung)]) + " spp references)";
    runMeasurements(all, options.jobs, what);
    const GpuEstimates estimates = estimatesOf(spec, all, dir / "estimates" / ("rung" + std::to_string(rung + 1)));
    RungRecord record{spec.rungs[std::size_t(rung)], results(spec, all, estimates), {}, goal, estimates.words};
    std::vector<RungResult> contenders;
    bool baselineMeasured = false;
    for (const RungResult& r : record.results)
      if (r.id != "baseline") {
        contenders.push_back(r);
      } else {
        baselineMeasured = true;
        if (spec.budgetIsBaseline) record.goal.budgetMs = r.ms;  // the baseline's time, this rung
      }
    if (contenders.empty()) throw Error("tune: every candidate's runs failed at rung " + std::to_string(rung + 1));
    if (spec.budgetIsBaseline && !baselineMeasured)
      throw Error("tune: the baseline's runs failed at rung " + std::to_string(rung + 1) +
                  ", and budget_ms = \"baseline\" is its time");
    record.promoted = rung + 1 < int(spec.rungs.size()) ? promote(contenders, record.goal, spec.eta)
                                                        : std::vector<std::string>{};
    alive.clear();
    alive.push_back(byId.at("baseline"));
    for (const std::string& id : record.promoted) alive.push_back(byId.at(id));
    rungs.push_back(std::move(record));
  }
  return writeTuneOutputs(spec, dir, byId, rungs, options);
}

}  // namespace lpvlab::cli

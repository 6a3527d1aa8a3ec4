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

#include "framework/cli/child_runs.h"
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

// A finished run's error and median time, or nullopt where it failed or lacks the figure.
std::optional<std::pair<double, double>> figures(const TuneSpec& spec, const fs::path& runDir) {
  std::ifstream in(runDir / "manifest.json");
  if (!in) return std::nullopt;
  const nlohmann::json m = nlohmann::json::parse(in, nullptr, false);
  const nlohmann::json::json_pointer error("/reference/comparison/" + spec.pair + "/metrics/" + spec.metric);
  const nlohmann::json::json_pointer ms("/timing/stage_ms/" + spec.time + "/median");
  if (m.is_discarded() || !m.contains(error) || !m.contains(ms) || !m[error].is_number()) return std::nullopt;
  return std::make_pair(m[error].get<double>(), m[ms].get<double>());
}

// Per candidate, the mean over its views; candidates with a failed view are left out (named).
std::vector<RungResult> results(const TuneSpec& spec, const std::vector<Measurement>& all) {
  std::map<std::string, std::vector<std::pair<double, double>>> byCandidate;
  std::map<std::string, bool> failed;
  for (const Measurement& m : all) {
    const auto f = figures(spec, m.directory);
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
  for (const auto& [id, _] : failed)
    log::warning("candidate " + id + ": a run failed or has no " + spec.pair + "." + spec.metric +
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
      for (const char* name : {"configs", "rungs", "held_out"}) fs::remove_all(dir / name);
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
};

void printTable(const std::vector<RungResult>& results, const std::map<std::string, const TuneCandidate*>& byId,
                const TuneGoal& goal, const TuneSpec& spec) {
  std::cout << "  " << std::left << std::setw(12) << "candidate" << std::right << std::setw(12)
            << spec.metric << std::setw(10) << (spec.time + " ms") << "  configuration\n";
  std::vector<RungResult> sorted = results;
  std::stable_sort(sorted.begin(), sorted.end(), [&](const RungResult& a, const RungResult& b) { return goal.better(a, b); });
  for (const RungResult& r : sorted)
    std::cout << "  " << std::left << std::setw(12) << r.id << std::right << std::fixed << std::setprecision(4)
              << std::setw(12) << r.error << std::setprecision(1) << std::setw(10) << r.ms << "  "
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
  for (const Measurement& m : all) {
    const auto f = figures(spec, m.directory);
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

int writeTuneOutputs(const TuneSpec& spec, const fs::path& dir,
                     const std::map<std::string, const TuneCandidate*>& byId,
                     const std::vector<RungRecord>& rungs, const Options& options) {
  const TuneGoal& last = rungs.back().goal;
  const std::optional<RungResult> best = choose(rungs.back().results, last);
  const std::string goalText = spec.budgetMs ? "the least " + spec.pair + "." + spec.metric + " within " +
                                                   (spec.budgetIsBaseline ? "the baseline's " + spec.time + " time"
                                                                          : std::to_string(*spec.budgetMs) + " ms (" + spec.time + ")")
                                             : "the least " + spec.time + " time within " + spec.pair + "." +
                                                   spec.metric + " " + std::to_string(*spec.maxError);
  nlohmann::json result = {{"file", spec.file}, {"goal", goalText}, {"metric", spec.pair + "." + spec.metric},
                           {"time", spec.time}, {"eta", spec.eta}, {"host", hostInfo()},
                           {"created_utc", utcTimestamp()}, {"lpvlab", lpvlabRevision()},
                           {"clock", "each run's own (its manifest's timing.clock): CPU wall clock or GL timer queries"}};
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
  const TuneCandidate& chosen = *byId.at(best->id);
  result["chosen"] = toJson(*best, last);
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
    RungRecord record{spec.rungs[std::size_t(rung)], results(spec, all), {}, goal};
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

#include "framework/tune/tune_spec.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/experiment/experiment_file.h"
#include "framework/experiment/sweep_expansion.h"
#include "framework/fit/fit_spec.h"

namespace lpvlab {

namespace {

const std::set<std::string> kKeys = {"metric", "time", "gpu", "fit", "budget_ms", "error", "candidates", "eta",
                                     "rungs", "seed", "space", "views", "held_out"};

std::string where(const std::string& file, const std::string& key) {
  return file + ": key 'tune." + key + "'";
}

double numberOf(const toml::node& node, const std::string& at) {
  if (const auto* i = node.as_integer()) return double(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  throw Error(at + ": expected a number");
}

// A space entry: a list of choices, or {min, max[, step][, log]}.
TuneDimension readDimension(const std::string& key, const toml::node& node, const std::string& file) {
  const std::string at = where(file, "space.\"" + key + "\"");
  if (std::count(key.begin(), key.end(), '.') != 1 || key.front() == '.' || key.back() == '.')
    throw Error(at + ": expected \"<table>.<name>\", a key of the experiment");
  TuneDimension d;
  d.key = key;
  if (const toml::array* list = node.as_array()) {
    if (list->empty()) throw Error(at + ": an empty list of choices");
    for (const toml::node& choice : *list) d.choices.push_back(tomlValueText(choice));
    return d;
  }
  const toml::table* range = node.as_table();
  if (!range) throw Error(at + ": expected a list of choices or { min, max }");
  for (const auto& [k, v] : *range)
    if (k.str() != "min" && k.str() != "max" && k.str() != "step" && k.str() != "log")
      throw Error(at + "." + std::string(k.str()) + ": unknown (min, max, step, log)");
  if (!range->get("min") || !range->get("max")) throw Error(at + ": a range needs min and max");
  d.min = numberOf(*range->get("min"), at + ".min");
  d.max = numberOf(*range->get("max"), at + ".max");
  d.integer = range->get("min")->is_integer() && range->get("max")->is_integer();
  if (const toml::node* step = range->get("step")) d.step = numberOf(*step, at + ".step");
  if (const toml::node* log = range->get("log")) {
    if (!log->is_boolean()) throw Error(at + ".log: expected true or false");
    d.log = log->as_boolean()->get();
  }
  if (!(std::isfinite(d.min) && std::isfinite(d.max) && d.min <= d.max))
    throw Error(at + ": min " + std::to_string(d.min) + " and max " + std::to_string(d.max) +
                " are not finite with min <= max");
  if (d.step < 0.0 || !std::isfinite(d.step)) throw Error(at + ".step: must be >= 0");
  if (d.log && !(d.min > 0.0)) throw Error(at + ".log: a log range needs min > 0");
  return d;
}

// A key that must have one TOML type when given.
template <class T>
void requireType(const toml::table& tune, const std::string& key, const std::string& file, const char* what) {
  if (const toml::node* node = tune.get(key); node && !node->is<T>())
    throw Error(where(file, key) + ": expected " + what);
}

void readGoal(const toml::table& tune, const std::string& file, TuneSpec& spec) {
  if (const toml::node* b = tune.get("budget_ms")) {
    if (b->value_or(std::string()) == "baseline")
      spec.budgetIsBaseline = true, spec.budgetMs = 1.0;  // replaced by the baseline's time per rung
    else
      spec.budgetMs = numberOf(*b, where(file, "budget_ms") + " (a number of ms, or \"baseline\")");
  }
  if (const toml::node* e = tune.get("error")) spec.maxError = numberOf(*e, where(file, "error"));
  if (spec.budgetMs && !(*spec.budgetMs > 0.0)) throw Error(where(file, "budget_ms") + ": must be > 0");
  if (spec.maxError && !(*spec.maxError > 0.0)) throw Error(where(file, "error") + ": must be > 0");
}

void readRungs(const toml::table& tune, const std::string& file, TuneSpec& spec) {
  const toml::node* node = tune.get("rungs");
  if (!node) return;
  const toml::array* rungs = node->as_array();
  if (!rungs || rungs->empty()) throw Error(where(file, "rungs") + ": expected a list of sample counts");
  spec.rungs.clear();
  for (const toml::node& r : *rungs) {
    const auto* samples = r.as_integer();
    if (!samples || samples->get() < 1 || samples->get() > (1 << 24))
      throw Error(where(file, "rungs") + ": each rung is a sample count from 1 to 2^24");
    if (!spec.rungs.empty() && samples->get() < spec.rungs.back())
      throw Error(where(file, "rungs") + ": the sample counts must not decrease");
    spec.rungs.push_back(int(samples->get()));
  }
}

// [tune.fit] as the [fit] table of `lpvlab fit` on the tuned views, checked as the fit checks
// its file (on the baseline: keys that exist, bounds, settings) before anything runs.
void readFit(const toml::table& tune, const std::string& file, TuneSpec& spec) {
  const toml::node* node = tune.get("fit");
  if (!node) return;
  const toml::table* fit = node->as_table();
  if (!fit) throw Error(where(file, "fit") + ": expected a table ([tune.fit], as a [fit] table)");
  for (const char* own : {"views", "held_out"})
    if (fit->contains(own))
      throw Error(where(file, std::string("fit.") + own) + ": the fit runs on the tune's own views ([[tune.views]]); "
                  "the tune measures its held-out views itself");
  toml::table table = *fit;
  toml::array views;
  if (const toml::node* tuned = tune.get("views"))
    if (const toml::array* list = tuned->as_array())
      for (const toml::node& view : *list)
        if (const toml::table* t = view.as_table()) {
          toml::table absolute = *t;
          absolutizeSceneFile(absolute, file);
          views.push_back(std::move(absolute));
        }
  if (views.empty()) views.push_back(toml::table{{"name", "file"}});
  table.insert_or_assign("views", std::move(views));
  toml::table root = spec.base;
  root.insert_or_assign("fit", table);
  try {
    readFitSpec(root, file);
  } catch (const Error& e) {
    throw Error(where(file, "fit") + ": as lpvlab fit's [fit] table: " + e.what());
  }
  spec.fit = std::move(table);
}

}  // namespace

TuneSpec readTuneSpec(const std::string& path, const std::vector<std::string>& overrides,
                      std::optional<double> budgetMs, std::optional<double> maxError) {
  toml::table root = readExperimentTable(path);
  for (const std::string& o : overrides) applyOverride(root, o);
  const toml::node* node = root.get("tune");
  if (!node || !node->is_table())
    throw Error(path + ": no [tune] table: nothing to tune (see docs/tuning.md)");
  const toml::table tune = *node->as_table();
  root.erase("tune");
  if (root.contains("sweep")) throw Error(path + ": a tune file cannot have a [sweep] table");
  if (root.contains("fit")) throw Error(path + ": a tune file cannot have a [fit] table");
  for (const auto& [k, v] : tune)
    if (!kKeys.count(std::string(k.str())))
      throw Error(where(path, std::string(k.str())) + ": unknown key (see docs/tuning.md)");
  requireType<std::string>(tune, "metric", path, "a string");
  requireType<std::string>(tune, "time", path, "a string");
  for (const char* key : {"candidates", "eta", "seed"}) requireType<std::int64_t>(tune, key, path, "an integer");
  TuneSpec spec;
  spec.file = path;
  spec.base = std::move(root);
  const std::string metric = tune["metric"].value_or(spec.pair + "." + spec.metric);
  const auto dot = metric.rfind('.');
  if (dot == std::string::npos || metric.find("_vs_") == std::string::npos)
    throw Error(where(path, "metric") + ": '" + echoed(metric) + "': expected <run>_vs_<reference>.<metric>, "
                "e.g. indirect_vs_indirect1.block_nrmse");
  spec.pair = metric.substr(0, dot);
  spec.metric = metric.substr(dot + 1);
  spec.time = tune["time"].value_or(spec.time);
  if (spec.time != "method" && spec.time != "total" && spec.time != "gpu-estimate")
    throw Error(where(path, "time") + ": '" + echoed(spec.time) + "': expected method, total or gpu-estimate");
  requireType<std::string>(tune, "gpu", path, "a string (a key of analysis/lpvlab_analysis/gpus.toml)");
  if (tune.contains("gpu") && spec.time != "gpu-estimate")
    throw Error(where(path, "gpu") + ": only with time = \"gpu-estimate\" (the GPU whose estimate is the time)");
  spec.gpu = tune["gpu"].value_or(spec.gpu);
  readGoal(tune, path, spec);
  if (budgetMs) spec.budgetMs = budgetMs, spec.maxError.reset(), spec.budgetIsBaseline = false;
  if (maxError) spec.maxError = maxError, spec.budgetMs.reset(), spec.budgetIsBaseline = false;
  if (spec.budgetMs.has_value() == spec.maxError.has_value())
    throw Error(path + ": [tune] needs exactly one goal: budget_ms (the least error within a time) "
                "or error (the least time within an error), in the file or as --budget-ms / --error");
  spec.candidates = int(tune["candidates"].value_or(std::int64_t(spec.candidates)));
  spec.eta = int(tune["eta"].value_or(std::int64_t(spec.eta)));
  if (spec.candidates < 1 || spec.candidates > 10000) throw Error(where(path, "candidates") + ": from 1 to 10000");
  if (spec.eta < 2 || spec.eta > 100) throw Error(where(path, "eta") + ": from 2 to 100");
  spec.seed = std::uint64_t(tune["seed"].value_or(std::int64_t(1)));
  readRungs(tune, path, spec);
  const toml::table* space = tune["space"].as_table();
  if (!space || space->empty())
    throw Error(where(path, "space") + ": nothing to search: give [tune.space] keys with their choices or ranges");
  for (const auto& [key, value] : *space) spec.space.push_back(readDimension(std::string(key.str()), value, path));
  spec.views = readNamedViews(tune, "tune", "views", path);
  spec.heldOut = readNamedViews(tune, "tune", "held_out", path);
  if (spec.views.empty()) spec.views.push_back({"file", {}});
  readFit(tune, path, spec);
  return spec;
}

}  // namespace lpvlab

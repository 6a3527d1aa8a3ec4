#include "framework/fit/fit_spec.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/experiment_file.h"
#include "framework/experiment/named_views.h"

namespace lpvlab {

namespace {

const std::vector<std::string> kStages = {"injection", "occlusion", "propagation", "rendering"};

const nlohmann::json* findKey(const nlohmann::json& config, const std::string& stage,
                              const std::string& name) {
  if (!config.contains(stage) || !config[stage].is_object()) return nullptr;
  const nlohmann::json& table = config[stage];
  return table.contains(name) ? &table[name] : nullptr;
}

// The real-valued parameters the strategy of `stage` read, for messages.
std::string realKeys(const nlohmann::json& config, const std::string& stage) {
  std::string out;
  if (config.contains(stage) && config[stage].is_object())
    for (const auto& [k, v] : config[stage].items())
      if (v.is_number_float()) out += (out.empty() ? "" : ", ") + stage + "." + k;
  return out.empty() ? "none" : out;
}

// Checks that `p.key` is a real-valued parameter that a strategy of the experiment reads, and
// returns the experiment's value of it.
double experimentValue(const FitParameter& p, const nlohmann::json& config, const std::string& where) {
  const auto dot = p.key.find('.');
  const std::string stage = p.key.substr(0, dot);
  const std::string name = dot == std::string::npos ? "" : p.key.substr(dot + 1);
  if (dot == std::string::npos || std::find(kStages.begin(), kStages.end(), stage) == kStages.end() ||
      name.empty() || name.find('.') != std::string::npos)
    throw Error(where + ": '" + p.key + "' is not a strategy parameter: expected <stage>.<name> "
                "with <stage> one of injection, occlusion, propagation, rendering");
  const std::string type = config.contains(stage) && config[stage].contains("type")
                               ? config[stage]["type"].get<std::string>() : "?";
  const nlohmann::json* value = findKey(config, stage, name);
  if (!value || name == "type")
    throw Error(where + ": unknown parameter '" + p.key + "': the " + stage + " strategy '" +
                type + "' does not read it (its real-valued parameters: " + realKeys(config, stage) + ")");
  if (!value->is_number_float())
    throw Error(where + ": parameter '" + p.key + "' of the " + stage + " strategy '" + type +
                "' is not real-valued (only real parameters can be fitted; its real-valued "
                "parameters: " + realKeys(config, stage) + ")");
  return value->get<double>();
}

}  // namespace

toml::table FitSpec::viewTable(const FitViewSpec& view) const { return withView(base, view); }

const char* residualName(ResidualKind kind) {
  return kind == ResidualKind::Linear ? "linear" : kind == ResidualKind::Relative ? "relative" : "log";
}

const char* lossName(LossKind kind) {
  return kind == LossKind::None ? "none" : kind == LossKind::Huber ? "huber" : "cauchy";
}

const char* derivativeName(DerivativeKind kind) {
  return kind == DerivativeKind::Automatic ? "automatic" : "central";
}

FitSpec readFitSpec(const std::string& path, const std::vector<std::string>& overrides) {
  toml::table root = readExperimentTable(path);
  for (const std::string& o : overrides) applyOverride(root, o);
  return readFitSpec(std::move(root), path);
}

FitSpec readFitSpec(toml::table root, const std::string& path) {
  FitSpec spec;
  spec.file = path;
  const toml::node* fitNode = root.get("fit");
  if (!fitNode || !fitNode->is_table())
    throw Error(path + ": no [fit] table: nothing to fit (see docs/fitting.md)");
  toml::table fit = *fitNode->as_table();
  root.erase("fit");
  if (root.contains("sweep")) throw Error(path + ": a fit file cannot have a [sweep] table");
  spec.base = std::move(root);

  spec.views = readNamedViews(fit, "fit", "views", path);
  spec.heldOut = readNamedViews(fit, "fit", "held_out", path);
  if (spec.views.empty())
    throw Error(path + ": key 'fit.views': no views to fit on; add at least one [[fit.views]] "
                "with a name (and the experiment keys that make it a view, none for the file's own)");
  for (const FitViewSpec& h : spec.heldOut)
    for (const FitViewSpec& v : spec.views)
      if (h.name == v.name)
        throw Error(path + ": key 'fit.held_out': '" + h.name + "' is also a fitted view");
  fit.erase("views");
  fit.erase("held_out");

  Params params(fit, path, "fit");
  const std::string residual = params.getChoice("residual", "linear", {"linear", "relative", "log"});
  spec.residual = residual == "linear" ? ResidualKind::Linear
                  : residual == "relative" ? ResidualKind::Relative : ResidualKind::Log;
  spec.epsilon = params.get<double>("epsilon", 1e-2, {.min = 1e-12});
  const std::string loss = params.getChoice("loss", "none", {"none", "huber", "cauchy"});
  spec.loss = loss == "none" ? LossKind::None : loss == "huber" ? LossKind::Huber : LossKind::Cauchy;
  spec.lossScale = params.get<double>("loss_scale", 1.0, {.min = 1e-12});
  spec.relativeStep = params.get<double>("step", 1e-3, {.min = 1e-7, .max = 0.1});
  spec.derivatives = params.getChoice("derivatives", "automatic", {"automatic", "central"}) == "central"
                         ? DerivativeKind::Central
                         : DerivativeKind::Automatic;
  spec.maxIterations = params.get<int>("max_iterations", 20, {.min = 0, .max = 10000});
  spec.rankTolerance = params.get<double>("rank_tolerance", 1e-3, {.min = 0.0, .max = 1.0});
  spec.tile = params.get<int>("tile", 16, {.min = 1, .max = 16384});

  // The keys must be parameters that a strategy of the experiment actually reads: the strategies
  // are constructed (by loading the experiment) and their resolved parameters consulted.
  const toml::array* listed = fit.get("parameters") ? fit.get("parameters")->as_array() : nullptr;
  const std::vector<Params> parameterTables =
      listed && listed->empty() ? std::vector<Params>{} : params.tables("parameters");
  if (parameterTables.empty())
    throw Error(params.where("parameters") + ": no parameters to fit; give "
                "parameters = [{ key = \"propagation.damping\", lower = 0.5, upper = 1.5 }, ...]");
  const nlohmann::json config = loadExperiment(spec.base, path).configuration;
  for (Params p : parameterTables) {
    FitParameter parameter;
    parameter.key = p.require<std::string>("key");
    const std::string where = p.where("key");
    for (const FitParameter& other : spec.parameters)
      if (other.key == parameter.key) throw Error(where + ": '" + parameter.key + "' is fitted twice");
    const double value = experimentValue(parameter, config, where);
    parameter.initial = p.get<double>("initial", value);
    parameter.lower = p.get<double>("lower", -1e300);
    parameter.upper = p.get<double>("upper", 1e300);
    parameter.step = p.get<double>("step", 0.0, {.min = 0.0, .max = 1.0});
    if (!(parameter.lower < parameter.upper))
      throw Error(p.where("lower") + ": bounds of '" + parameter.key + "' are empty (lower " +
                  std::to_string(parameter.lower) + " must be below upper " +
                  std::to_string(parameter.upper) + ")");
    if (!(parameter.initial >= parameter.lower && parameter.initial <= parameter.upper))
      throw Error(p.where("initial") + ": the bounds [" + std::to_string(parameter.lower) + ", " +
                  std::to_string(parameter.upper) + "] of '" + parameter.key +
                  "' exclude its initial value " + std::to_string(parameter.initial));
    spec.parameters.push_back(parameter);
  }
  params.finish();
  return spec;
}

}  // namespace lpvlab

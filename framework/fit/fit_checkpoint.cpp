#include "framework/fit/fit_checkpoint.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "framework/core/error.h"
#include "framework/core/hash.h"
#include "framework/fit/fit_output.h"
#include "framework/core/atomic_file.h"

namespace lpvlab {

namespace {

std::string tomlText(const toml::table& table) {
  std::ostringstream out;
  out << table;
  return out.str();
}

}  // namespace

std::string fitKey(const FitSpec& spec) {
  Hasher h;
  h.text(tomlText(spec.base));
  for (const FitParameter& p : spec.parameters)
    h.text(p.key).value(p.initial).value(p.lower).value(p.upper).value(p.step);
  for (const FitViewSpec& v : spec.views) h.text(v.name).text(tomlText(v.keys));
  h.value(int(spec.residual)).value(spec.epsilon).value(int(spec.loss)).value(spec.lossScale);
  h.value(spec.relativeStep);
  return h.hex();
}

void writeFitProgress(const std::string& path, const std::string& key, const FitProgress& progress) {
  nlohmann::json log = nlohmann::json::array();
  for (const FitIteration& it : progress.log) {
    nlohmann::json entry = iterationJson(it);
    entry["trust_region_radius"] =
        it.trustRegionRadius;  // what resuming needs beyond fit.json's log
    log.push_back(std::move(entry));
  }
  const nlohmann::json json = {{"fit_key", key}, {"renders", progress.renders},
                               {"seconds", progress.seconds}, {"log", log}};
  writeTextAtomically(path, json.dump(2) + "\n");
}

std::optional<FitProgress> readFitProgress(const std::string& path, const std::string& key, bool* otherFit) {
  if (otherFit) *otherFit = false;
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    std::ifstream in(path);
    const nlohmann::json json = nlohmann::json::parse(in);
    if (json.at("fit_key").get<std::string>() != key) {
      if (otherFit) *otherFit = true;
      return std::nullopt;
    }
    FitProgress progress;
    progress.renders = json.at("renders").get<int>();
    progress.seconds = json.at("seconds").get<double>();
    for (const nlohmann::json& it : json.at("log"))
      progress.log.push_back(
          {it.at("iteration").get<int>(), it.at("cost").get<double>(),
           it.at("gradient_max_norm").get<double>(), it.at("step_norm").get<double>(),
           it.at("step_successful").get<bool>(), it.at("seconds").get<double>(),
           it.at("x").get<std::vector<double>>(), 0, it.value("trust_region_radius", 0.0)});
    if (progress.log.empty()) throw Error("no iterations");
    return progress;
  } catch (const std::exception& e) {  // the JSON's errors and the empty log's alike
    throw Error(path + ": not a fit's progress file (" + e.what() + "); delete it to start over");
  }
}

}  // namespace lpvlab

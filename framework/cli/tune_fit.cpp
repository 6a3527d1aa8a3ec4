#include "framework/cli/tune_fit.h"

#include <fstream>
#include <iomanip>
#include <sstream>

#include "framework/core/atomic_file.h"
#include "framework/core/error.h"
#include "framework/core/install_layout.h"
#include "framework/core/log.h"
#include "framework/experiment/sweep_expansion.h"
#include "framework/io/child_process.h"

namespace lpvlab::cli {

namespace fs = std::filesystem;

namespace {

// `overrides` with `key`'s value replaced (or added).
void setOverride(std::vector<std::string>& overrides, const std::string& key, const std::string& value) {
  for (std::string& o : overrides)
    if (o.compare(0, key.size() + 1, key + "=") == 0) {
      o = key + "=" + value;
      return;
    }
  overrides.push_back(key + "=" + value);
}

void runFit(const TuneSpec& spec, const fs::path& dir, const std::vector<std::string>& overrides) {
  toml::table root = spec.base;
  root.insert_or_assign("fit", *spec.fit);
  const fs::path file = dir / "configs" / "fit.toml";
  fs::create_directories(file.parent_path());
  writeTextAtomically(file.string(), configurationToml(root, spec.file, {"fit", "the chosen configuration", overrides, {}}));
  log::info("tune: fitting the chosen configuration's constants ([tune.fit]) into " + (dir / "fit").string());
  const int status = runProgram({executablePath().string(), "fit", file.string(), "--out", (dir / "fit").string()});
  if (status != 0)
    throw Error("tune: lpvlab fit " + file.string() + " failed (exit " + std::to_string(status) +
                "; its messages are above): [tune.fit] could not refine the chosen configuration");
}

}  // namespace

TuneFit fitChosenConstants(const TuneSpec& spec, const fs::path& dir, const std::vector<std::string>& chosen,
                           const std::vector<std::string>& runOverrides) {
  std::vector<std::string> overrides = chosen;
  overrides.insert(overrides.end(), runOverrides.begin(), runOverrides.end());
  const fs::path result = dir / "fit" / "fit.json";
  if (!fs::exists(result)) runFit(spec, dir, overrides);  // a finished fit is reused as it is
  std::ifstream in(result);
  const nlohmann::json fit = nlohmann::json::parse(in, nullptr, false);
  if (!fit.is_object() || !fit.contains("parameters")) throw Error(result.string() + ": not lpvlab fit's fit.json");
  TuneFit out{chosen, {{"directory", (dir / "fit").string()}, {"converged", fit.value("converged", false)},
                       {"parameters", nlohmann::json::array()}}};
  for (const nlohmann::json& p : fit["parameters"]) {
    const bool undetermined = p.value("undetermined", false);
    std::ostringstream value;
    value << std::setprecision(9) << p["value"].get<double>();
    if (!undetermined) setOverride(out.overrides, p["key"].get<std::string>(), value.str());
    out.record["parameters"].push_back({{"key", p["key"]}, {"before", p["initial"]}, {"after", p["value"]},
                                        {"undetermined", undetermined}});
  }
  return out;
}

}  // namespace lpvlab::cli

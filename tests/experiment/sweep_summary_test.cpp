// summary.csv's parameter columns come from what the manifests contain (issue 37): the swept
// keys, then the keys each run's manifest names in summary_keys (run_outputs.cpp), each run's in
// its order. No list of any method's keys is fixed in the summary: a method that names none gets
// none, and LPV's runs name theirs through IndirectMethod::summaryKeys.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/experiment/experiment.h"
#include "framework/experiment/json_path.h"
#include "framework/experiment/sweep_summary.h"
#include "framework/core/atomic_file.h"
#include "io/temp_dir.h"
#include "sweep_support.h"

namespace lpvlab {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

nlohmann::json manifestWith(const nlohmann::json& keys, const nlohmann::json& configuration) {
  return {{"configuration", configuration},
          {"summary_keys", keys},
          {"timing", {{"samples", {{"stage_ms", {{"total", {1.0}}}}}}}}};
}

// Header and rows of DIR/summary.csv after summarising the given manifests by id.
std::vector<std::vector<std::string>> summarise(const test::TempDir& dir,
                                                const std::vector<std::pair<std::string, nlohmann::json>>& runs) {
  std::vector<std::string> ids;
  for (const auto& [id, manifest] : runs) {
    std::filesystem::create_directories(dir.file(id));
    writeTextAtomically(dir.file(id + "/manifest.json"), manifest.dump());
    ids.push_back(id);
  }
  test::writeSweepIndex(dir.path(), ids);
  writeSweepSummary(dir.path().string());
  std::ifstream csv(dir.file("summary.csv"));
  std::vector<std::vector<std::string>> lines;
  for (std::string line; std::getline(csv, line);) lines.push_back(split(line));
  return lines;
}

std::vector<std::string> paramColumns(const std::vector<std::string>& header) {
  std::vector<std::string> params;
  for (const std::string& column : header)
    if (column.rfind("param.", 0) == 0) params.push_back(column);
  return params;
}

TEST(SweepSummary, ParameterColumnsAreTheManifestsSummaryKeys) {
  test::TempDir dir;
  const auto lines = summarise(
      dir, {{"a0", manifestWith({"indirect.method", "grid.resolution", "scene.file"},
                                {{"indirect", {{"method", "lpv"}}}, {"grid", {{"resolution", 24}}}})},
            {"b1", manifestWith({"indirect.method", "radiosity.patch_size", "scene.file"},
                                {{"indirect", {{"method", "radiosity"}}},
                                 {"radiosity", {{"patch_size", 0.05}}}})}});
  ASSERT_EQ(lines.size(), 3u);
  // Each key new to the table follows the key before it in its run's list.
  EXPECT_EQ(paramColumns(lines[0]),
            (std::vector<std::string>{"param.indirect.method", "param.radiosity.patch_size",
                                      "param.grid.resolution", "param.scene.file"}));
  // No key a manifest does not name: the summary fixes no method's keys.
  for (const std::string& column : lines[0]) EXPECT_NE(column, "param.injection.type");
  const auto at = [&](std::size_t row, const std::string& column) {
    for (std::size_t i = 0; i < lines[0].size(); ++i)
      if (lines[0][i] == column) return lines[row].at(i);
    return std::string("(no column)");
  };
  EXPECT_EQ(at(1, "param.grid.resolution"), "24");
  EXPECT_EQ(at(1, "param.radiosity.patch_size"), "") << "a run without the key has an empty cell";
  EXPECT_EQ(at(2, "param.radiosity.patch_size"), "0.05");
  EXPECT_EQ(at(2, "param.indirect.method"), "radiosity");
}

TEST(SweepSummary, EachRunsKeyOrderIsKeptWhateverRunComesFirst) {
  // Another method's run first ([method, scene]), then LPV's ([method, strategies, grid, scene])
  // with grid.resolution swept: LPV's keys go between the method and the scene, in its order.
  test::TempDir dir;
  nlohmann::json index = {{"swept_keys", {"grid.resolution"}},
                          {"configurations", {{{"id", "a0"}, {"name", "a0"}}, {{"id", "b1"}, {"name", "b1"}}}}};
  const auto lines = [&] {
    std::filesystem::create_directories(dir.file("a0"));
    std::filesystem::create_directories(dir.file("b1"));
    writeTextAtomically(dir.file("a0/manifest.json"),
                        manifestWith({"indirect.method", "scene.file"}, {}).dump());
    writeTextAtomically(dir.file("b1/manifest.json"),
                        manifestWith({"indirect.method", "injection.type", "grid.resolution",
                                      "grid.sh_order", "scene.file"}, {}).dump());
    writeTextAtomically(dir.file("sweep.json"), index.dump());
    writeSweepSummary(dir.path().string());
    std::ifstream csv(dir.file("summary.csv"));
    std::string header;
    std::getline(csv, header);
    return split(header);
  }();
  EXPECT_EQ(paramColumns(lines),
            (std::vector<std::string>{"param.grid.resolution", "param.indirect.method",
                                      "param.injection.type", "param.grid.sh_order",
                                      "param.scene.file"}));
}

TEST(SweepSummary, AManifestWithoutSummaryKeysHasOnlyItsSweptColumns) {
  test::TempDir dir;
  nlohmann::json manifest = manifestWith({}, {{"grid", {{"resolution", 8}}}});
  manifest.erase("summary_keys");
  const auto lines = summarise(dir, {{"c0", manifest}});
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(paramColumns(lines[0]).empty()) << lines[0].size() << " columns";
}

TEST(SweepSummary, LpvNamesItsStrategiesGridAndIterations) {
  // What LPV's runs write into their manifests' summary_keys (after the method and before the
  // scene, which the run adds).
  const Experiment experiment = loadExperiment("");
  const auto keys = experiment.method->summaryKeys();
  for (const char* key : {"injection.type", "occlusion.type", "propagation.type", "rendering.type",
                          "grid.resolution", "grid.sh_order", "cascades.levels",
                          "propagation.iterations"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
  for (const std::string& key : keys)
    EXPECT_NE(findPath(experiment.configuration, key), nullptr) << key << " is no configuration key";
}

}  // namespace
}  // namespace lpvlab

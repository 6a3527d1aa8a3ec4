// Experiment inheritance (`extends`) and sweep expansion ([sweep] product / zip): the
// configurations a file expands to, their ids and names, and the errors (unequal zip lists, an
// empty list, an unknown swept key, an `extends` cycle) naming the file and key.

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "error_support.h"

#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/json_path.h"
#include "framework/experiment/experiment_file.h"
#include "framework/experiment/sweep_expansion.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

using test::contains;
using test::errorOf;

class SweepExpand : public ::testing::Test {
protected:
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = dir_.file(name);
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream(path) << text;
    return path;
  }
  test::TempDir dir_;
};

std::vector<std::vector<std::string>> overridesOf(const std::vector<SweepConfiguration>& configs) {
  std::vector<std::vector<std::string>> out;
  for (const auto& c : configs) out.push_back(c.overrides);
  return out;
}

TEST_F(SweepExpand, ProductIsCartesianWithStableDistinctIds) {
  const std::string file = write("p.toml", R"(
[sweep]
product = { "propagation.iterations" = [1, 4, 16], "grid.resolution" = [16, 32] }
)");
  const auto configs = expandSweep(file);
  ASSERT_EQ(configs.size(), 6u);
  // Keys in sorted order; the last varies fastest.
  EXPECT_EQ(configs[0].overrides, (std::vector<std::string>{"grid.resolution=16", "propagation.iterations=1"}));
  EXPECT_EQ(configs[1].overrides, (std::vector<std::string>{"grid.resolution=16", "propagation.iterations=4"}));
  EXPECT_EQ(configs[5].overrides, (std::vector<std::string>{"grid.resolution=32", "propagation.iterations=16"}));
  EXPECT_EQ(configs[1].name, "resolution=16,iterations=4");
  std::set<std::string> ids;
  for (const auto& c : configs) ids.insert(c.id);
  EXPECT_EQ(ids.size(), 6u);
  const auto again = expandSweep(file);
  for (std::size_t i = 0; i < configs.size(); ++i) EXPECT_EQ(configs[i].id, again[i].id);
  // Strings are quoted as TOML in the overrides and plain in names.
  const auto strings = expandSweep(write("s.toml", "[sweep]\nproduct = { \"propagation.type\" = [\"standard\"] }\n"));
  ASSERT_EQ(strings.size(), 1u);
  EXPECT_EQ(strings[0].overrides[0], "propagation.type=\"standard\"");
  EXPECT_EQ(strings[0].name, "type=standard");
}

// A configuration is everything it runs with: the same swept values over another base value
// (or another -s) are other configurations, with other ids, and the whole sweep another hash.
TEST_F(SweepExpand, IdsAndTheSweepHashCoverEveryResolvedValue) {
  const std::string sweep = "[sweep]\nproduct = { \"propagation.iterations\" = [1, 4] }\n";
  const std::string at16 = write("g16.toml", "[grid]\nresolution = 16\n" + sweep);
  const std::string at20 = write("g20.toml", "[grid]\nresolution = 20\n" + sweep);
  const auto a = expandSweep(at16), b = expandSweep(at20), c = expandSweep(at16, {"grid.sh_order=2"});
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  ASSERT_EQ(c.size(), 2u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].name, b[i].name);
    EXPECT_NE(a[i].id, b[i].id) << "the base resolution differs";
    EXPECT_NE(a[i].id, c[i].id) << "the -s differs";
  }
  const auto hashOf = [](const std::string& file, const std::vector<std::string>& overrides) {
    toml::table root = readExperimentTable(file);
    for (const std::string& o : overrides) applyOverride(root, o);
    return sweepHash(root, file);
  };
  EXPECT_EQ(hashOf(at16, {}), hashOf(at16, {}));
  EXPECT_NE(hashOf(at16, {}), hashOf(at20, {}));
  EXPECT_NE(hashOf(at16, {}), hashOf(at16, {"grid.sh_order=2"}));
  // The same values written another way are the same sweep.
  const std::string reordered = write("r16.toml", sweep + "[grid]\nresolution = 16\n");
  EXPECT_EQ(hashOf(at16, {}), hashOf(reordered, {}));
  EXPECT_EQ(expandSweep(reordered)[1].id, a[1].id);
}

TEST_F(SweepExpand, ZipIteratesTogetherAndCombinesWithProduct) {
  const auto zip = expandSweep(write("z.toml", R"(
[sweep]
zip = { "grid.resolution" = [8, 16], "propagation.iterations" = [2, 3] }
)"));
  EXPECT_EQ(overridesOf(zip), (std::vector<std::vector<std::string>>{
                                  {"grid.resolution=8", "propagation.iterations=2"},
                                  {"grid.resolution=16", "propagation.iterations=3"}}));
  const auto both = expandSweep(write("b.toml", R"(
[sweep]
zip = { "grid.resolution" = [8, 16], "propagation.iterations" = [2, 3] }
product = { "output.width" = [16, 32, 48] }
)"));
  ASSERT_EQ(both.size(), 6u);
  EXPECT_EQ(both[0].overrides, (std::vector<std::string>{"grid.resolution=8", "propagation.iterations=2", "output.width=16"}));
  EXPECT_EQ(both[5].overrides, (std::vector<std::string>{"grid.resolution=16", "propagation.iterations=3", "output.width=48"}));
  // No [sweep]: one configuration, no overrides.
  const auto none = expandSweep(write("n.toml", "[grid]\nresolution = 8\n"));
  ASSERT_EQ(none.size(), 1u);
  EXPECT_TRUE(none[0].overrides.empty());
  EXPECT_EQ(none[0].name, "base");
}

TEST_F(SweepExpand, UnequalZipEmptyListAndUnknownKeyAreErrors) {
  const std::string unequal = write("u.toml", R"(
[sweep]
zip = { "grid.resolution" = [8, 16, 32], "propagation.iterations" = [2, 3] }
)");
  const std::string e1 = errorOf([&] { expandSweep(unequal); });
  EXPECT_TRUE(contains(e1, "u.toml"));
  EXPECT_TRUE(contains(e1, "grid.resolution (3 values)"));
  EXPECT_TRUE(contains(e1, "propagation.iterations (2 values)"));
  // loadExperiment checks the sweep of a file it reads, too.
  EXPECT_TRUE(contains(errorOf([&] { loadExperiment(unequal); }), "unequal length"));

  const std::string empty = write("e.toml", "[sweep]\nproduct = { \"grid.resolution\" = [] }\n");
  const std::string e2 = errorOf([&] { expandSweep(empty); });
  EXPECT_TRUE(contains(e2, "e.toml"));
  EXPECT_TRUE(contains(e2, "grid.resolution"));
  EXPECT_TRUE(contains(e2, "empty"));

  // An unknown key expands fine and is caught when the configuration is loaded.
  const std::string unknown = write("k.toml", R"(
[output]
width = 16
height = 16
[sweep]
product = { "propagation.iteratoins" = [1, 2] }
)");
  const auto configs = expandSweep(unknown);
  ASSERT_EQ(configs.size(), 2u);
  EXPECT_TRUE(contains(errorOf([&] { loadExperiment(unknown, configs[0].overrides); }),
                       "propagation.iteratoins"));
  // ... and in the resolved configuration file `lpvlab sweep` writes.
  const std::string resolved = write("configs/" + configs[1].id + ".toml", configurationToml(unknown, configs[1]));
  EXPECT_TRUE(contains(errorOf([&] { loadExperiment(resolved); }), "iteratoins"));
}

TEST_F(SweepExpand, ResolvedConfigurationLoadsWithItsOverrides) {
  const std::string file = write("r.toml", R"(
[output]
width = 16
height = 16
[sweep]
product = { "propagation.iterations" = [3, 5], "grid.resolution" = [6] }
)");
  const auto configs = expandSweep(file);
  ASSERT_EQ(configs.size(), 2u);
  const std::string path = write("out/configs/" + configs[1].id + ".toml", configurationToml(file, configs[1]));
  const Experiment e = loadExperiment(path);
  EXPECT_EQ(e.configuration["propagation"]["iterations"], 5);
  EXPECT_EQ(e.configuration["grid"]["resolution"], 6);
  // A sweep file read directly is its base configuration.
  const Experiment base = loadExperiment(file);
  EXPECT_EQ(base.configuration["grid"]["resolution"], 32);
}

TEST_F(SweepExpand, ExtendsChainMergesTablesReplacesArraysAndKeepsRelativeScenePaths) {
  write("bases/base.toml", R"(
[scene]
file = "models/room.obj"
replace_lights = true
[[lights]]
type = "point"
position = [0.2, 0.3, 0.2]
intensity = 1.0
[[lights]]
type = "point"
position = [0.3, 0.3, 0.2]
intensity = 2.0
[grid]
resolution = 8
margin = 2.0
[propagation]
iterations = 4
)");
  write("mid.toml", R"(
extends = "bases/base.toml"
[grid]
resolution = 12
)");
  const std::string child = write("child.toml", R"(
extends = "mid.toml"
[[lights]]
type = "point"
position = [0.25, 0.3, 0.25]
intensity = 3.0
[propagation]
type = "standard"
)");
  const toml::table t = readExperimentTable(child);
  EXPECT_FALSE(t.contains("extends"));
  EXPECT_EQ(t["grid"]["resolution"].value<int>(), 12);        // mid replaces base
  EXPECT_EQ(t["grid"]["margin"].value<double>(), 2.0);        // sub-table merged
  EXPECT_EQ(t["propagation"]["iterations"].value<int>(), 4);  // kept from base
  EXPECT_EQ(t["propagation"]["type"].value<std::string>(), "standard");
  ASSERT_TRUE(t["lights"].as_array());
  ASSERT_EQ(t["lights"].as_array()->size(), 1u);              // arrays of tables replace whole
  EXPECT_EQ(t["lights"][0]["intensity"].value<double>(), 3.0);
  const fs::path expected = fs::absolute(dir_.path() / "bases" / "models" / "room.obj").lexically_normal();
  EXPECT_EQ(t["scene"]["file"].value<std::string>(), expected.string());

  // A loadable chain: loadExperiment reads it merged.
  write("cb_base.toml", "[grid]\nresolution = 7\n[propagation]\niterations = 3\n[output]\nwidth = 16\nheight = 16\n");
  const std::string cb = write("cb_child.toml", "extends = \"cb_base.toml\"\n[propagation]\niterations = 9\n");
  const Experiment e = loadExperiment(cb);
  EXPECT_EQ(e.configuration["grid"]["resolution"], 7);
  EXPECT_EQ(e.configuration["propagation"]["iterations"], 9);
  EXPECT_EQ(e.configuration["output"]["width"], 16);
}

TEST_F(SweepExpand, ExtendsCycleAndMissingBaseAreErrors) {
  write("a.toml", "extends = \"b.toml\"\n");
  write("b.toml", "extends = \"c.toml\"\n");
  const std::string c = write("c.toml", "extends = \"a.toml\"\n");
  const std::string e = errorOf([&] { readExperimentTable(c); });
  EXPECT_TRUE(contains(e, "cycle"));
  EXPECT_TRUE(contains(e, "a.toml"));
  EXPECT_TRUE(contains(e, "b.toml"));
  EXPECT_TRUE(contains(e, "c.toml"));
  EXPECT_TRUE(contains(errorOf([&] { loadExperiment(c); }), "cycle"));
  const std::string missing = write("m.toml", "extends = \"nope.toml\"\n");
  const std::string e2 = errorOf([&] { loadExperiment(missing); });
  EXPECT_TRUE(contains(e2, "m.toml"));
  EXPECT_TRUE(contains(e2, "extends"));
  EXPECT_TRUE(contains(e2, "nope.toml"));
}

}  // namespace
}  // namespace lpvlab

namespace lpvlab {
namespace {

// summary.csv's param.* columns read swept keys from the resolved configuration, arrays of tables
// included ("particles[0].draw").
TEST(JsonPath, IndexesArraysOfTables) {
  const nlohmann::json j = nlohmann::json::parse(
      R"({"particles": [{"draw": "geometry"}, {"emitters": [{"rate": 4.0}]}], "grid": {"resolution": 32}})");
  ASSERT_NE(findPath(j, "particles[0].draw"), nullptr);
  EXPECT_EQ(*findPath(j, "particles[0].draw"), "geometry");
  EXPECT_EQ(*findPath(j, "particles[1].emitters[0].rate"), 4.0);
  EXPECT_EQ(*findPath(j, "grid.resolution"), 32);
  EXPECT_EQ(findPath(j, "particles[2].draw"), nullptr);
  EXPECT_EQ(findPath(j, "particles[x].draw"), nullptr);
  EXPECT_EQ(findPath(j, "grid[0].resolution"), nullptr);
}

}  // namespace
}  // namespace lpvlab

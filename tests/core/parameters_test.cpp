#include "framework/core/parameters.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "error_support.h"
#include "framework/core/error.h"

// gmock isn't linked into the tests; gtest's IsSubstring prints both strings when it fails.
#define EXPECT_CONTAINS(text, part) EXPECT_PRED_FORMAT2(::testing::IsSubstring, part, text)

namespace lpvlab {
namespace {

using test::errorOf;

toml::table parse(std::string_view text) { return toml::parse(text, std::string_view("exp.toml")); }

TEST(Params, DefaultWhenAbsentValueWhenPresent) {
  const toml::table t = parse("iterations = 16\nname = 'box'\nscale = 2\n");
  Params p(t, "exp.toml");
  EXPECT_EQ(p.get("absent", 7), 7);
  EXPECT_EQ(p.get("iterations", 8), 16);
  EXPECT_EQ(p.get<std::string>("name", "x"), "box");
  EXPECT_DOUBLE_EQ(p.get("scale", 1.0), 2.0);  // an integer reads as a number
}

TEST(Params, VectorsAndStringLists) {
  const toml::table t = parse("origin = [1, 2.5, -3]\ncells = [32, 32, 16]\naovs = ['a', 'b']\n");
  Params p(t, "exp.toml");
  EXPECT_EQ(p.get("origin", glm::vec3(0)), glm::vec3(1, 2.5f, -3));
  EXPECT_EQ(p.get("cells", glm::ivec3(0)), glm::ivec3(32, 32, 16));
  EXPECT_EQ(p.get("aovs", std::vector<std::string>{}), (std::vector<std::string>{"a", "b"}));
}

TEST(Params, WrongTypeNamesFileLineKeyAndExpectedType) {
  const toml::table t = parse("[propagation]\n\niterations = 'many'\n");
  Params p(t, "exp.toml");
  Params sub = p.table("propagation");
  const std::string message = errorOf([&] { sub.get("iterations", 8); });
  EXPECT_CONTAINS(message, "exp.toml:3");
  EXPECT_CONTAINS(message, "propagation.iterations");
  EXPECT_CONTAINS(message, "an integer");
  EXPECT_CONTAINS(message, "a string");
}

TEST(Params, OutOfRangeIsAnErrorNotClamped) {
  const toml::table t = parse("iterations = 0\nweight = 1.5\n");
  Params p(t, "exp.toml");
  EXPECT_CONTAINS(errorOf([&] {
                    p.get("iterations", 8, Range<int>{1, 64});
                  }),
                  "below the minimum 1");
  EXPECT_CONTAINS(errorOf([&] {
                    p.get("weight", 0.5, Range<double>{0.0, 1.0});
                  }),
                  "above the maximum 1");
  // Inside the range the value passes through untouched.
  EXPECT_DOUBLE_EQ(p.get("weight", 0.5, Range<double>{0.0, 2.0}), 1.5);
}

TEST(Params, NanAndInfAreRejected) {
  const toml::table t = parse("a = nan\nb = inf\nc = -inf\nv = [0, nan, 1]\n");
  Params p(t, "exp.toml");
  EXPECT_CONTAINS(errorOf([&] { p.get("a", 1.0); }), "not finite");
  EXPECT_CONTAINS(errorOf([&] { p.get("b", 1.0f); }), "not finite");
  EXPECT_CONTAINS(errorOf([&] { p.get("c", 1.0); }), "not finite");
  EXPECT_CONTAINS(errorOf([&] { p.get("v", glm::vec3(0)); }), "not finite");
}

TEST(Params, UnknownRootKeyNamesKeyLineAndValidKeys) {
  const toml::table t = parse("iterations = 4\n\niteratoins = 8\n");
  Params p(t, "exp.toml");
  p.get("iterations", 1);
  p.get("damping", 0.5);
  const std::string message = errorOf([&] { p.finish(); });
  EXPECT_CONTAINS(message, "exp.toml:3");
  EXPECT_CONTAINS(message, "'iteratoins'");
  EXPECT_CONTAINS(message, "iterations, damping");
}

TEST(Params, UnknownKeyInSubTable) {
  const toml::table t = parse("[camera]\nfov = 60\nfvo = 50\n");
  Params p(t, "exp.toml");
  p.table("camera").get("fov", 45.0);
  const std::string message = errorOf([&] { p.finish(); });
  EXPECT_CONTAINS(message, "exp.toml:3");
  EXPECT_CONTAINS(message, "'camera.fvo'");
  EXPECT_CONTAINS(message, "fov");
}

TEST(Params, FinishPassesWhenEveryKeyWasAskedFor) {
  const toml::table t = parse("a = 1\n[camera]\nfov = 60\n");
  Params p(t, "exp.toml");
  p.get("a", 0);
  p.table("camera").get("fov", 45.0);
  EXPECT_NO_THROW(p.finish());
}

// A stage may look at a table in two places; both reads count as asked for.
TEST(Params, SameTableAskedTwiceSharesTracking) {
  const toml::table t = parse("[camera]\nfov = 60\nnear = 0.1\n");
  Params p(t, "exp.toml");
  p.table("camera").get("fov", 45.0);
  p.table("camera").get("near", 0.01);
  EXPECT_NO_THROW(p.finish());
  EXPECT_EQ(p.resolved()["camera"]["fov"], 60.0);
  EXPECT_EQ(p.resolved()["camera"]["near"], 0.1);
}

TEST(Params, SameArrayOfTablesAskedTwiceSharesTracking) {
  const toml::table t = parse("[[lights]]\ntype = 'spot'\nangle = 30\n");
  Params p(t, "exp.toml");
  p.tables("lights")[0].get<std::string>("type", "");
  p.tables("lights")[0].get("angle", 45.0);
  EXPECT_NO_THROW(p.finish());
  EXPECT_EQ(p.resolved()["lights"].size(), 1u);
}

TEST(Params, ChoiceListsValidValues) {
  const toml::table t = parse("type = 'gathr'\n");
  Params p(t, "exp.toml");
  const std::string message = errorOf([&] {
    p.getChoice("type", "gather", {"gather", "scatter"});
  });
  EXPECT_CONTAINS(message, "'gathr'");
  EXPECT_CONTAINS(message, "gather, scatter");
  const toml::table empty;
  Params q(empty, "exp.toml");
  EXPECT_EQ(q.getChoice("type", "gather", {"gather", "scatter"}), "gather");
}

TEST(Params, RequireMissingIsAnError) {
  const toml::table t = parse("b = 2\n");
  Params p(t, "exp.toml");
  EXPECT_CONTAINS(errorOf([&] { p.require<int>("a"); }), "missing required key 'a'");
  EXPECT_EQ(p.require<int>("b"), 2);
}

TEST(Params, ArraysOfTables) {
  const toml::table t = parse("[[lights]]\ntype = 'spot'\n[[lights]]\ntype = 'point'\nextra = 1\n");
  Params p(t, "exp.toml");
  std::vector<Params> lights = p.tables("lights");
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0].get<std::string>("type", ""), "spot");
  EXPECT_EQ(lights[1].get<std::string>("type", ""), "point");
  EXPECT_CONTAINS(errorOf([&] { p.finish(); }), "lights[1].extra");
  EXPECT_TRUE(p.tables("absent").empty());
}

TEST(Params, HasMarksKeyAsKnown) {
  const toml::table t = parse("flag = true\n");
  Params p(t, "exp.toml");
  EXPECT_TRUE(p.has("flag"));
  EXPECT_FALSE(p.has("other"));
  EXPECT_NO_THROW(p.finish());
}

TEST(Params, ResolvedHoldsDefaultsAndNestedTables) {
  const toml::table t = parse("a = 3\n[grid]\nsize = 32\n[[lights]]\npower = 2.0\n");
  Params p(t, "exp.toml");
  p.get("a", 1);
  p.get("b", 0.25);
  Params grid = p.table("grid");
  grid.get("size", 16);
  grid.get("origin", glm::vec3(1, 2, 3));
  p.tables("lights")[0].get("power", 1.0);
  const nlohmann::json r = p.resolved();
  EXPECT_EQ(r["a"], 3);
  EXPECT_EQ(r["b"], 0.25);
  EXPECT_EQ(r["grid"]["size"], 32);
  EXPECT_EQ(r["grid"]["origin"], nlohmann::json::array({1.0, 2.0, 3.0}));
  ASSERT_TRUE(r["lights"].is_array());
  EXPECT_EQ(r["lights"][0]["power"], 2.0);
}

TEST(ApplyOverride, CreatesTablesAndSetsInteger) {
  toml::table root;
  applyOverride(root, "a.b=3");
  ASSERT_TRUE(root["a"]["b"].is_integer());
  EXPECT_EQ(root["a"]["b"].value<int64_t>(), 3);
}

TEST(ApplyOverride, ReplacesExistingValueInExistingTable) {
  toml::table root = parse("[a]\nb = 1\nc = 2\n");
  applyOverride(root, "a.b=5.5");
  EXPECT_EQ(root["a"]["b"].value<double>(), 5.5);
  EXPECT_EQ(root["a"]["c"].value<int64_t>(), 2);
}

TEST(ApplyOverride, BareWordBecomesString) {
  toml::table root;
  applyOverride(root, "x=hello");
  EXPECT_EQ(root["x"].value<std::string>(), "hello");
}

TEST(ApplyOverride, ArrayValue) {
  toml::table root;
  applyOverride(root, "v=[1,2,3]");
  const toml::array* array = root["v"].as_array();
  ASSERT_NE(array, nullptr);
  ASSERT_EQ(array->size(), 3u);
  EXPECT_EQ((*array)[2].value<int64_t>(), 3);
}

TEST(ApplyOverride, MalformedIsAnError) {
  toml::table root;
  EXPECT_CONTAINS(errorOf([&] { applyOverride(root, "novalue"); }), "novalue");
  EXPECT_THROW(applyOverride(root, "=3"), Error);
}

TEST(ApplyOverride, ThroughANonTableIsAnError) {
  toml::table root = parse("a = 1\n");
  EXPECT_CONTAINS(errorOf([&] { applyOverride(root, "a.b=2"); }), "'a' is not a table");
}

TEST(ApplyOverride, IndexesArraysOfTables) {
  toml::table root = parse("[[p]]\nrate = 1\n[[p]]\nrate = 2\n[[p.e]]\nspeed = 3\n");
  applyOverride(root, "p[1].rate=20");
  applyOverride(root, "p[1].e[0].speed=30.5");
  applyOverride(root, "p[0].size=0.5");
  EXPECT_EQ(root["p"][0]["rate"].value<int64_t>(), 1);
  EXPECT_EQ(root["p"][1]["rate"].value<int64_t>(), 20);
  EXPECT_EQ(root["p"][1]["e"][0]["speed"].value<double>(), 30.5);
  EXPECT_EQ(root["p"][0]["size"].value<double>(), 0.5);
  EXPECT_CONTAINS(errorOf([&] { applyOverride(root, "p[2].rate=1"); }), "there are 2 [[p]] tables");
  EXPECT_CONTAINS(errorOf([&] { applyOverride(root, "q[0].rate=1"); }), "'q' is not an array of tables");
  EXPECT_CONTAINS(errorOf([&] { applyOverride(root, "p[x].rate=1"); }), "name[index]");
  EXPECT_CONTAINS(errorOf([&] { applyOverride(root, "p[0.rate=1"); }), "name[index]");
}

class TomlFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("lpvlab_params_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  std::filesystem::path dir_;
};

TEST_F(TomlFile, ReadsValues) {
  const toml::table t = readTomlFile(write("ok.toml", "a = 1\n"));
  EXPECT_EQ(t["a"].value<int64_t>(), 1);
}

TEST_F(TomlFile, SyntaxErrorNamesFileLineAndColumn) {
  const std::string path = write("bad.toml", "a = 1\nb = = 2\n");
  const std::string message = errorOf([&] { readTomlFile(path); });
  EXPECT_CONTAINS(message, path + ":2:");
}

TEST_F(TomlFile, MissingFileSaysNotFound) {
  const std::string path = (dir_ / "absent.toml").string();
  const std::string message = errorOf([&] { readTomlFile(path); });
  EXPECT_CONTAINS(message, path);
  EXPECT_CONTAINS(message, "not found");
}

}  // namespace
}  // namespace lpvlab

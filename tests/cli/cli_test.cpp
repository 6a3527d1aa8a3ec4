// The lpvlab executable end to end, as a user runs it: a small run writes its three files (and
// no temporaries) with a complete manifest; bad input exits non-zero with one error line that
// names the problem, and writes nothing.
// The executable is found next to this test binary's folder (build/tests/test_pipeline ->
// build/lpvlab); build the `lpvlab` target too (a full build does).

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "executable_support.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

using test::quoted;
using test::readFile;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

using Result = test::LpvlabResult;
using test::runLpvlab;

const nlohmann::json* find(const nlohmann::json& j, const std::vector<std::string>& path) {
  const nlohmann::json* node = &j;
  for (const std::string& key : path) {
    if (!node->is_object() || !node->contains(key)) return nullptr;
    node = &(*node)[key];
  }
  return node;
}

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class Cli : public ::testing::Test {
protected:
  // work: the current directory of lpvlab (so stray default run directories would show);
  // logs: its captured output.
  void SetUp() override {
    fs::create_directories(dir_.path() / "work");
    fs::create_directories(dir_.path() / "logs");
  }
  fs::path work() const { return dir_.path() / "work"; }
  fs::path logs() const { return dir_.path() / "logs"; }

  // A failing invocation: exit code 1, one line on stderr, "lpvlab: error: ...", nothing written.
  std::string expectOneErrorLine(const std::string& args) {
    const Result r = runLpvlab(args, work(), logs());
    EXPECT_NE(r.exitCode, 0) << args;
    const std::vector<std::string> errLines = lines(r.err);
    EXPECT_EQ(errLines.size(), 1u) << "stderr of lpvlab " << args << ":\n" << r.err;
    EXPECT_EQ(r.err.rfind("lpvlab: error:", 0), 0u) << r.err;
    EXPECT_TRUE(entries(work()).empty()) << "lpvlab " << args << " wrote into its directory";
    return r.err;
  }

  test::TempDir dir_;
};

TEST_F(Cli, RunWritesImagesAndACompleteManifest) {
  const fs::path out = dir_.path() / "run";
  const Result r = runLpvlab("run --out " + quoted(out.string()) +
                                 " -s output.width=64 -s output.height=64 -s timing.warmup=0"
                                 " -s timing.repeats=1 -s grid.resolution=8"
                                 " -s propagation.iterations=4",
                             work(), logs());
  ASSERT_EQ(r.exitCode, 0) << "stdout:\n" << r.out << "\nstderr:\n" << r.err;
  EXPECT_TRUE(entries(work()).empty()) << "--out was given: nothing in the current directory";
  EXPECT_EQ(entries(out), (std::vector<std::string>{"combined.png", "images.exr", "manifest.json"}));
  for (const std::string& name : entries(out)) {
    EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "leftover temporary " << name;
    EXPECT_GT(fs::file_size(out / name), 0u) << name;
  }
  EXPECT_NE(r.out.find("propagation"), std::string::npos) << "the timing table is printed";

  nlohmann::json manifest;
  ASSERT_NO_THROW(manifest = nlohmann::json::parse(readFile(out / "manifest.json")));
  const nlohmann::json* median = find(manifest, {"timing", "stage_ms", "propagation", "median"});
  ASSERT_TRUE(median && median->is_number());
  EXPECT_GE(median->get<double>(), 0.0);
  // Each stage's time says its clock, by where the stage ran (issue 35: CPU times were called GPU
  // times): the raster passes on GL, propagation where compute says, the total both if they differ.
  const nlohmann::json* clock = find(manifest, {"timing", "clock"});
  const nlohmann::json* where = find(manifest, {"compute", "strategies", "propagation"});
  ASSERT_TRUE(clock && where) << manifest.dump(1);
  const std::string propagationClock = *where == "cpu" ? "cpu_wall_clock" : "gl_timer_query";
  EXPECT_EQ(clock->value("propagation", ""), propagationClock);
  EXPECT_EQ(clock->value("gbuffer", ""), "gl_timer_query");
  EXPECT_EQ(clock->value("total", ""), propagationClock == "gl_timer_query" ? "gl_timer_query" : "mixed");
  EXPECT_NE(r.out.find(propagationClock == "cpu_wall_clock" ? "CPU wall clock" : "GL timer query"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("gpu median"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("times: GL timer queries on "), std::string::npos) << r.out;
  const nlohmann::json* iterations = find(manifest, {"configuration", "propagation", "iterations"});
  ASSERT_TRUE(iterations);
  EXPECT_EQ(*iterations, 4);
  const nlohmann::json* resolution = find(manifest, {"configuration", "grid", "resolution"});
  ASSERT_TRUE(resolution);
  EXPECT_EQ(*resolution, 8);
  const nlohmann::json* hash = find(manifest, {"scene", "hash"});
  ASSERT_TRUE(hash && hash->is_string());
  EXPECT_FALSE(hash->get<std::string>().empty());
  const nlohmann::json* revision = find(manifest, {"git_revision"});
  ASSERT_TRUE(revision && revision->is_string());
  EXPECT_FALSE(revision->get<std::string>().empty());
  const nlohmann::json* renderer = find(manifest, {"libraries", "gl_renderer"});
  ASSERT_TRUE(renderer && renderer->is_string());
  EXPECT_FALSE(renderer->get<std::string>().empty());
  const nlohmann::json* memory = find(manifest, {"memory_bytes", "total"});
  ASSERT_TRUE(memory && memory->is_number());
  EXPECT_GT(memory->get<double>(), 0.0);
  const nlohmann::json* rsm = find(manifest, {"injection_flux_W", "rsm"});
  const nlohmann::json* grid = find(manifest, {"injection_flux_W", "grid"});
  ASSERT_TRUE(rsm && grid);
  EXPECT_GT(rsm->get<double>(), 0.0);
  EXPECT_NEAR(grid->get<double>(), rsm->get<double>(), 1e-4 * rsm->get<double>());
}

// -q keeps stderr to warnings and errors, -v adds how the run was set up; stdout (the results)
// is the same at every level; LPVLAB_LOG_LEVEL sets the level where no flag does, and a bad one
// is named.
TEST_F(Cli, QuietAndVerboseSetWhatStderrShows) {
  const std::string small = " -s output.width=32 -s output.height=32 -s timing.warmup=0 -s timing.repeats=1"
                            " -s grid.resolution=8 -s propagation.iterations=4 -s reference.compare=true"
                            " -s reference.samples=2 --force --out " + quoted((dir_.path() / "run").string());
  const Result normal = runLpvlab("run" + small, work(), logs());
  ASSERT_EQ(normal.exitCode, 0) << normal.err;
  EXPECT_NE(normal.err.find("lpvlab: cornell_box on "), std::string::npos) << normal.err;
  EXPECT_EQ(normal.err.find(": reused ("), std::string::npos) << "a debug line at the default level:\n" << normal.err;

  const Result quiet = runLpvlab("run -q" + small, work(), logs());
  ASSERT_EQ(quiet.exitCode, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "") << "-q printed notes or progress";
  EXPECT_NE(quiet.out.find("propagation"), std::string::npos) << "-q hid the results:\n" << quiet.out;
  EXPECT_EQ(lines(quiet.out).size(), lines(normal.out).size());

  const Result verbose = runLpvlab("--verbose run" + small, work(), logs());
  ASSERT_EQ(verbose.exitCode, 0) << verbose.err;
  EXPECT_NE(verbose.err.find("lpvlab: reference "), std::string::npos) << verbose.err;
  EXPECT_NE(verbose.err.find(": reused ("), std::string::npos) << "the cache's decision:\n" << verbose.err;
  EXPECT_NE(verbose.err.find("lpvlab: raster passes: "), std::string::npos) << verbose.err;

  const Result byEnvironment = runLpvlab("run" + small, work(), logs(), "LPVLAB_LOG_LEVEL=quiet");
  EXPECT_EQ(byEnvironment.err, "");
  // Errors show at every level, as one line.
  const Result failing = runLpvlab("run -q -s grid.resolution=0", work(), logs());
  EXPECT_NE(failing.exitCode, 0);
  EXPECT_EQ(failing.err.rfind("lpvlab: error: ", 0), 0u) << failing.err;
  EXPECT_NE(failing.err.find("grid.resolution"), std::string::npos) << failing.err;
  for (const char* bad : {"run -q -v", "--quiet list --verbose"})
    EXPECT_NE(expectOneErrorLine(bad).find("excludes"), std::string::npos) << bad;
  const Result badLevel = runLpvlab("list", work(), logs(), "LPVLAB_LOG_LEVEL=loud");
  EXPECT_NE(badLevel.exitCode, 0);
  EXPECT_NE(badLevel.err.find("LPVLAB_LOG_LEVEL: 'loud'"), std::string::npos) << badLevel.err;
}

TEST_F(Cli, MissingExperimentFileIsOneErrorLineAndNoOutput) {
  const std::string err = expectOneErrorLine("run nonexistent.toml");
  EXPECT_NE(err.find("nonexistent.toml"), std::string::npos) << err;
  // With --out given, the directory is not created either.
  const fs::path out = dir_.path() / "never";
  expectOneErrorLine("run nonexistent.toml --out " + quoted(out.string()));
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, UnknownOverrideKeyIsNamed) {
  const std::string err = expectOneErrorLine("run -s propagation.bogus=1");
  EXPECT_NE(err.find("propagation.bogus"), std::string::npos) << err;
}

TEST_F(Cli, UnknownStrategyIsNamedWithTheKnownOnes) {
  const std::string err = expectOneErrorLine("run -s propagation.type=nope");
  EXPECT_NE(err.find("nope"), std::string::npos) << err;
  EXPECT_NE(err.find("standard"), std::string::npos) << err;
}

// A composition that cannot work stops before running, naming the strategy, the key and why.
TEST_F(Cli, ImpossibleCompositionIsRefusedWithTheReason) {
  const std::string sky = expectOneErrorLine("run -s 'sky.radiance=[1, 1, 1]'");
  EXPECT_NE(sky.find("[sky] radiance"), std::string::npos) << sky;
  EXPECT_NE(sky.find("[[injection.also]]"), std::string::npos) << sky;
}

TEST_F(Cli, ListNamesEveryStageAndItsStrategies) {
  const Result r = runLpvlab("list", work(), logs());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* expected : {"[injection] type =", "[occlusion] type =", "[propagation] type =",
                               "[rendering] type =", "rsm_vpl:", "sky_columns:", "none:",
                               "geometry_volume:", "standard:", "directed:", "tetrahedral:",
                               "trilinear:", "glossy:"})
    EXPECT_NE(r.out.find(expected), std::string::npos) << expected << " missing from:\n" << r.out;
  // Whether each has a CPU kernel: every shipped strategy has one, each entry says so.
  std::size_t entries = 0;
  for (std::size_t at = r.out.find("(CPU backend: "); at != std::string::npos;
       at = r.out.find("(CPU backend: ", at + 1)) {
    ++entries;
    EXPECT_EQ(r.out.compare(at, 18, "(CPU backend: yes)"), 0) << r.out.substr(at, 80);
  }
  EXPECT_GE(entries, 10u) << r.out;  // 10 strategies in 4 stages
  // Those that draw with GL on any backend say so, on the line after their CPU line (a run without
  // GL refuses them); the others don't.
  for (const char* name : {"sky_columns:", "subsurface:", "rsm_vpl:", "standard:"}) {
    const std::size_t cpuLine = r.out.find("(CPU backend: ", r.out.find(name));
    const std::size_t next = r.out.find('\n', cpuLine) + 1;
    const bool drawsWithGl = std::string(name) == "sky_columns:" || std::string(name) == "subsurface:";
    EXPECT_EQ(r.out.compare(next, 47, "      (needs GL, whatever the backend: it draws") == 0, drawsWithGl)
        << name << "\n" << r.out.substr(cpuLine, 200);
  }
  // Each strategy's parameters with their defaults (by name), printed as written (a float's 0.02 is not
  // 0.019999999552965164).
  for (const char* expected : {"dilation = true, gpu_kernel = \"simple\", iterations = 32, method = \"gather\", region_angle_deg = 10, release = true",
                               "shift = 1", "normal_offset = 0"})
    EXPECT_NE(r.out.find(expected), std::string::npos) << expected << " missing from:\n" << r.out;
  EXPECT_EQ(r.out.find("999999"), std::string::npos) << "float noise in:\n" << r.out;
}

TEST_F(Cli, RunAndBenchSayWhereTheKernelsRan) {
  const fs::path out = dir_.path() / "run";
  const Result r = runLpvlab("run --out " + quoted(out.string()) +
                                 " -s output.width=32 -s output.height=32 -s timing.warmup=0"
                                 " -s timing.repeats=1 -s grid.resolution=8",
                             work(), logs());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // On llvmpipe "auto" runs direct light and every strategy of the default composition on the CPU.
  EXPECT_NE(r.err.find("compute: cpu where possible; on the CPU: direct, injection, occlusion, "
                       "propagation, rendering"),
            std::string::npos)
      << r.err;
  const nlohmann::json manifest = nlohmann::json::parse(readFile(out / "manifest.json"));
  const nlohmann::json* propagation = find(manifest, {"compute", "strategies", "propagation"});
  ASSERT_TRUE(propagation);
  EXPECT_EQ(*propagation, "cpu");
  const nlohmann::json* direct = find(manifest, {"compute", "direct"});
  ASSERT_TRUE(direct);
  EXPECT_EQ(*direct, "cpu");
  ASSERT_TRUE(find(manifest, {"work", "propagation"}));
}

TEST_F(Cli, BenchTracerMeasuresEachInstructionSetAndWidthAskedFor) {
  const Result r = runLpvlab("bench --tracer -s output.width=16 -s output.height=16"
                             " -s timing.repeats=1 --spp 1 --isa sse4.2,auto --packet-width 1,4",
                             work(), logs());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* row : {"\nsse4.2   1 ", "\nsse4.2   4 "})
    EXPECT_NE(r.out.find(row), std::string::npos) << row << " in\n" << r.out;
  EXPECT_EQ(lines(r.out).size(), 2u + 4u) << r.out;  // title, column names, 2 x 2 rows
}

TEST_F(Cli, BenchTracerRefusesUnknownInstructionSetsAndWidthsBeforeMeasuring) {
  const std::string isa = expectOneErrorLine("bench --tracer --isa avx2,avx9");
  EXPECT_NE(isa.find("--isa"), std::string::npos) << isa;
  EXPECT_NE(isa.find("'avx9'"), std::string::npos) << isa;
  const std::string width = expectOneErrorLine("bench --tracer --packet-width 3");
  EXPECT_NE(width.find("--packet-width"), std::string::npos) << width;
}

}  // namespace
}  // namespace lpvlab

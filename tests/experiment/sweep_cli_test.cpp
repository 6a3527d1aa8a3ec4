// `lpvlab sweep` end to end, as a user runs it (the executable, found like cli_test.cpp does):
// every configuration runs into DIR/<id>/ and summary.csv has one row per configuration and
// repeat with the shared schema; a configuration whose manifest is missing is redone and no other;
// a sweep killed mid-way and rerun loses and duplicates nothing; a failing configuration is
// reported (error.log) without stopping the others; --emit slurm writes a job array, runs nothing.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "executable_support.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

using test::lpvlabExecutable;
using test::quoted;
using test::readFile;

using Result = test::LpvlabResult;

// lpvlab ARGS run in (and logging into) `dir`.
Result runLpvlab(const std::string& args, const fs::path& dir,
                 const std::string& environment = "") {
  return test::runLpvlab(args, dir, dir, environment);
}

// RFC 4180 fields: quoted where they hold a comma or quote (names like "a=1,b=2" do).
std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> out(1);
  bool inQuotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (inQuotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
      else if (c == '"') inQuotes = false;
      else out.back() += c;
    } else if (c == '"') {
      inQuotes = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

struct Csv {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
};

Csv readCsv(const fs::path& path) {
  Csv csv;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return csv;
  csv.header = splitCsvLine(line);
  while (std::getline(in, line)) {
    const auto fields = splitCsvLine(line);
    EXPECT_EQ(fields.size(), csv.header.size()) << line;
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < fields.size() && i < csv.header.size(); ++i) row[csv.header[i]] = fields[i];
    csv.rows.push_back(row);
  }
  return csv;
}

// (config_id, repeat, every param.* column): what must not change when runs are redone.
std::set<std::string> identity(const Csv& csv) {
  std::set<std::string> out;
  for (const auto& row : csv.rows) {
    std::string key;
    for (const auto& [column, value] : row)
      if (column == "config_id" || column == "repeat" || column == "config_name" ||
          column.rfind("param.", 0) == 0)
        key += column + "=" + value + ";";
    out.insert(key);
  }
  return out;
}

// The run directories of a sweep directory (everything but configs/ and logs/).
std::vector<fs::path> runDirs(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_directory() && e.path().filename() != "configs" && e.path().filename() != "logs")
      out.push_back(e.path());
  return out;
}

class SweepCli : public ::testing::Test {
protected:
  // Three configurations of the built-in Cornell box, tiny; two timed repeats each.
  std::string writeSweep(const std::string& name, const std::string& sweep) {
    const std::string path = dir_.file(name);
    std::ofstream(path) << "[output]\nwidth = 16\nheight = 16\n[grid]\nresolution = 4\n"
                           "[light_maps]\nrsm_resolution = 16\nshadow_resolution = 32\n"
                           "[timing]\nwarmup = 0\nrepeats = 2\n[sweep]\n"
                        << sweep;
    return path;
  }
  test::TempDir dir_;
};

TEST_F(SweepCli, RunsEveryConfigurationWritesSummaryAndRedoesOnlyTheInterruptedOne) {
  const std::string file = writeSweep("abl.toml", "product = { \"propagation.iterations\" = [1, 2, 4] }\n");
  const fs::path out = dir_.path() / "sweep";
  const std::string args = "sweep " + quoted(file) + " --jobs 1 --out " + quoted(out.string());
  const Result first = runLpvlab(args, dir_.path());
  ASSERT_EQ(first.exitCode, 0) << first.err;
  const auto dirs = runDirs(out);
  ASSERT_EQ(dirs.size(), 3u);
  for (const fs::path& d : dirs) {
    EXPECT_TRUE(fs::exists(d / "manifest.json")) << d;
    EXPECT_TRUE(fs::exists(d / "images.exr")) << d;
    EXPECT_FALSE(fs::exists(d / "error.log")) << d;
    EXPECT_TRUE(fs::exists(out / "configs" / (d.filename().string() + ".toml"))) << d;
  }
  const Csv before = readCsv(out / "summary.csv");
  ASSERT_EQ(before.rows.size(), 6u);
  const std::vector<std::string> leading = {"config_id", "config_name", "repeat", "run_dir",
                                            "param.propagation.iterations", "param.indirect.method",
                                            "param.injection.type",
                                            "param.occlusion.type", "param.propagation.type",
                                            "param.rendering.type", "param.grid.resolution",
                                            "param.grid.sh_order", "param.cascades.levels",
                                            "param.scene.file"};
  ASSERT_GE(before.header.size(), leading.size());
  for (std::size_t i = 0; i < leading.size(); ++i) EXPECT_EQ(before.header[i], leading[i]);
  for (const char* column : {"time.total.ms", "time.total.clock", "wall_ms.total",
                             "time.propagation.ms", "time.propagation.clock", "timed_on.gl",
                             "timed_on.cpu", "memory_bytes",
                             "memory_bytes.light_grid", "memory_bytes.light_maps", "cells"})
    EXPECT_NE(std::find(before.header.begin(), before.header.end(), column), before.header.end()) << column;
  // The stages' columns in the order the pipeline ran them (not alphabetical), then the sums: the
  // method's stages, the shared ones (raster passes, direct light), the total.
  std::vector<std::string> timed;
  for (const std::string& column : before.header)
    if (column.rfind("time.", 0) == 0 && column.size() > 8 && column.substr(column.size() - 3) == ".ms")
      timed.push_back(column);
  EXPECT_EQ(timed, (std::vector<std::string>{"time.shadow_maps.ms", "time.rsm.ms", "time.gbuffer.ms",
                                             "time.direct.ms", "time.clear.ms", "time.occlusion.ms",
                                             "time.injection.ms", "time.propagation.ms",
                                             "time.indirect.ms", "time.method.ms",
                                             "time.shared.ms", "time.total.ms"}));
  std::set<std::string> iterations;
  for (const auto& row : before.rows) {
    iterations.insert(row.at("param.propagation.iterations"));
    // The method's time is its five stages' sum, the shared time the pipeline's four, and the
    // two make the total (each rounded by the CSV's number format: to 1e-9 ms).
    double method = 0.0, shared = 0.0;
    for (const char* stage : {"clear", "occlusion", "injection", "propagation", "indirect"})
      method += std::stod(row.at(std::string("time.") + stage + ".ms"));
    for (const char* stage : {"shadow_maps", "rsm", "gbuffer", "direct"})
      shared += std::stod(row.at(std::string("time.") + stage + ".ms"));
    EXPECT_NEAR(std::stod(row.at("time.method.ms")), method, 1e-9 * (1 + method));
    EXPECT_NEAR(std::stod(row.at("time.shared.ms")), shared, 1e-9 * (1 + shared));
    EXPECT_NEAR(std::stod(row.at("time.total.ms")), method + shared, 1e-9 * (1 + method + shared));
    EXPECT_EQ(row.at("param.grid.resolution"), "4");
    EXPECT_EQ(row.at("cells").empty(), false);
    EXPECT_FALSE(row.at("time.total.ms").empty());
    EXPECT_FALSE(row.at("timed_on.gl").empty());
    EXPECT_TRUE(row.at("time.propagation.clock") == "gl_timer_query" ||
                row.at("time.propagation.clock") == "cpu_wall_clock")
        << row.at("time.propagation.clock");
  }
  EXPECT_EQ(iterations, (std::set<std::string>{"1", "2", "4"}));
  // Sorted by config id, then repeat.
  for (std::size_t i = 1; i < before.rows.size(); ++i)
    EXPECT_LE(before.rows[i - 1].at("config_id") + before.rows[i - 1].at("repeat"),
              before.rows[i].at("config_id") + before.rows[i].at("repeat"));

  // Interrupt one (its manifest gone): only that one is redone.
  std::map<std::string, std::string> manifests;
  for (const fs::path& d : dirs) manifests[d.filename().string()] = readFile(d / "manifest.json");
  const std::string victim = dirs[1].filename().string();
  fs::remove(dirs[1] / "manifest.json");
  std::ofstream(dirs[1] / "stale.tmp") << "left by the interrupted run";
  const Result second = runLpvlab(args, dir_.path());
  ASSERT_EQ(second.exitCode, 0) << second.err;
  EXPECT_NE(second.err.find("2 complete, 1 to run"), std::string::npos) << second.err;
  for (const auto& [id, text] : manifests) {
    const std::string now = readFile(out / id / "manifest.json");
    if (id == victim) {
      EXPECT_FALSE(now.empty());
      EXPECT_NE(now, text);  // a new run (new timestamp, timings)
      EXPECT_FALSE(fs::exists(out / id / "stale.tmp"));  // redone from scratch
    } else {
      EXPECT_EQ(now, text) << id << " was run again";
    }
  }
  const Csv after = readCsv(out / "summary.csv");
  EXPECT_EQ(after.header, before.header);
  EXPECT_EQ(identity(after), identity(before));

  // `lpvlab summary` rebuilds the same table; an incomplete directory is skipped and named.
  fs::create_directories(out / "deadbeef00");
  const Result summary = runLpvlab("summary " + quoted(out.string()), dir_.path());
  ASSERT_EQ(summary.exitCode, 0) << summary.err;
  EXPECT_NE(summary.err.find("deadbeef00"), std::string::npos) << summary.err;
  EXPECT_EQ(identity(readCsv(out / "summary.csv")), identity(before));
}

TEST_F(SweepCli, KilledSweepResumesWithoutLossOrDuplication) {
  const std::string file = writeSweep("kill.toml", "zip = { \"propagation.iterations\" = [1, 2, 3], "
                                                   "\"grid.resolution\" = [4, 5, 6] }\n");
  const fs::path out = dir_.path() / "sweep";
  ASSERT_TRUE(fs::exists(lpvlabExecutable()));
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string exe = lpvlabExecutable().string();
    freopen("/dev/null", "w", stdout);
    freopen("/dev/null", "w", stderr);
    execl(exe.c_str(), exe.c_str(), "sweep", file.c_str(), "--jobs", "1", "--out", out.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Kill it as soon as the first configuration is complete.
  bool sawManifest = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!sawManifest && std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(out))
      for (const fs::path& d : runDirs(out)) sawManifest = sawManifest || fs::exists(d / "manifest.json");
    if (!sawManifest) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(sawManifest);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the child run dies with it

  const Result rerun = runLpvlab("sweep " + quoted(file) + " --jobs 2 --out " + quoted(out.string()),
                                 dir_.path());
  ASSERT_EQ(rerun.exitCode, 0) << rerun.err;
  const auto dirs = runDirs(out);
  EXPECT_EQ(dirs.size(), 3u);
  for (const fs::path& d : dirs) EXPECT_TRUE(fs::exists(d / "manifest.json")) << d;
  const Csv csv = readCsv(out / "summary.csv");
  ASSERT_EQ(csv.rows.size(), 6u);
  std::set<std::pair<std::string, std::string>> keys;
  std::set<std::string> zipped;
  for (const auto& row : csv.rows) {
    keys.insert({row.at("config_id"), row.at("repeat")});
    zipped.insert(row.at("param.grid.resolution") + "/" + row.at("param.propagation.iterations"));
  }
  EXPECT_EQ(keys.size(), 6u);  // none duplicated
  EXPECT_EQ(zipped, (std::set<std::string>{"4/1", "5/2", "6/3"}));
}

TEST_F(SweepCli, ABadSweptValueOrKeyStopsTheSweepBeforeAnythingIsWritten) {
  // Every configuration is loaded first: the error names the user's file, its [sweep] table and
  // the configuration (not a generated configs/<id>.toml), and no directory appears.
  for (const std::string& sweep :
       {std::string("product = { \"grid.resolution\" = [4, 2000, 5] }\n"),
        std::string("product = { \"grid.nothere\" = [1, 2] }\n")}) {
    const std::string file = writeSweep("bad.toml", sweep);
    const fs::path out = dir_.path() / "sweep";
    const Result r =
        runLpvlab("sweep " + quoted(file) + " --out " + quoted(out.string()), dir_.path());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find(file + ":"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("key 'sweep'"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("configs/"), std::string::npos) << r.err;
    EXPECT_NE(
        r.err.find(sweep.find("2000") != std::string::npos ? "resolution=2000" : "grid.nothere"),
        std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(SweepCli, FailingConfigurationIsReportedAndOthersComplete) {
  // A failure only the run can meet: the reference cache is a file, so the configuration that
  // compares with a reference fails in its child; the others run.
  const std::string file = writeSweep("fail.toml",
                                      "zip = { \"reference.compare\" = [false, true, false], "
                                      "\"propagation.iterations\" = [1, 2, 3] }\n");
  const fs::path out = dir_.path() / "sweep";
  const std::string cache = dir_.file("cache-is-a-file");
  std::ofstream(cache) << "not a folder\n";
  const Result r = runLpvlab("sweep " + quoted(file) + " --out " + quoted(out.string()),
                             dir_.path(), "LPVLAB_CACHE_DIR=" + quoted(cache));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("compare=true"), std::string::npos) << r.err;
  int complete = 0, failed = 0;
  for (const fs::path& d : runDirs(out)) {
    if (fs::exists(d / "manifest.json")) ++complete;
    else {
      ++failed;
      EXPECT_NE(readFile(d / "error.log").find("cache-is-a-file"), std::string::npos)
          << readFile(d / "error.log");
    }
  }
  EXPECT_EQ(complete, 2);
  EXPECT_EQ(failed, 1);
  EXPECT_EQ(readCsv(out / "summary.csv").rows.size(), 4u);
}

TEST_F(SweepCli, EmitSlurmWritesAJobArrayAndRunsNothing) {
  const std::string file = writeSweep("slurm.toml", "product = { \"propagation.iterations\" = [1, 2, 4] }\n");
  const fs::path out = dir_.path() / "sweep";
  const Result r = runLpvlab("sweep " + quoted(file) + " --emit slurm --out " + quoted(out.string()), dir_.path());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string script = readFile(out / "sweep.slurm");
  EXPECT_NE(script.find("#SBATCH --array=0-2"), std::string::npos) << script;
  EXPECT_NE(script.find("manifest.json"), std::string::npos);
  EXPECT_TRUE(runDirs(out).empty());
  int configs = 0;
  for (const auto& e : fs::directory_iterator(out / "configs")) {
    ++configs;
    EXPECT_NE(script.find(e.path().stem().string()), std::string::npos);
  }
  EXPECT_EQ(configs, 3);
}

}  // namespace
}  // namespace lpvlab

// `lpvlab tune` as a user runs it, on a tiny Cornell box: it writes tune.json, pareto.csv and
// chosen.toml, whose configuration runs when included and is the best within the goal of those
// measured at the last rung; an interrupted tune resumes with the runs it has; another tune in
// the directory is refused; a bad [tune] table is one error naming the key.

#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "executable_support.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;
using test::quoted;

// A tiny Cornell box: the baseline of the tunes below.
const std::string kTinyBox = R"(
[output]
width = 32
height = 32
[grid]
resolution = 8
[light_maps]
rsm_resolution = 32
)";

const std::string kTune = kTinyBox + R"(
[tune]
budget_ms = "baseline"
candidates = 3
eta = 2
rungs = [2, 4]
[tune.space]
"grid.resolution" = [6, 10]
"propagation.iterations" = { min = 2, max = 12 }
[[tune.held_out]]
name = "lower"
camera = { position = [0.278, 0.2, -0.4], look_at = [0.278, 0.25, 0.3], fov_deg = 50.0 }
)";

TEST(TuneCommand, ChoosesWithinTheGoalWritesItsFilesAndResumes) {
  test::TempDir dir;
  std::ofstream(dir.file("tune.toml")) << kTune;
  const fs::path out = dir.path() / "tuned";
  const std::string args = "tune tune.toml --out " + quoted(out.string());
  const test::LpvlabResult r = test::runLpvlab(args, dir.path(), dir.path());
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const nlohmann::json result = nlohmann::json::parse(test::readFile(out / "tune.json"));
  ASSERT_EQ(result["rungs"].size(), 2u);
  EXPECT_EQ(result["rungs"][0]["results"].size(), 4u);  // the baseline and 3 candidates
  EXPECT_EQ(result["rungs"][0]["promoted"].size(), 2u);  // ceil(3 / 2)
  EXPECT_EQ(result["rungs"][1]["results"].size(), 3u);  // the baseline and the 2 promoted
  // The chosen one is the most accurate of the last rung's within its budget (the baseline's time).
  const double budget = result["rungs"][1]["budget_ms"].get<double>();
  double best = 1e300;
  for (const nlohmann::json& x : result["rungs"][1]["results"])
    if (x["ms"].get<double>() <= budget) best = std::min(best, x["error"].get<double>());
  ASSERT_TRUE(result["chosen"].is_object()) << r.out;
  EXPECT_EQ(result["chosen"]["error"].get<double>(), best);
  EXPECT_TRUE(result["held_out"]["lower"]["chosen"].is_object());
  EXPECT_TRUE(result["held_out"]["lower"]["baseline"].is_object());
  EXPECT_NE(test::readFile(out / "pareto.csv").find("rung,samples,id,error,ms"), std::string::npos);

  // chosen.toml is a file an experiment includes.
  std::ofstream(dir.file("use.toml")) << "include = [\"" << (out / "chosen.toml").string()
                                      << "\"]\n[output]\nwidth = 32\nheight = 32\n";
  const test::LpvlabResult use = test::runLpvlab(
      "run use.toml -s timing.warmup=0 -s timing.repeats=1 --out " + quoted((dir.path() / "use").string()),
      dir.path(), dir.path());
  EXPECT_EQ(use.exitCode, 0) << use.err;

  // Interrupted: the last rung's summary and one of its runs gone; the rest is reused.
  fs::remove(out / "tune.json");
  fs::remove_all(out / "rungs" / "1" / "baseline");
  const test::LpvlabResult resumed = test::runLpvlab(args, dir.path(), dir.path());
  ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("4 runs, 4 already done"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("3 runs, 2 already done"), std::string::npos) << resumed.err;
  // Finished: not redone without --force; another tune is refused.
  const test::LpvlabResult again = test::runLpvlab(args, dir.path(), dir.path());
  EXPECT_EQ(again.exitCode, 1);
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
}

// time = "gpu-estimate": the times are the GPU estimate of each run's counted GL-kernel work
// (analysis/gpu_estimate.py), which grows with the grid; the budget is the baseline's estimate, so
// the larger grid is over it and the smaller within it, whatever this machine's timing noise.
TEST(TuneCommand, AGpuEstimatedTuneRanksByTheEstimateAndSaysSo) {
  test::TempDir dir;
  std::ofstream(dir.file("tune.toml")) << kTinyBox << R"(
[tune]
budget_ms = "baseline"
time = "gpu-estimate"
gpu = "h100_sxm"
candidates = 3
rungs = [2]
[tune.space]
"grid.resolution" = [6, 12]
)";
  const fs::path out = dir.path() / "tuned";
  const test::LpvlabResult r = test::runLpvlab("tune tune.toml --out " + quoted(out.string()), dir.path(), dir.path());
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const nlohmann::json result = nlohmann::json::parse(test::readFile(out / "tune.json"));
  EXPECT_EQ(result["time"], "gpu-estimate");
  EXPECT_EQ(result["gpu"], "h100_sxm");
  EXPECT_NE(result["clock"].get<std::string>().find("not a measurement"), std::string::npos) << result["clock"];
  EXPECT_NE(result["goal"].get<std::string>().find("GPU-estimated"), std::string::npos) << result["goal"];
  std::map<std::string, double> ms;
  for (const nlohmann::json& x : result["rungs"][0]["results"]) {
    const auto& overrides = result["candidates"][x["id"].get<std::string>()];
    ms[overrides.empty() ? "8" : overrides[0].get<std::string>().substr(std::string("grid.resolution=").size())] =
        x["ms"].get<double>();
    EXPECT_EQ(x["feasible"].get<bool>(), x["ms"].get<double>() <= result["rungs"][0]["budget_ms"].get<double>());
  }
  ASSERT_EQ(ms.size(), 3u) << result.dump(2);
  EXPECT_GT(ms["6"], 0.0);
  EXPECT_LT(ms["6"], ms["8"]);
  EXPECT_LT(ms["8"], ms["12"]);
  EXPECT_EQ(result["rungs"][0]["budget_ms"].get<double>(), ms["8"]);
  ASSERT_TRUE(result["chosen"].is_object());
  EXPECT_LE(result["chosen"]["ms"].get<double>(), ms["8"]) << "never the grid over the estimated budget";

  // A GPU the estimate does not know: one error naming the key, before anything is written.
  std::ofstream(dir.file("bad_gpu.toml")) << "[tune]\nbudget_ms = 5.0\ntime = \"gpu-estimate\"\ngpu = \"nope\"\n"
                                             "[tune.space]\n\"grid.resolution\" = [6]\n";
  const test::LpvlabResult bad =
      test::runLpvlab("tune bad_gpu.toml --out " + quoted((dir.path() / "x").string()), dir.path(), dir.path());
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find("tune.gpu"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("not a GPU of"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir.path() / "x" / "tune_state.json"));
}

// [tune.fit]: the chosen configuration's face solid angles fitted by lpvlab fit on the tuned
// view, measured there, and adopted only where more accurate within the goal; started again, the
// tune reuses the finished fit.
TEST(TuneCommand, TheChosenConstantsAreFittedAndAdoptedOnlyWhenMoreAccurate) {
  test::TempDir dir;
  std::ofstream(dir.file("tune.toml")) << kTinyBox << R"(
[tune]
budget_ms = "baseline"
candidates = 2
rungs = [4]
[tune.space]
"propagation.iterations" = [4, 8]
[tune.fit]
parameters = [
  { key = "propagation.far_face_solid_angle", lower = 0.05, upper = 1.0 },
  { key = "propagation.side_face_solid_angle", lower = 0.05, upper = 0.5 },
]
max_iterations = 3
)";
  const fs::path out = dir.path() / "tuned";
  const std::string args = "tune tune.toml --out " + quoted(out.string());
  const test::LpvlabResult r = test::runLpvlab(args, dir.path(), dir.path());
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const nlohmann::json result = nlohmann::json::parse(test::readFile(out / "tune.json"));
  ASSERT_TRUE(result.contains("fit")) << result.dump(2);
  const nlohmann::json& fit = result["fit"];
  ASSERT_EQ(fit["parameters"].size(), 2u);
  EXPECT_TRUE(fs::exists(out / "fit" / "fit.json"));
  ASSERT_TRUE(fit["after"].is_object()) << fit.dump(2);
  const double before = fit["before"]["error"].get<double>(), after = fit["after"]["error"].get<double>();
  // The search drew no constants: the fit started from the shipped ones.
  EXPECT_NEAR(fit["parameters"][0]["before"].get<double>(), 0.40066968, 1e-6);
  const std::string chosenToml = test::readFile(out / "chosen.toml");
  if (fit["adopted"].get<bool>()) {
    EXPECT_LT(after, before);
    EXPECT_EQ(result["chosen"]["error"].get<double>(), after);
    EXPECT_NE(chosenToml.find("far_face_solid_angle"), std::string::npos) << chosenToml;
  } else {
    EXPECT_EQ(result["chosen"]["error"].get<double>(), before);
    EXPECT_EQ(chosenToml.find("far_face_solid_angle"), std::string::npos) << chosenToml;
  }
  // Started again without its summary: the finished fit and every run are reused.
  EXPECT_NE(r.err.find("fitting the chosen configuration"), std::string::npos) << r.err;
  fs::remove(out / "tune.json");
  const test::LpvlabResult resumed = test::runLpvlab(args, dir.path(), dir.path());
  ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
  EXPECT_EQ(resumed.err.find("fitting the chosen configuration"), std::string::npos) << resumed.err;
  EXPECT_EQ(nlohmann::json::parse(test::readFile(out / "tune.json"))["chosen"], result["chosen"]);
}

TEST(TuneCommand, ABadTableIsOneErrorNamingTheKey) {
  test::TempDir dir;
  std::ofstream(dir.file("bad.toml")) << "[tune]\nbudget_ms = 10.0\n[tune.space]\n\"grid.resolution\" = [8, -3]\n";
  const test::LpvlabResult r = test::runLpvlab("tune bad.toml --out " + quoted((dir.path() / "x").string()),
                                               dir.path(), dir.path());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("grid.resolution"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "x" / "tune_state.json")) << "checked before anything was written";
  const test::LpvlabResult both =
      test::runLpvlab("tune bad.toml --budget-ms 5 --error 0.1", dir.path(), dir.path());
  EXPECT_NE(both.exitCode, 0);
  EXPECT_NE(both.err.find("one goal"), std::string::npos) << both.err;
}

}  // namespace
}  // namespace lpvlab

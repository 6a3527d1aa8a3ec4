// SIGKILL at random moments of `lpvlab reference`, `lpvlab fit` and an animated `lpvlab run`, then
// the same command again until it finishes. Nothing is lost (the result equals an uninterrupted
// run's) and nothing is duplicated (one cache entry, no leftover temporaries, every fit iteration
// logged once, every frame once with the temporal figures of an uninterrupted run).
// The kill times come from a seed printed with each test: LPVLAB_KILL_SEED=N repeats a run.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "executable_support.h"
#include "framework/experiment/sequence.h"
#include "framework/io/image.h"
#include "framework/reference/reference_cache.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::uint32_t killSeed() {
  if (const char* env = std::getenv("LPVLAB_KILL_SEED")) return std::uint32_t(std::stoul(env));
  return std::random_device{}();
}

// Says, polled every 2 ms while a run goes on, whether the moment kills are timed from has come.
using Armed = std::function<bool()>;

// Runs `lpvlab ARGS` with its output appended to `log`; kills it with SIGKILL `killAfter` seconds
// after `armed` first holds (after the start when it is empty) unless it ended before. Returns
// true when it ended on its own with exit code 0; `seconds` gets the time from that moment to the
// end.
bool runLpvlab(const std::vector<std::string>& args, const fs::path& log, double killAfter,
               double* seconds = nullptr, const Armed& armedBy = {}) {
  const std::string exe = test::lpvlabExecutable().string();
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    std::FILE* out = std::fopen(log.c_str(), "a");
    if (out) {
      dup2(fileno(out), 1);
      dup2(fileno(out), 2);
    }
    std::vector<char*> argv = {const_cast<char*>(exe.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  std::optional<Clock::time_point> armed, deadline;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (!armed && (!armedBy || armedBy())) {
      armed = Clock::now();
      deadline = *armed + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(killAfter));
    }
    if (deadline && Clock::now() >= *deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (seconds && armed) *seconds = std::chrono::duration<double>(Clock::now() - *armed).count();
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// Armed once `path` exists: for every run alike.
std::function<Armed()> whenExists(const fs::path& path) {
  return [path] { return Armed([path] { return fs::exists(path); }); };
}

// Kills the command `kills` times, each at a uniformly random moment of the first `window`
// seconds after the run's `armedFor()` holds (a checkpoint: so that every kill but an early one
// leaves something to resume from), then lets it finish. Returns the number of kills that landed
// (the others found it done). A kill can land after the command finished its outputs, before it
// exited: `finished` (when given) says so, and the command is not run again, since lpvlab refuses
// to write over a finished run or fit.
int killRepeatedlyThenFinish(const std::vector<std::string>& args, const fs::path& log,
                             const std::function<Armed()>& armedFor, double window, int kills,
                             std::mt19937& random, const std::function<bool()>& finished = {}) {
  std::uniform_real_distribution<double> moment(0.0, window);
  int landed = 0;
  for (int i = 0; i < kills; ++i) {
    if (runLpvlab(args, log, moment(random), nullptr, armedFor())) return landed;
    ++landed;
    if (finished && finished()) return landed;
  }
  if (finished && finished()) return landed;
  EXPECT_TRUE(runLpvlab(args, log, 1e9)) << test::readFile(log);
  return landed;
}

std::vector<fs::path> leftoverTemporaries(const fs::path& dir) {
  std::vector<fs::path> found;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) found.push_back(e.path());
  return found;
}

std::vector<fs::path> subdirectories(const fs::path& dir) {
  std::vector<fs::path> found;
  for (const fs::directory_entry& e : fs::directory_iterator(dir))
    if (e.is_directory()) found.push_back(e.path());
  return found;
}

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

class KillResume : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("lpvlab_kill_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    seed_ = killSeed();
    std::cout << "kill seed " << seed_ << " (LPVLAB_KILL_SEED=" << seed_ << " repeats it)\n";
    random_.seed(seed_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }

  fs::path dir_;
  std::uint32_t seed_ = 0;
  std::mt19937 random_;
};

TEST_F(KillResume, AKilledReferenceResumesToTheUninterruptedSums) {
  // Checkpoints after every pass (about a second each), so kills land between, during and just
  // after checkpoint writes.
  const fs::path file = write("reference.toml",
                              "[output]\nwidth = 48\nheight = 48\n"
                              "[reference]\nsamples = 1536\nthreads = 1\ncheckpoint_seconds = 0\n");
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  double seconds = 0.0;
  ASSERT_TRUE(runLpvlab({"reference", file.string(), "--cache", whole.string()}, dir_ / "whole.log",
                        1e9, &seconds))
      << test::readFile(dir_ / "whole.log");
  const std::vector<fs::path> a = subdirectories(whole);
  ASSERT_EQ(a.size(), 1u);
  const fs::path state = killed / a[0].filename() / "state.bin";
  const int landed =
      killRepeatedlyThenFinish({"reference", file.string(), "--cache", killed.string()},
                               dir_ / "killed.log", whenExists(state), 0.3 * seconds, 5, random_);
  std::cout << landed << " kills landed in a " << seconds << " s rendering\n";
  EXPECT_GE(landed, 1);
  EXPECT_NE(test::readFile(dir_ / "killed.log").find("continuing from"), std::string::npos);

  const std::vector<fs::path> b = subdirectories(killed);
  ASSERT_EQ(b.size(), 1u);  // one cache entry: nothing rendered twice under another key
  EXPECT_EQ(a[0].filename(), b[0].filename());
  EXPECT_EQ(leftoverTemporaries(killed), std::vector<fs::path>{});
  const Accumulator x = loadAccumulator((a[0] / "state.bin").string());
  const Accumulator y = loadAccumulator((b[0] / "state.bin").string());
  EXPECT_EQ(y.samples, 1536);
  EXPECT_EQ(x.samples, y.samples);
  // Every sample's random numbers follow from its pixel and index, and each pixel's sums add its
  // samples in index order however the passes split them: the sums are equal to the bit.
  EXPECT_TRUE(x.sum == y.sum);
  EXPECT_TRUE(x.sumSquares == y.sumSquares);
  EXPECT_TRUE(x.firstHit == y.firstHit);
  EXPECT_EQ(readJson(b[0] / "manifest.json").at("samples_per_pixel").get<int>(), 1536);
}

TEST_F(KillResume, AKilledFitResumesToTheUninterruptedConstants) {
  const fs::path base = fs::path(LPVLAB_SOURCE_DIR) / "experiments" / "fit_cornell_box.toml";
  const fs::path file = write(
      "fit.toml",
      "extends = \"" + base.string() +
          "\"\n"
          "[output]\nwidth = 48\nheight = 48\n[light_maps]\nrsm_resolution = 48\n"
          "[grid]\nresolution = 16\n[reference]\nsamples = 32\n"
          "[fit]\nmax_iterations = 8\nparameters = [\n"
          "  { key = \"propagation.far_face_solid_angle\", lower = 0.0, upper = 2.0943951 },\n"
          "  { key = \"propagation.side_face_solid_angle\", lower = 0.0, upper = 0.5235988 } ]\n");
  setenv("LPVLAB_CACHE_DIR", (dir_ / "cache").c_str(), 1);  // the references, rendered once
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  double seconds = 0.0;
  ASSERT_TRUE(runLpvlab({"fit", file.string(), "--out", whole.string()}, dir_ / "whole.log", 1e9))
      << test::readFile(dir_ / "whole.log");
  // Timed again now that the references are cached, from the first saved iteration on, as the
  // kills are: the set-up before it (GL context, shaders, references read) takes a varying part of
  // a short run, and a window measured from the start could outlast the iterations.
  fs::remove_all(whole);
  ASSERT_TRUE(runLpvlab({"fit", file.string(), "--out", whole.string()}, dir_ / "whole.log", 1e9,
                        &seconds, whenExists(whole / "fit.progress.json")()));
  const int landed = killRepeatedlyThenFinish(
      {"fit", file.string(), "--out", killed.string()}, dir_ / "killed.log",
      whenExists(killed / "fit.progress.json"), 0.8 * seconds, 4, random_, [&] {
        return fs::exists(killed / "fit.json") && !fs::exists(killed / "fit.progress.json");
      });
  std::cout << landed << " kills landed in the " << seconds
            << " s after a fit's first saved iteration\n";
  unsetenv("LPVLAB_CACHE_DIR");
  EXPECT_GE(landed, 1);
  EXPECT_NE(test::readFile(dir_ / "killed.log").find("resuming after iteration"),
            std::string::npos);

  EXPECT_FALSE(fs::exists(killed / "fit.progress.json"));
  EXPECT_EQ(leftoverTemporaries(killed), std::vector<fs::path>{});
  const nlohmann::json a = readJson(whole / "fit.json"), b = readJson(killed / "fit.json");
  // Every iteration once, in order.
  const nlohmann::json& log = b.at("convergence");
  for (std::size_t i = 0; i < log.size(); ++i)
    EXPECT_EQ(log[i].at("iteration").get<int>(), int(i)) << log.dump();
  ASSERT_EQ(a.at("parameters").size(), b.at("parameters").size());
  EXPECT_EQ(a.at("convergence").size(), log.size());
  // A resumed solve starts from the saved iterate and trust-region radius, so it takes the same
  // steps: the constants agree to far below their standard errors.
  for (std::size_t j = 0; j < a.at("parameters").size(); ++j) {
    const double va = a["parameters"][j].at("value"), vb = b["parameters"][j].at("value");
    EXPECT_NEAR(va, vb, 1e-9 * std::max(1.0, std::abs(va))) << a["parameters"][j].at("key");
  }
}

TEST_F(KillResume, AKilledSequenceResumesToTheUninterruptedFrames) {
  const fs::path base =
      fs::path(LPVLAB_SOURCE_DIR) / "experiments" / "cornell_box_moving_block.toml";
  const fs::path file = write("sequence.toml", "extends = \"" + base.string() +
                                                   "\"\n[output]\nwidth = 48\nheight = 48\n"
                                                   "[light_maps]\nrsm_resolution = 48\n"
                                                   "[grid]\nresolution = 16\n[timing]\nwarmup = 0\n"
                                                   "[animation]\nframes = 16\nvideo = false\n");
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  // Kills are timed from the first frame record a run writes, not from its start: the GL context
  // and the shaders take a large and varying part of a short run, and a window measured from the
  // start could outlast the frames or end before the first of them.
  const auto firstNewRecord = [](const fs::path& dir) {
    return [dir] {
      const auto started = fs::file_time_type::clock::now();
      return Armed([dir, started] {
        std::error_code ignored;
        for (const fs::directory_entry& e : fs::directory_iterator(dir, ignored))
          if (e.path().extension() == ".json" && e.last_write_time(ignored) > started) return true;
        return false;
      });
    };
  };
  double seconds = 0.0;
  ASSERT_TRUE(runLpvlab({"run", file.string(), "--out", whole.string()}, dir_ / "whole.log", 1e9,
                        &seconds, firstNewRecord(whole / "frames")()))
      << test::readFile(dir_ / "whole.log");
  const int landed = killRepeatedlyThenFinish(
      {"run", file.string(), "--out", killed.string()}, dir_ / "killed.log",
      firstNewRecord(killed / "frames"), 0.8 * seconds, 4, random_,
      [&] { return fs::exists(killed / "manifest.json"); });
  std::cout << landed << " kills landed in the " << seconds
            << " s after the first frame of a sequence\n";
  EXPECT_GE(landed, 1);
  EXPECT_EQ(leftoverTemporaries(killed), std::vector<fs::path>{});
  const nlohmann::json a = readJson(whole / "manifest.json"),
                       b = readJson(killed / "manifest.json");
  const nlohmann::json& records = b.at("sequence").at("frame_records");
  ASSERT_EQ(records.size(), 16u);
  for (int frame = 0; frame < 16; ++frame) {
    // Every frame once, in order, and the image an uninterrupted run renders, to the bit.
    EXPECT_EQ(records[std::size_t(frame)].at("frame").get<int>(), frame);
    const std::string stem = frameStem(frame, 16);
    const std::vector<NamedImage> x = readExr((whole / (stem + ".exr")).string());
    const std::vector<NamedImage> y = readExr((killed / (stem + ".exr")).string());
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      EXPECT_TRUE(x[i].image.pixels == y[i].image.pixels) << stem << " " << x[i].name;
    EXPECT_EQ(records[std::size_t(frame)].at("png_exposure_stops"),
              a["sequence"]["frame_records"][std::size_t(frame)].at("png_exposure_stops"));
    // Its temporal figures too, also where the frame before was read back after a kill.
    EXPECT_EQ(
        records[std::size_t(frame)].value("temporal", nlohmann::json()),
        a["sequence"]["frame_records"][std::size_t(frame)].value("temporal", nlohmann::json()))
        << stem;
  }
}

}  // namespace
}  // namespace lpvlab

namespace lpvlab {
namespace {

// Armed once `dir` (searched recursively) holds a file named `name`, or ending so: a checkpoint.
std::function<Armed()> whenSomeFileEndsWith(const fs::path& dir, const std::string& name) {
  return [dir, name] {
    return Armed([dir, name] {
      std::error_code ignored;
      if (!fs::exists(dir, ignored)) return false;
      for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir, ignored)) {
        const std::string file = e.path().filename().string();
        if (file.size() >= name.size() && file.compare(file.size() - name.size(), name.size(), name) == 0)
          return true;
      }
      return false;
    });
  };
}

// The oracles' images are checkpointed as they are rendered: a killed explanation resumes with
// them, and its budget and exact grid are the uninterrupted one's to the bit (every oracle is
// deterministic).
TEST_F(KillResume, AKilledExplanationResumesToTheUninterruptedBudget) {
  setenv("LPVLAB_CACHE_DIR", (dir_ / "cache").c_str(), 1);
  const std::vector<std::string> small = {"-s", "output.width=64", "-s", "output.height=64",
                                          "-s", "light_maps.rsm_resolution=64", "-s", "grid.resolution=16",
                                          "-s", "reference.samples=8", "--vpls", "512"};
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  std::vector<std::string> args = {"explain", "--out", whole.string()};
  args.insert(args.end(), small.begin(), small.end());
  double seconds = 0.0;
  ASSERT_TRUE(runLpvlab(args, dir_ / "whole.log", 1e9)) << test::readFile(dir_ / "whole.log");
  fs::remove_all(whole);
  ASSERT_TRUE(runLpvlab(args, dir_ / "whole.log", 1e9, &seconds, whenSomeFileEndsWith(whole / "partial", ".exr")()));
  args[2] = killed.string();
  const int landed = killRepeatedlyThenFinish(args, dir_ / "killed.log", whenSomeFileEndsWith(killed / "partial", ".exr"),
                                              0.8 * seconds, 3, random_, [&] { return fs::exists(killed / "explain.json"); });
  unsetenv("LPVLAB_CACHE_DIR");
  std::cout << landed << " kills landed in the " << seconds << " s after the first oracle's image\n";
  EXPECT_GE(landed, 1);
  EXPECT_NE(test::readFile(dir_ / "killed.log").find("from the checkpoint"), std::string::npos);
  EXPECT_FALSE(fs::exists(killed / "partial"));
  EXPECT_EQ(leftoverTemporaries(killed), std::vector<fs::path>{});
  EXPECT_EQ(readJson(whole / "explain.json").at("budgets"), readJson(killed / "explain.json").at("budgets"));
  // The exact grid comes back from the checkpoint with its image: written, and the same.
  EXPECT_EQ(test::readFile(whole / "exact_grid.npy"), test::readFile(killed / "exact_grid.npy"));
}

// A killed tune resumes with the runs it finished: it measures, promotes and chooses as the
// uninterrupted one did (the errors are deterministic, the times are not: a budget every candidate
// meets ranks them by error alone).
TEST_F(KillResume, AKilledTuneResumesToTheUninterruptedChoice) {
  // A cache of its own for each tune: a reference cached with more samples than a rung asks for
  // is used as it is, so the second tune would compare its first rung with the first's last.
  setenv("LPVLAB_CACHE_DIR", (dir_ / "cache_whole").c_str(), 1);
  const fs::path file = write("tune.toml",
                              "[output]\nwidth = 32\nheight = 32\n[grid]\nresolution = 8\n"
                              "[light_maps]\nrsm_resolution = 32\n"
                              "[tune]\nbudget_ms = 1000000.0\ncandidates = 4\neta = 2\nrungs = [2, 4]\n"
                              "[tune.space]\n\"grid.resolution\" = [6, 8, 10, 12]\n"
                              "\"propagation.iterations\" = [2, 4, 8]\n");
  const fs::path whole = dir_ / "whole", killed = dir_ / "killed";
  double seconds = 0.0;
  ASSERT_TRUE(runLpvlab({"tune", file.string(), "--out", whole.string()}, dir_ / "whole.log", 1e9, &seconds,
                        whenSomeFileEndsWith(whole / "rungs", "manifest.json")()))
      << test::readFile(dir_ / "whole.log");
  setenv("LPVLAB_CACHE_DIR", (dir_ / "cache_killed").c_str(), 1);
  const int landed = killRepeatedlyThenFinish(
      {"tune", file.string(), "--out", killed.string()}, dir_ / "killed.log",
      whenSomeFileEndsWith(killed / "rungs", "manifest.json"), 0.8 * seconds, 3, random_,
      [&] { return fs::exists(killed / "tune.json"); });
  unsetenv("LPVLAB_CACHE_DIR");
  std::cout << landed << " kills landed in the " << seconds << " s after a tune's first run\n";
  EXPECT_GE(landed, 1);
  const nlohmann::json a = readJson(whole / "tune.json"), b = readJson(killed / "tune.json");
  ASSERT_EQ(a.at("rungs").size(), b.at("rungs").size());
  for (std::size_t r = 0; r < a["rungs"].size(); ++r) {
    EXPECT_EQ(a["rungs"][r].at("promoted"), b["rungs"][r].at("promoted")) << r;
    std::map<std::string, double> errors;
    for (const nlohmann::json& x : a["rungs"][r]["results"]) errors[x["id"]] = x["error"];
    for (const nlohmann::json& x : b["rungs"][r]["results"]) EXPECT_EQ(errors.at(x["id"]), x["error"].get<double>());
  }
  EXPECT_EQ(a.at("candidates"), b.at("candidates"));
}

}  // namespace
}  // namespace lpvlab

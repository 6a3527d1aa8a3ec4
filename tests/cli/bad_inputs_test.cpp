// Bad input through the real lpvlab executable, one row a case (issue 35: nothing silently wrong):
// each must exit non-zero with one `lpvlab: error:` message that names the file (or override)
// and the key or thing at fault, and write nothing where it was asked to write. Every case here
// ran with exit 0 and a wrong or empty result before it was fixed. The report's unknown metric
// is tested beside the report's other errors (analysis/tests/test_report.py).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "executable_support.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

namespace fs = std::filesystem;

// A one-triangle glTF (its buffer inline) with a perspective camera whose clip planes are given.
std::string gltfWithCamera(double znear, double zfar) {
  // Three vec3 floats: (0,0,0), (1,0,0), (0,1,0), base64.
  const std::string positions = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,1]}],
  "nodes":[{"mesh":0},{"name":"cam","camera":0,"translation":[0.3,0.3,2.0]}],
  "cameras":[{"name":"cam","type":"perspective","perspective":{"yfov":0.8,"znear":)" +
         std::to_string(znear) + R"(,"zfar":)" + std::to_string(zfar) + R"(,"aspectRatio":1.0}}],
  "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
  "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
  "bufferViews":[{"buffer":0,"byteLength":36}],
  "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)" +
         positions + R"("}]})";
}

// The id of the first configuration a sweep.json lists.
std::string firstConfigurationId(const std::string& sweepJson) {
  const std::string key = "\"id\": \"";
  const auto at = sweepJson.find(key);
  return at == std::string::npos ? "" : sweepJson.substr(at + key.size(), 10);
}

struct BadInput {
  std::string name;
  std::string args;                        // after `lpvlab`, in the case's directory
  std::vector<std::string> mustName;       // substrings of stderr
  std::vector<std::string> mustNotExist;   // paths (relative to the case's directory)
};

class BadInputs : public ::testing::Test {
protected:
  void SetUp() override {
    // Files the cases read: an OBJ whose material library is missing, glTF cameras with their
    // far plane not beyond the near one, a run directory, and an empty directory.
    write("nomtl/box.obj",
          "mtllib box.mtl\nusemtl white\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write("badcamera.gltf", gltfWithCamera(10.0, 1.0));
    write("flatcamera.gltf", gltfWithCamera(1.0, 1.0));
    write("a_run/manifest.json", "{}\n");
    write("a_fit/fit.json", "{}\n");  // a finished fit: its outputs and no fit.progress.json
    write("empty_sweep.toml", "extends = \"" LPVLAB_SOURCE_DIR "/experiments/cornell_box.toml\"\n[sweep]\n");
    write("one_sweep.toml", "extends = \"" LPVLAB_SOURCE_DIR
                            "/experiments/cornell_box.toml\"\n[sweep.product]\n\"grid.resolution\" = [8]\n");
    fs::create_directories(dir_.path() / "empty");
  }
  void write(const std::string& relative, const std::string& text) {
    const fs::path path = dir_.path() / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
  }
  test::TempDir dir_;
};

const std::string kSmall =
    " -s output.width=8 -s output.height=8 -s timing.warmup=0 -s timing.repeats=1"
    " -s 'lights=[{name=\"p\",type=\"point\",position=[0.3,0.3,1.0],intensity=1.0}]'";

const std::vector<BadInput>& cases() {
  static const std::vector<BadInput> c = {
      {"an unknown raster choice",
       "run --out out" + kSmall + " -s compute.raster='\"vulkan\"'",
       {"compute.raster", "vulkan"},
       {"out"}},
      {"shadow rays with direct light on GL",
       "run --out out" + kSmall + " -s light_maps.shadows='\"rays\"' -s compute.backend='\"gl\"'",
       {"light_maps.shadows", "backend"},
       {"out"}},
      {"directed propagation by scattering on the CPU backend, whose kernel gathers",
       "run --out out" + kSmall +
           " -s propagation.type='\"directed\"' -s propagation.method='\"scatter\"'"
           " -s compute.backend='\"cpu\"'",
       {"directed", "scatter", "GL only"},
       {"out"}},
      {"a clamp compensation without a clamp: nothing to compensate",
       "run --out out" + kSmall +
           " -s indirect.method='\"instant_radiosity\"' -s indirect.clamp_compensation=true",
       {"indirect.clamp_compensation", "without a clamp"},
       {"out"}},
      {"a clamp compensation with spherical lights, which it does not model",
       "run --out out" + kSmall +
           " -s indirect.method='\"instant_radiosity\"' -s indirect.clamp=1.0"
           " -s indirect.clamp_compensation=true -s indirect.sphere_radius=0.1",
       {"indirect.clamp_compensation", "sphere_radius"},
       {"out"}},
      {"an unknown VPL placement of incremental instant radiosity",
       "run --out out" + kSmall +
           " -s indirect.method='\"incremental_instant_radiosity\"' -s indirect.placement='\"random\"'",
       {"indirect.placement", "random"},
       {"out"}},
      {"an unknown shadowing",
       "run --out out" + kSmall + " -s light_maps.shadows='\"pcss\"'",
       {"light_maps.shadows", "pcss"},
       {"out"}},
      {"the static camera's near beyond its far",
       "run --out out" + kSmall +
           " -s 'camera={position=[0.278,0.273,-0.8],look_at=[0.278,0.273,0.3],near=10.0,far=1.0}'",
       {"camera.far", "must exceed near (10 m)"},
       {"out"}},
      {"the static camera's near equal to its far",
       "run --out out" + kSmall +
           " -s 'camera={position=[0.278,0.273,-0.8],look_at=[0.278,0.273,0.3],near=1.0,far=1.0}'",
       {"camera.far", "must exceed near (1 m)"},
       {"out"}},
      {"a glTF camera's near beyond its far",
       "run --out out" + kSmall + " -s scene.file='\"badcamera.gltf\"' -s camera.name='\"cam\"'",
       {"camera.name", "badcamera.gltf", "camera 'cam' has near 10 m and far 1 m"},
       {"out"}},
      {"a glTF camera's near equal to its far",
       "run --out out" + kSmall + " -s scene.file='\"flatcamera.gltf\"' -s camera.name='\"cam\"'",
       {"flatcamera.gltf", "camera 'cam' has near 1 m and far 1 m"},
       {"out"}},
      {"an OBJ whose material library is missing (info)",
       "info nomtl/box.obj",
       {"nomtl/box.obj:1", "material library 'box.mtl' cannot be read"},
       {}},
      {"an OBJ whose material library is missing (run)",
       "run --out out" + kSmall +
           " -s scene.file='\"nomtl/box.obj\"' -s 'camera={position=[0.3,0.3,2.0],look_at=[0.3,0.3,0.0]}'",
       {"scene.file", "box.obj:1", "material library 'box.mtl'"},
       {"out"}},
      {"summary of a run directory",
       "summary a_run",
       {"a_run: not a sweep directory", "sweep.json", "single run's manifest.json"},
       {"a_run/summary.csv"}},
      {"summary of a directory of no sweep",
       "summary empty",
       {"empty: not a sweep directory", "sweep.json"},
       {"empty/summary.csv"}},
      {"a light's colour out of range",
       "run --out out" + kSmall +
           " -s 'lights=[{name=\"p\",type=\"point\",position=[0.3,0.3,0.3],intensity=1.0,color=[1e30,1,1]}]'",
       {"lights[0].color", "above the maximum 1e+12"},
       {"out"}},
      {"a light's colour x intensity out of range",
       "run --out out" + kSmall +
           " -s 'lights=[{name=\"p\",type=\"point\",position=[0.3,0.3,0.3],intensity=1e12,color=[2,1,1]}]'",
       {"lights[0].color", "colour x intensity reaches 2e+12"},
       {"out"}},
      {"a fit into a finished fit",
       "fit " LPVLAB_SOURCE_DIR "/experiments/fit_cornell_box.toml --out a_fit",
       {"--out a_fit: holds a finished fit", "--force"},
       {"a_fit/fit.progress.json", "a_fit/fit.md"}},
      {"an empty [sweep] table",
       "sweep empty_sweep.toml --out swept" + kSmall,
       {"empty_sweep.toml", "key 'sweep': empty"},
       {"swept"}},
      {"a sweep into a run's directory",
       "sweep one_sweep.toml --out a_run" + kSmall,
       {"--out a_run", "holds a single run"},
       {"a_run/sweep.json", "a_run/configs"}},
      {"an override whose value starts as TOML and does not parse",
       "run --out out" + kSmall + " -s 'camera={position=[0,1'",
       {"override 'camera'", "is not valid TOML"},
       {"out"}},
      {"a 2000-character value, echoed cut",
       "run --out out" + kSmall + " -s scene.file='\"" + std::string(2000, 'a') + "\"'",
       {"scene.file", "(2000 characters)"},
       {"out"}},
  };
  return c;
}

TEST_F(BadInputs, EachIsOneNamedErrorWithANonZeroExitAndWritesNothing) {
  for (const BadInput& bad : cases()) {
    SCOPED_TRACE(bad.name + ": lpvlab " + bad.args);
    const test::LpvlabResult r = test::runLpvlab(bad.args, dir_.path(), dir_.path());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_EQ(r.exitCode == 0 ? "" : r.err.substr(0, 15), r.exitCode == 0 ? "" : "lpvlab: error: ")
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line:\n" << r.err;
    for (const std::string& needle : bad.mustName)
      EXPECT_NE(r.err.find(needle), std::string::npos) << "names '" << needle << "':\n" << r.err;
    EXPECT_LT(r.err.size(), 400u) << "values are echoed cut";
    for (const std::string& path : bad.mustNotExist)
      EXPECT_FALSE(fs::exists(dir_.path() / path)) << path << " was written";
  }
}

// A finished run (its manifest.json) is not written over: the second run into it is refused and
// leaves it as it was; with --force the old run's files go first (here an error map the new run
// does not write, which would otherwise stand beside a manifest without a comparison) and a file
// of the user's in the directory stays.
TEST_F(BadInputs, AFinishedRunIsNotWrittenOverWithoutForceAndForceRemovesWhatItWrote) {
  const fs::path run = dir_.path() / "r";
  ASSERT_EQ(test::runLpvlab("run --out r" + kSmall, dir_.path(), dir_.path()).exitCode, 0);
  write("r/notes.txt", "mine\n");
  const std::string manifest = test::readFile(run / "manifest.json");

  const test::LpvlabResult again = test::runLpvlab("run --out r" + kSmall, dir_.path(), dir_.path());
  EXPECT_NE(again.exitCode, 0);
  EXPECT_NE(again.err.find("lpvlab: error: --out r: holds a finished run (manifest.json, created "),
            std::string::npos)
      << again.err;
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
  EXPECT_EQ(test::readFile(run / "manifest.json"), manifest) << "the finished run is left as it was";

  // The old run as one with a comparison would have left it: an error map in its outputs.
  std::string withMap = manifest;
  const std::string outputs = "\"outputs\": {";
  ASSERT_NE(withMap.find(outputs), std::string::npos);
  withMap.insert(withMap.find(outputs) + outputs.size(),
                 "\"error_map\": \"error_indirect.png (FLIP of indirect)\", ");
  write("r/manifest.json", withMap);
  write("r/error_indirect.png", "old\n");
  const test::LpvlabResult forced =
      test::runLpvlab("run --force --out r" + kSmall, dir_.path(), dir_.path());
  EXPECT_EQ(forced.exitCode, 0) << forced.err;
  EXPECT_FALSE(fs::exists(run / "error_indirect.png")) << "the old run's error map was removed";
  EXPECT_TRUE(fs::exists(run / "manifest.json"));
  EXPECT_NE(test::readFile(run / "manifest.json"), withMap);
  EXPECT_EQ(test::readFile(run / "notes.txt"), "mine\n") << "only what the old run wrote goes";

  // A run with --dump-grid, replaced by one without: its grid files go with it.
  ASSERT_EQ(test::runLpvlab("run --force --dump-grid --out r" + kSmall, dir_.path(), dir_.path()).exitCode, 0);
  EXPECT_TRUE(fs::exists(run / "grid.npy"));
  EXPECT_TRUE(fs::exists(run / "grid.json"));
  ASSERT_EQ(test::runLpvlab("run --force --out r" + kSmall, dir_.path(), dir_.path()).exitCode, 0);
  EXPECT_FALSE(fs::exists(run / "grid.npy")) << "an old run's grid beside a new run's manifest";
  EXPECT_FALSE(fs::exists(run / "grid.json"));
}

// Results that run but are suspect are flagged, not refused (a black image can be what a study
// asks for): a warning on stderr, the manifest's "warnings", a column of summary.csv.
TEST_F(BadInputs, BlackResultsAndUnconvergedSolvesAreFlaggedInTheOutputManifestAndSummary) {
  const std::string dark =
      " -s scene.replace_lights=true"
      " -s 'lights=[{name=\"off\",type=\"point\",position=[0.3,0.3,0.3],intensity=0.0}]'";
  const std::string flags[] = {
      "run --out black" + kSmall + dark,
      // Radiosity stopped before it began: an indirect image of zeros, converged = false.
      "run --out unsolved -s indirect.method='\"radiosity\"' -s indirect.max_iterations=0" + kSmall};
  const test::LpvlabResult black = test::runLpvlab(flags[0], dir_.path(), dir_.path());
  ASSERT_EQ(black.exitCode, 0) << black.err;
  EXPECT_NE(black.err.find("lpvlab: warning: every value of 'direct' and 'indirect' is zero"),
            std::string::npos)
      << black.err;
  EXPECT_NE(test::readFile(dir_.path() / "black" / "manifest.json").find("\"warnings\""),
            std::string::npos);
  // A sequence's frames are flagged the same way, each in its record and all in the manifest.
  const test::LpvlabResult sequence = test::runLpvlab(
      "run --out black_sequence" + kSmall + dark +
          " -s animation.frames=2 -s animation.fps=1 -s animation.video=false",
      dir_.path(), dir_.path());
  ASSERT_EQ(sequence.exitCode, 0) << sequence.err;
  EXPECT_NE(sequence.err.find("lpvlab: warning: every frame: every value of 'direct' and "
                              "'indirect' is zero"),
            std::string::npos)
      << sequence.err;
  EXPECT_NE(test::readFile(dir_.path() / "black_sequence" / "manifest.json").find("\"warnings\""),
            std::string::npos);
  const test::LpvlabResult unsolved = test::runLpvlab(flags[1], dir_.path(), dir_.path());
  ASSERT_EQ(unsolved.exitCode, 0) << unsolved.err;
  EXPECT_NE(unsolved.err.find("lpvlab: warning: the indirect method's solver did not converge"),
            std::string::npos)
      << unsolved.err;
  // The open box's two-sided walls under a sun, with one cell of grid margin: the VPLs of their
  // sunlit outsides fall outside the grid (8% of the flux); with two cells none do.
  const std::string openBox =
      " -s scene.file='\"" LPVLAB_SOURCE_DIR "/experiments/scenes/open_box.obj\"'"
      " -s 'camera={position=[0.5,0.75,2.6],look_at=[0.5,0.35,0.5]}'"
      " -s output.width=8 -s output.height=8 -s timing.warmup=0 -s timing.repeats=1"
      " -s 'lights=[{name=\"sun\",type=\"directional\",direction=[0.3,-1.0,-0.4],intensity=2.0}]'";
  const test::LpvlabResult outside = test::runLpvlab("run --out outside" + openBox, dir_.path(), dir_.path());
  ASSERT_EQ(outside.exitCode, 0) << outside.err;
  EXPECT_NE(outside.err.find("of the RSMs' reflected flux fell outside the light grid"), std::string::npos)
      << outside.err;
  const test::LpvlabResult inside =
      test::runLpvlab("run --out inside -s grid.margin=2.0" + openBox, dir_.path(), dir_.path());
  ASSERT_EQ(inside.exitCode, 0) << inside.err;
  EXPECT_EQ(inside.err.find("lpvlab: warning:"), std::string::npos) << inside.err;
  // Face solid angles that make propagation gain energy (docs/variants.md): flagged, by table.
  const test::LpvlabResult gaining = test::runLpvlab(
      "run --out gaining -s output.width=8 -s output.height=8 -s timing.warmup=0 -s timing.repeats=1 "
      "-s propagation.far_face_solid_angle=1.43 -s propagation.side_face_solid_angle=0.42",
      dir_.path(), dir_.path());
  ASSERT_EQ(gaining.exitCode, 0) << gaining.err;
  EXPECT_NE(gaining.err.find("lpvlab: warning: propagation: damping x 6 (far_face_solid_angle"), std::string::npos)
      << gaining.err;
  EXPECT_NE(test::readFile(dir_.path() / "gaining" / "manifest.json").find("propagation gains energy"),
            std::string::npos);
  // A lit run has no warnings: the box's own spot.
  ASSERT_EQ(test::runLpvlab("run --out lit -s output.width=8 -s output.height=8 -s timing.warmup=0 "
                            "-s timing.repeats=1",
                            dir_.path(), dir_.path())
                .exitCode,
            0);
  EXPECT_EQ(test::readFile(dir_.path() / "lit" / "manifest.json").find("\"warnings\""),
            std::string::npos);

  // A sweep of the dark light and a lit one: summary.csv carries the warnings of the dark run.
  write("dark_sweep.toml", "extends = \"" LPVLAB_SOURCE_DIR
                           "/experiments/cornell_box.toml\"\n[scene]\nreplace_lights = true\n"
                           "[[lights]]\nname = \"p\"\ntype = \"point\"\nposition = [0.3, 0.3, 0.3]\n"
                           "intensity = 1.0\n[sweep.product]\n\"lights[0].intensity\" = [0.0, 1.0]\n");
  const test::LpvlabResult sweep = test::runLpvlab(
      "sweep dark_sweep.toml --out swept -s output.width=8 -s output.height=8 -s timing.warmup=0 "
      "-s timing.repeats=1",
      dir_.path(), dir_.path());
  ASSERT_EQ(sweep.exitCode, 0) << sweep.err;
  const std::string csv = test::readFile(dir_.path() / "swept" / "summary.csv");
  EXPECT_NE(csv.substr(0, csv.find('\n')).find("warnings"), std::string::npos) << csv;
  EXPECT_NE(csv.find("every value of 'direct' and 'indirect' is zero"), std::string::npos) << csv;
}

// A sweep directory holds one sweep (its hash in sweep.json). Three ways another sweep's runs
// got into one summary.csv, each refused now without a change to the directory: another file,
// the same file with another -s, and a changed base value under the same swept keys (whose
// configs/<id>.toml said 20 while the runs were 16). --force replaces the old sweep; `summary`
// counts only the recorded sweep's configurations and names what it left out.
TEST_F(BadInputs, ASweepDirectoryHoldsOneSweepAndItsSummaryOnlyThatSweepsRuns) {
  const std::string small =
      " -s output.width=8 -s output.height=8 -s timing.warmup=0 -s timing.repeats=1";
  const std::string base = "extends = \"" LPVLAB_SOURCE_DIR "/experiments/cornell_box.toml\"\n";
  write("a.toml", base + "[sweep.product]\n\"propagation.iterations\" = [1, 2]\n");
  write("b.toml", base + "[sweep.product]\n\"grid.sh_order\" = [1]\n");
  const fs::path swept = dir_.path() / "swept";
  const test::LpvlabResult a = test::runLpvlab("sweep a.toml --out swept" + small, dir_.path(), dir_.path());
  ASSERT_EQ(a.exitCode, 0) << a.err;
  const std::string index = test::readFile(swept / "sweep.json");
  ASSERT_NE(index.find("\"sweep_hash\""), std::string::npos) << index;
  // Resuming the same sweep is still what it was: all complete, nothing rerun.
  const test::LpvlabResult same = test::runLpvlab("sweep a.toml --out swept" + small, dir_.path(), dir_.path());
  EXPECT_EQ(same.exitCode, 0) << same.err;
  EXPECT_NE(same.err.find("2 configurations, 2 complete, 0 to run"), std::string::npos) << same.err;

  write("c16.toml", base + "[grid]\nresolution = 16\n[sweep.product]\n\"propagation.iterations\" = [1, 2]\n");
  write("c.toml", base + "[grid]\nresolution = 20\n[sweep.product]\n\"propagation.iterations\" = [1, 2]\n");
  ASSERT_EQ(test::runLpvlab("sweep c16.toml --out swept16" + small, dir_.path(), dir_.path()).exitCode, 0);
  fs::copy_file(dir_.path() / "c.toml", dir_.path() / "c16.toml", fs::copy_options::overwrite_existing);
  const std::string index16 = test::readFile(dir_.path() / "swept16" / "sweep.json");
  for (const auto& [args, source] : std::vector<std::pair<std::string, std::string>>{
           {"sweep b.toml --out swept" + small, "b.toml"},
           {"sweep a.toml --out swept -s grid.resolution=12" + small, "-s grid.resolution=12"},
           {"sweep c16.toml --out swept16" + small, "c16.toml"}}) {
    SCOPED_TRACE("lpvlab " + args);
    const test::LpvlabResult r = test::runLpvlab(args, dir_.path(), dir_.path());
    EXPECT_NE(r.exitCode, 0);
    EXPECT_EQ(r.err.rfind("lpvlab: error: --out swept", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("holds another sweep ("), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(source), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("choose a new --out"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_EQ(test::readFile(swept / "sweep.json"), index) << "the old sweep is left as it was";
  EXPECT_EQ(test::readFile(dir_.path() / "swept16" / "sweep.json"), index16);

  // Another run's directory in the sweep's, and a configuration whose manifest holds nothing:
  // neither gives a row, and both are named.
  write("swept/stray/manifest.json", test::readFile(swept / firstConfigurationId(index) / "manifest.json"));
  write("swept/" + firstConfigurationId(index) + "/manifest.json", "{}\n");
  const test::LpvlabResult summary = test::runLpvlab("summary swept", dir_.path(), dir_.path());
  EXPECT_EQ(summary.exitCode, 0) << summary.err;
  EXPECT_NE(summary.err.find("swept/stray: not a configuration of this sweep"), std::string::npos)
      << summary.err;
  EXPECT_NE(summary.err.find("swept/" + firstConfigurationId(index) + ": no rows: its manifest.json has no timing"),
            std::string::npos)
      << summary.err;
  EXPECT_NE(summary.out.find(": 1 rows from 1 runs"), std::string::npos) << summary.out;
  EXPECT_EQ(test::readFile(swept / "summary.csv").find("stray"), std::string::npos);

  // --force: the other sweep replaces this one; its summary holds its own configuration alone.
  const test::LpvlabResult forced =
      test::runLpvlab("sweep b.toml --force --out swept" + small, dir_.path(), dir_.path());
  ASSERT_EQ(forced.exitCode, 0) << forced.err;
  EXPECT_NE(forced.out.find(": 1 rows from 1 runs"), std::string::npos) << forced.out;
  EXPECT_FALSE(fs::exists(swept / firstConfigurationId(index))) << "the old sweep's runs were removed";
  EXPECT_TRUE(fs::exists(swept / "stray")) << "only what the old sweep wrote goes";
}

// Usage errors (an unknown command or option, a word too many) are one `lpvlab: error:` line
// naming the word, with exit code 2 (CLI11's own codes were 105-115, and "A subcommand is
// required" for an unknown command); --version prints the version and the git revision.
TEST_F(BadInputs, UsageErrorsExitTwoNamingTheWordAndVersionPrintsTheRevision) {
  for (const auto& [args, word] : std::vector<std::pair<std::string, std::string>>{
           {"comapre", "unknown command 'comapre' (commands: run, "},
           {"", "A subcommand is required"},
           {"run --nosuch", "--nosuch"},
           {"run a.toml b.toml", "b.toml"}}) {
    SCOPED_TRACE("lpvlab " + args);
    const test::LpvlabResult r = test::runLpvlab(args, dir_.path(), dir_.path());
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_EQ(r.err.rfind("lpvlab: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(word), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const test::LpvlabResult version = test::runLpvlab("--version", dir_.path(), dir_.path());
  EXPECT_EQ(version.exitCode, 0) << version.err;
  EXPECT_EQ(version.out.rfind(std::string("lpvlab ") + LPVLAB_VERSION + " (git ", 0), 0u) << version.out;
}

// `info` says what a light is and the units of its numbers (it printed "type 1" and a bare
// intensity): the box's spot light by name, its W/sr and its cone.
TEST_F(BadInputs, InfoNamesEachLightsTypeAndUnits) {
  const test::LpvlabResult r = test::runLpvlab("info builtin:cornell_box", dir_.path(), dir_.path());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.find(": type "), std::string::npos) << r.out;
  for (const char* needle : {"light      spot: spot at [", " m towards [", "W/sr", "cone half-angles ",
                             "deg, colour [", "bounds     [", "camera     "})
    EXPECT_NE(r.out.find(needle), std::string::npos) << needle << " in\n" << r.out;
}

// The cases' files are good but for the fault: the same OBJ with its library, and the glTF with
// a far plane beyond the near one, run.
TEST_F(BadInputs, TheSameFilesWithoutTheFaultRun) {
  write("nomtl/box.mtl", "newmtl white\nKd 0.7 0.7 0.7\n");
  write("goodcamera.gltf", gltfWithCamera(0.1, 100.0));
  for (const std::string& args :
       {std::string("info nomtl/box.obj"),
        "run --out good_gltf" + kSmall + " -s scene.file='\"goodcamera.gltf\"' -s camera.name='\"cam\"'"}) {
    const test::LpvlabResult r = test::runLpvlab(args, dir_.path(), dir_.path());
    EXPECT_EQ(r.exitCode, 0) << args << ":\n" << r.err;
  }
}

}  // namespace
}  // namespace lpvlab

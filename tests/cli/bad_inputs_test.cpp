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
    for (const std::string& path : bad.mustNotExist)
      EXPECT_FALSE(fs::exists(dir_.path() / path)) << path << " was written";
  }
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

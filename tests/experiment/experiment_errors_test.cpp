// Experiment files that are wrong in each way loadExperiment must catch: every one throws an
// lpvlab::Error whose message names the file (with the line where there is one) and the key, and
// lists the valid choices where there are some. And a valid file using every kind of light loads.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "error_support.h"
#include "lpv_support.h"
#include "framework/core/error.h"
#include "framework/experiment/experiment.h"
#include "io/temp_dir.h"

namespace lpvlab {
namespace {

using test::contains;

class ExperimentErrors : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    const std::string path = dir_.file(name);
    std::ofstream(path) << text;
    return path;
  }
  // The message of the Error loadExperiment throws (a failure if it throws nothing or another
  // type).
  static std::string errorOf(const std::string& path,
                             const std::vector<std::string>& overrides = {}) {
    return test::errorOf([&] { loadExperiment(path, overrides); });
  }
  test::TempDir dir_;
};

TEST_F(ExperimentErrors, UnknownTopLevelKey) {
  const std::string path =
      write("top.toml", "# a typo at the top\n[output]\nwidth = 64\n\nbogus_key = 1\n");
  const std::string message = errorOf(path);
  // bogus_key sits under [output] in TOML; a real top-level key must come before any table.
  EXPECT_TRUE(contains(message, path + ":5"));
  EXPECT_TRUE(contains(message, "output.bogus_key"));

  const std::string top = write("top2.toml", "bogus_key = 1\n[output]\nwidth = 64\n");
  const std::string topMessage = errorOf(top);
  EXPECT_TRUE(contains(topMessage, top + ":1"));
  EXPECT_TRUE(contains(topMessage, "'bogus_key'"));
  EXPECT_TRUE(contains(topMessage, "propagation"));  // the valid top-level keys are listed
  EXPECT_TRUE(contains(topMessage, "grid"));
}

// A glossy lobe set by [[materials]]: applied to every material with name = "*", refused where
// the Lambertian reference would ignore it, and where a surface would reflect more than it gets.
TEST_F(ExperimentErrors, GlossyMaterialOverridesAreAppliedOrRefused) {
  const std::string glossy = write("glossy.toml",
                                   "[reference]\nbrdf = \"phong\"\n[[materials]]\nname = \"*\"\n"
                                   "base_color = [0.6, 0.6, 0.6]\nspecular = [0.3, 0.3, 0.3]\nshininess = 40.0\n");
  const Experiment e = loadExperiment(glossy);
  EXPECT_TRUE(e.reference.tracer.glossy);
  ASSERT_GT(e.scene.materials.size(), 1u);
  for (const Material& m : e.scene.materials) {
    EXPECT_EQ(m.specular, glm::vec3(0.3f)) << m.name;
    EXPECT_EQ(m.shininess, 40.0f) << m.name;
    EXPECT_EQ(m.baseColor, glm::vec3(0.6f)) << m.name;
  }

  const std::string ignored = write("ignored.toml", "[[materials]]\nname = \"*\"\n"
                                                    "base_color = [0.5, 0.5, 0.5]\nspecular = [0.3, 0.3, 0.3]\n");
  const std::string ignoredMessage = errorOf(ignored);
  EXPECT_TRUE(contains(ignoredMessage, "specular")) << ignoredMessage;
  EXPECT_TRUE(contains(ignoredMessage, "brdf")) << ignoredMessage;

  const std::string bright = write("bright.toml",
                                   "[reference]\nbrdf = \"phong\"\n[[materials]]\nname = \"*\"\n"
                                   "base_color = [0.8, 0.8, 0.8]\nspecular = [0.3, 0.3, 0.3]\n");
  const std::string brightMessage = errorOf(bright);
  EXPECT_TRUE(contains(brightMessage, "specular")) << brightMessage;
  EXPECT_TRUE(contains(brightMessage, "more than it receives")) << brightMessage;

  const std::string brdf = write("brdf.toml", "[reference]\nbrdf = \"ggx\"\n");
  const std::string brdfMessage = errorOf(brdf);
  EXPECT_TRUE(contains(brdfMessage, "reference.brdf")) << brdfMessage;
  EXPECT_TRUE(contains(brdfMessage, "phong")) << brdfMessage;
}

TEST_F(ExperimentErrors, IndirectMethodsAndTheirParametersAreChecked) {
  const std::string unknown = write("method.toml", "[indirect]\nmethod = \"photon_mapping\"\n");
  const std::string message = errorOf(unknown);
  EXPECT_TRUE(contains(message, unknown + ":2")) << message;
  EXPECT_TRUE(contains(message, "indirect.method")) << message;
  EXPECT_TRUE(contains(message, "instant_radiosity")) << message;  // the choices are listed
  EXPECT_TRUE(contains(message, "lpv")) << message;

  // A method's own keys: a typo, a value out of range, a bad choice.
  const std::string typo =
      write("typo.toml", "[indirect]\nmethod = \"instant_radiosity\"\nlight_path = 64\n");
  const std::string typoMessage = errorOf(typo);
  EXPECT_TRUE(contains(typoMessage, typo + ":3")) << typoMessage;
  EXPECT_TRUE(contains(typoMessage, "indirect.light_path")) << typoMessage;
  EXPECT_TRUE(contains(typoMessage, "light_paths")) << typoMessage;  // the valid keys
  const std::string range = write("range.toml", "[indirect]\nmethod = \"instant_radiosity\"\n");
  EXPECT_TRUE(contains(errorOf(range, {"indirect.clamp=-1"}), "indirect.clamp"));
  EXPECT_TRUE(contains(errorOf(range, {"indirect.light_paths=0"}), "indirect.light_paths"));
  EXPECT_TRUE(contains(errorOf(range, {"indirect.visibility=\"maybe\""}), "rays"));
  EXPECT_TRUE(contains(errorOf("", {"indirect.method=rsm_gather", "indirect.pattern=spiral"}),
                       "importance"));
  // LPV's keys stay checked under another method (a sweep over methods shares them).
  EXPECT_TRUE(contains(errorOf(range, {"propagation.iteratons=4"}), "propagation.iteratons"));
}

TEST_F(ExperimentErrors, UnsnappedCascadesThatCarryAreRefusedNamingBothKeys) {
  const std::string path = write("snap.toml", "[cascades]\nlevels = 3\nsnap = false\n");
  const std::string message = errorOf(path);
  EXPECT_TRUE(contains(message, path + ":3")) << message;
  EXPECT_TRUE(contains(message, "cascades.snap")) << message;
  EXPECT_TRUE(contains(message, "cascades.carry = false")) << message;
  // Without carrying, or with one level, it loads.
  EXPECT_FALSE(loadExperiment(path, {"cascades.carry=false"}).settings.cascades.snap);
  EXPECT_NO_THROW(loadExperiment(path, {"cascades.levels=1"}));
}

TEST_F(ExperimentErrors, AFollowingDirectionalViewNeedsItsWidthAndTheSceneViewTakesNone) {
  const std::string unused = write("sun_scene.toml", "[light_maps]\ndirectional_width = 2.0\n");
  std::string message = errorOf(unused);
  EXPECT_TRUE(contains(message, unused + ":2")) << message;
  EXPECT_TRUE(contains(message, "light_maps.directional_width")) << message;
  EXPECT_TRUE(contains(message, "directional = \"camera\"")) << message;

  const std::string missing = write("sun_camera.toml", "[light_maps]\ndirectional = \"camera\"\n");
  message = errorOf(missing);
  EXPECT_TRUE(contains(message, "light_maps.directional_width")) << message;

  const std::string zero = write("sun_zero.toml",
                                 "[light_maps]\ndirectional = \"camera\"\n"
                                 "directional_width = 0.0\n");
  message = errorOf(zero);
  EXPECT_TRUE(contains(message, zero + ":3")) << message;
  EXPECT_TRUE(contains(message, "directional_width")) << message;

  const Experiment e = loadExperiment(
      zero, {"light_maps.directional_width=3.5", "light_maps.directional_snap=false"});
  EXPECT_FLOAT_EQ(e.settings.directional.followWidth, 3.5f);
  EXPECT_FALSE(e.settings.directional.snap);
}

TEST_F(ExperimentErrors, UnknownKeyInAStrategyTableListsTheValidKeys) {
  const std::string path =
      write("typo.toml", "[propagation]\ntype = \"standard\"\niteratoins = 8\n");
  const std::string message = errorOf(path);
  EXPECT_TRUE(contains(message, path + ":3"));
  EXPECT_TRUE(contains(message, "propagation.iteratoins"));
  EXPECT_TRUE(contains(message, "iterations"));
  EXPECT_TRUE(contains(message, "type"));
}

TEST_F(ExperimentErrors, UnknownStrategyListsTheKnownOnes) {
  const std::string path = write("strategy.toml", "[propagation]\ntype = \"nope\"\n");
  const std::string message = errorOf(path);
  EXPECT_TRUE(contains(message, path + ":2"));
  EXPECT_TRUE(contains(message, "propagation.type"));
  EXPECT_TRUE(contains(message, "nope"));
  EXPECT_TRUE(contains(message, "standard"));
}

TEST_F(ExperimentErrors, OutOfRangeValuesAreErrorsNotClamped) {
  const std::string iterations = write("iterations.toml", "[propagation]\niterations = -1\n");
  std::string message = errorOf(iterations);
  EXPECT_TRUE(contains(message, iterations + ":2"));
  EXPECT_TRUE(contains(message, "propagation.iterations"));
  EXPECT_TRUE(contains(message, "-1"));

  const std::string resolution = write("resolution.toml", "[grid]\n\nresolution = 0\n");
  message = errorOf(resolution);
  EXPECT_TRUE(contains(message, resolution + ":3"));
  EXPECT_TRUE(contains(message, "grid.resolution"));

  const std::string cells =
      write("cells.toml", "[grid]\norigin = [0, 0, 0]\ncell_size = 0.1\ncells = [4, 0, 4]\n");
  message = errorOf(cells);
  EXPECT_TRUE(contains(message, cells + ":4"));
  EXPECT_TRUE(contains(message, "grid.cells"));
}

TEST_F(ExperimentErrors, SamplersAreNamedChoices) {
  const std::string tracer = write("sampler.toml", "[reference]\nsampler = \"halton\"\n");
  std::string message = errorOf(tracer);
  EXPECT_TRUE(contains(message, tracer + ":2"));
  EXPECT_TRUE(contains(message, "reference.sampler"));
  EXPECT_TRUE(contains(message, "sobol"));  // the valid choices are listed
  const std::string walks =
      write("walks.toml", "[indirect]\nmethod = \"instant_radiosity\"\nsampler = \"owen\"\n");
  message = errorOf(walks);
  EXPECT_TRUE(contains(message, walks + ":3"));
  EXPECT_TRUE(contains(message, "indirect.sampler"));
}

TEST_F(ExperimentErrors, TracerInstructionSetAndPacketWidthAreChecked) {
  const std::string isa = write("isa.toml", "[reference]\nisa = \"avx9\"\n");
  std::string message = errorOf(isa);
  EXPECT_TRUE(contains(message, isa + ":2"));
  EXPECT_TRUE(contains(message, "reference.isa"));
  EXPECT_TRUE(contains(message, "avx2"));  // the valid choices are listed

  const std::string width = write("width.toml", "[reference]\npacket_width = 3\n");
  message = errorOf(width);
  EXPECT_TRUE(contains(message, width + ":2"));
  EXPECT_TRUE(contains(message, "reference.packet_width"));
  EXPECT_TRUE(contains(message, "1, 4, 8, 16"));

  // Every instruction set this CPU has loads; one it lacks is refused by name.
  for (const std::string& name : embreeInstructionSets()) {
    const std::vector<std::string> has = supportedInstructionSets();
    const std::string path =
        write("isa_" + std::to_string(&name - &embreeInstructionSets()[0]) + ".toml",
              "[reference]\nisa = \"" + name + "\"\n");
    if (std::find(has.begin(), has.end(), name) != has.end())
      EXPECT_EQ(loadExperiment(path, {}).reference.tracer.engine.isa, name);
    else
      EXPECT_TRUE(contains(errorOf(path), "this CPU lacks '" + name + "'"));
  }
}

TEST_F(ExperimentErrors, WrongTypeNamesTheExpectedType) {
  const std::string path = write("type.toml", "[output]\nwidth = \"big\"\n");
  const std::string message = errorOf(path);
  EXPECT_TRUE(contains(message, path + ":2"));
  EXPECT_TRUE(contains(message, "output.width"));
  EXPECT_TRUE(contains(message, "integer"));
}

TEST_F(ExperimentErrors, SyntaxErrorNamesFileAndLine) {
  const std::string path = write("syntax.toml", "# fine\n[output]\nwidth = 64\nheight = = 3\n");
  const std::string message = errorOf(path);
  EXPECT_TRUE(contains(message, path + ":4"));
}

TEST_F(ExperimentErrors, MissingFiles) {
  const std::string missing = dir_.file("absent.toml");
  EXPECT_TRUE(contains(errorOf(missing), missing));

  const std::string path = write("scene.toml", "[scene]\nfile = \"no_such_scene.gltf\"\n");
  const std::string message = errorOf(path);
  // Scene paths are relative to the experiment file: the message names the resolved path.
  EXPECT_TRUE(contains(message, dir_.file("no_such_scene.gltf")));
  EXPECT_TRUE(contains(message, "no such file"));
}

TEST_F(ExperimentErrors, OverridesAreCheckedLikeTheFile) {
  std::string message = errorOf("", {"propagation.bogus=1"});
  EXPECT_TRUE(contains(message, "propagation.bogus"));
  EXPECT_TRUE(contains(message, "iterations"));

  message = errorOf("", {"propagation.iterations=-1"});
  EXPECT_TRUE(contains(message, "propagation.iterations"));

  message = errorOf("", {"propagation.type=nope"});
  EXPECT_TRUE(contains(message, "nope"));
  EXPECT_TRUE(contains(message, "standard"));

  message = errorOf("", {"no_equals_sign"});
  EXPECT_TRUE(contains(message, "no_equals_sign"));

  // An override of a key the file has is checked with the file's name.
  const std::string path = write("ok.toml", "[propagation]\niterations = 8\n");
  message = errorOf(path, {"propagation.iterations=\"many\""});
  EXPECT_TRUE(contains(message, path));
  EXPECT_TRUE(contains(message, "propagation.iterations"));
}

TEST_F(ExperimentErrors, AValidFileWithEveryKindOfLightLoads) {
  const std::string path = write("valid.toml", R"(# The Cornell box with three more lights.
[scene]
file = "builtin:cornell_box"   # trailing comments are fine

[[lights]]
type = "point"
position = [0.2, 0.4, 0.3]
intensity = 0.5

[[lights]]
type = "spot"
name = "second spot"
position = [0.3, 0.5, 0.3]
direction = [0, -2, 0]
color = [1.0, 0.5, 0.25]
intensity = 1.5
outer_cone_deg = 40.0
inner_cone_deg = 30.0

[[lights]]
type = "directional"
direction = [0.1, -1.0, 0.2]
intensity = 3

[propagation]
type = "standard"
iterations = 7

[output]
width = 96
height = 80
)");
  Experiment e;
  ASSERT_NO_THROW(e = loadExperiment(path, {"grid.resolution=12"}));
  EXPECT_EQ(e.name, "valid");
  EXPECT_EQ(e.file, path);
  ASSERT_EQ(e.scene.lights.size(), 4u);  // the box's own spot, then the three above
  const Light& point = e.scene.lights[1];
  const Light& spot = e.scene.lights[2];
  const Light& sun = e.scene.lights[3];
  EXPECT_EQ(point.type, LightType::Point);
  EXPECT_EQ(point.position, glm::vec3(0.2f, 0.4f, 0.3f));
  EXPECT_FLOAT_EQ(point.intensity, 0.5f);
  EXPECT_EQ(spot.type, LightType::Spot);
  EXPECT_EQ(spot.name, "second spot");
  EXPECT_EQ(spot.direction, glm::vec3(0, -1, 0));  // normalised
  EXPECT_EQ(spot.color, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_NEAR(spot.outerConeAngle, 40.0 * M_PI / 180.0, 1e-6);
  EXPECT_NEAR(spot.innerConeAngle, 30.0 * M_PI / 180.0, 1e-6);
  EXPECT_EQ(sun.type, LightType::Directional);
  EXPECT_NEAR(glm::length(sun.direction), 1.0, 1e-6);
  EXPECT_FLOAT_EQ(sun.intensity, 3.0f);

  EXPECT_EQ(e.settings.width, 96);
  EXPECT_EQ(e.settings.height, 80);
  const glm::ivec3 cells = e.settings.grid.resolution;  // the override, along the longest axis
  EXPECT_EQ(std::max({cells.x, cells.y, cells.z}), 12);
  ASSERT_TRUE(test::lpvStrategies(e).propagation);
  EXPECT_EQ(test::lpvStrategies(e).propagation->iterations(), 7);
  ASSERT_EQ(test::lpvStrategies(e).injection.size(), 1u);
  ASSERT_TRUE(test::lpvStrategies(e).occlusion);
  ASSERT_EQ(test::lpvStrategies(e).rendering.size(), 1u);
  EXPECT_EQ(e.configuration["propagation"]["iterations"], 7);
  EXPECT_EQ(e.configuration["grid"]["resolution"], 12);
  EXPECT_EQ(e.configuration["lights"].size(), 3u);
}

TEST_F(ExperimentErrors, ACameraPathMovesTheExperimentsCameraOrNeedsNone) {
  // [camera] (here inherited, as the shipped fly-throughs inherit theirs) gives the field of view
  // the path keeps; the path gives position and view.
  write("base.toml", "[camera]\nposition = [0, 0.3, -1]\nlook_at = [0, 0.3, 0]\nfov_deg = 30\n");
  const std::string path = write(
      "both.toml",
      "extends = \"base.toml\"\n[animation]\nframes = 2\n[animation.camera]\n"
      "[[animation.camera.keys]]\nframe = 0\nposition = [0.2, 0.3, -1]\nlook_at = [0.2, 0.3, 0]\n");
  const Experiment e = loadExperiment(path);
  EXPECT_NEAR(e.camera.verticalFov, 30.0f * float(M_PI) / 180.0f, 1e-6f);
  EXPECT_NEAR(e.camera.position.x, 0.2f, 1e-6f);
  // A scene without cameras and no [camera]: the path alone places it (45 degrees by default).
  std::ofstream(dir_.file("tri.obj")) << "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 3 2\n";
  const std::string bare = write(
      "bare.toml",
      "[scene]\nfile = \"tri.obj\"\n[[lights]]\nposition = [0.2, 1, 0.2]\nintensity = 1\n"
      "[animation]\n[animation.camera]\n"
      "[[animation.camera.keys]]\nframe = 0\nposition = [0.3, 1, 0.3]\nlook_at = [0.3, 0, 0.31]\n");
  const Experiment fromPath = loadExperiment(bare);
  EXPECT_NEAR(fromPath.camera.verticalFov, 45.0f * float(M_PI) / 180.0f, 1e-6f);
  EXPECT_GT(fromPath.camera.farPlane, fromPath.camera.nearPlane);
  // Without the path the same file has no camera: an error saying how to give one.
  const std::string none =
      write("none.toml",
            "[scene]\nfile = \"tri.obj\"\n[[lights]]\nposition = [0.2, 1, 0.2]\nintensity = 1\n");
  EXPECT_TRUE(contains(errorOf(none), "has no camera"));
}

TEST_F(ExperimentErrors, AnAnimatedLightOfTheExperimentIsFoundByName) {
  const std::string path = write(
      "lamp.toml",
      "[[lights]]\nname = \"lamp\"\ntype = \"point\"\nposition = [0.2, 0.3, 0.2]\nintensity = 0.1\n"
      "[animation]\nframes = 3\n[[animation.lights]]\nlight = \"lamp\"\n"
      "[[animation.lights.keys]]\nframe = 0\nposition = [0.2, 0.3, 0.2]\n"
      "[[animation.lights.keys]]\nframe = 2\nposition = [0.4, 0.3, 0.2]\n");
  const Experiment e = loadExperiment(path);
  ASSERT_EQ(e.animation.lights.size(), 1u);
  EXPECT_EQ(e.scene.lights[std::size_t(e.animation.lights[0].light)].name, "lamp");
  // A point light has no direction to key.
  const std::string bad = write(
      "lamp2.toml",
      "[[lights]]\nname = \"lamp\"\ntype = \"point\"\nposition = [0.2, 0.3, 0.2]\nintensity = 0.1\n"
      "[animation]\n[[animation.lights]]\nlight = \"lamp\"\n"
      "[[animation.lights.keys]]\nframe = 0\ndirection = [0, -1, 0]\n");
  EXPECT_TRUE(contains(errorOf(bad), "unknown key 'animation.lights[0].keys[0].direction'"));
}

}  // namespace
}  // namespace lpvlab

// [[particles]] tables read into particle systems, and one clear error naming the key for every
// bad setting: no model, no emitter, a negative or zero rate, a zero lifetime, a variation that
// would make a speed negative, an unknown shape, keys out of order, unknown keys.

#include "framework/particles/particle_file.h"

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "error_support.h"

namespace lpvlab {
namespace {

using test::contains;
using test::errorOf;

ParticleSettings read(const std::string& text) {
  const toml::table root = toml::parse(text);
  Params params(root, "particles.toml");
  std::vector<Params> tables = params.tables("particles");
  EXPECT_EQ(tables.size(), 1u);
  ParticleSettings settings = readParticleSettings(tables.at(0), 0);
  tables.at(0).finish();
  params.finish();
  return settings;
}

const char* kValid = R"(
[[particles]]
name = "sparks"
model = "models/crystal.obj"
model_meshes = ["crystal"]
seed = 3
gravity = [0.0, -1.0, 0.0]
prewarm = 0.5
spin_deg = 90.0
[[particles.over_life]]
life = 0.0
size = 0.02
color = [1.0, 0.5, 0.0]
[[particles.over_life]]
life = 1.0
size = 0.0
[[particles.emitters]]
shape = "box"
position = [0.0, 1.0, 0.0]
half_extent = [0.5, 0.0, 0.5]
rate = 100.0
direction = [0.0, -1.0, 0.0]
spread_deg = 30.0
speed = 0.5
speed_variation = 0.1
lifetime = 2.0
lifetime_variation = 0.5
)";

TEST(ParticleFile, ReadsEverySetting) {
  const ParticleSettings s = read(kValid);
  EXPECT_EQ(s.system.name, "sparks");
  EXPECT_EQ(s.model, "models/crystal.obj");
  EXPECT_EQ(s.modelMeshes, std::vector<std::string>{"crystal"});
  EXPECT_EQ(s.system.seed, 3u);
  EXPECT_DOUBLE_EQ(s.system.prewarm, 0.5);
  EXPECT_NEAR(s.system.spin, M_PI / 2, 1e-12);
  ASSERT_EQ(s.system.emitters.size(), 1u);
  const Emitter& e = s.system.emitters[0];
  EXPECT_EQ(e.shape, EmitterShape::Box);
  EXPECT_NEAR(e.spread, M_PI / 6, 1e-7);
  EXPECT_DOUBLE_EQ(e.rate, 100.0);
  EXPECT_NEAR(e.direction.y, -1.0, 1e-12);
  ASSERT_FALSE(s.system.sizeOverLife.empty());
  EXPECT_NEAR(s.system.sizeOverLife.sample(0.5), 0.01, 1e-9);
  ASSERT_FALSE(s.system.colorOverLife.empty());  // one key: held
  EXPECT_NEAR(s.system.colorOverLife.sample(0.7).y, 0.5, 1e-7);
  EXPECT_FALSE(s.drawing.lightField);
  std::string lightField = kValid;
  lightField.replace(lightField.find("seed = 3"), 8,
                     "seed = 3\ndraw = \"light_field\"\nazimuths = 12\nelevations = 6\nresolution = 32\ninterpolate = false");
  const ParticleSettings l = read(lightField);
  EXPECT_TRUE(l.drawing.lightField);
  EXPECT_EQ(l.drawing.views, glm::ivec2(12, 6));
  EXPECT_EQ(l.drawing.resolution, 32);
  EXPECT_FALSE(l.drawing.interpolate);
}

// The message of reading `text`, which must name `key` and say `what`.
void expectError(const std::string& text, const std::string& key, const std::string& what) {
  const std::string message = errorOf([&] { read(text); });
  EXPECT_TRUE(contains(message, "particles.toml")) << message;
  EXPECT_TRUE(contains(message, key)) << message;
  EXPECT_TRUE(contains(message, what)) << message;
}

// A system with one emitter: `system` keys, then the emitter's `keys`.
std::string emitter(const std::string& keys, const std::string& system = "") {
  return "[[particles]]\nmodel = \"m.obj\"\n" + system +
         "[[particles.emitters]]\nposition = [0.0, 0.0, 0.0]\n" + keys;
}

TEST(ParticleFile, BadSettingsAreNamedErrors) {
  expectError("[[particles]]\n[[particles.emitters]]\nposition = [0.0, 0.0, 0.0]\nrate = 1.0\nlifetime = 1.0\n",
              "particles[0].model", "needs a model");
  expectError("[[particles]]\nmodel = \"m.obj\"\n", "particles[0].emitters", "at least one");
  expectError(emitter("rate = -5.0\nlifetime = 1.0\n"), "rate", "below the minimum");
  expectError(emitter("rate = 0.0\nlifetime = 1.0\n"), "rate", "above 0");
  expectError(emitter("rate = 10.0\nlifetime = 0.0\n"), "lifetime", "above 0");
  expectError(emitter("rate = 10.0\nlifetime = 1.0\nlifetime_variation = 1.0\n"),
              "lifetime_variation", "above 0");
  expectError(emitter("rate = 10.0\nlifetime = 1.0\nspeed = 1.0\nspeed_variation = 2.0\n"),
              "speed_variation", "negative");
  expectError(emitter("rate = 10.0\nlifetime = 1.0\nshape = \"cone\"\n"), "shape", "sphere");
  expectError(emitter("rate = 10.0\nlifetime = 1.0\nshape = \"sphere\"\n"), "radius", "");
  expectError(emitter("rate = 10.0\nlifetime = 1.0\ndirection = [0.0, 0.0, 0.0]\n"), "direction",
              "zero");
  expectError(emitter("rate = 10.0\nlifetime = 1.0\nspread_deg = 200.0\n"), "spread_deg", "above the maximum");
  expectError(emitter("rate = 10.0\nlifetime = 1.0\nbogus = 1\n"), "bogus", "");
  expectError("[[particles]]\nmodel = \"m.obj\"\n[[particles.over_life]]\nlife = 0.5\nsize = 1.0\n"
              "[[particles.over_life]]\nlife = 0.2\nsize = 1.0\n[[particles.emitters]]\n"
              "position = [0.0, 0.0, 0.0]\nrate = 1.0\nlifetime = 1.0\n",
              "life", "increasing");
  expectError(emitter("rate = 10.0\nlifetime = 1.0\n", "draw = \"light_field\"\nazimuths = 0\n"),
              "azimuths", "below the minimum");
  expectError(emitter("rate = 10.0\nlifetime = 1.0\n", "draw = \"light_field\"\nelevations = 0\n"),
              "elevations", "below the minimum");
  expectError(emitter("rate = 10.0\nlifetime = 1.0\n", "draw = \"impostor\"\n"),
              "draw", "light_field");
  expectError("[[particles]]\nmodel = \"m.obj\"\ncolor = [2.0, 0.0, 0.0]\n[[particles.emitters]]\n"
              "position = [0.0, 0.0, 0.0]\nrate = 1.0\nlifetime = 1.0\n",
              "color", "");
}

}  // namespace
}  // namespace lpvlab

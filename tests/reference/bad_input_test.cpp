// What the tracer cannot render is an Error whose message says what is wrong.

#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/reference/path_tracer.h"
#include "framework/scene/scene_loader.h"
#include "test_scenes.h"

namespace lpvlab {
namespace {

// Runs `action`, expecting an Error whose message contains `fragment`.
template <class Action>
void expectError(Action action, const std::string& fragment) {
  try {
    action();
    ADD_FAILURE() << "no Error; expected one mentioning '" << fragment << "'";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

TEST(BadInput, SceneWithoutTrianglesIsAnError) {
  const Scene box = makeCornellBox();
  Scene empty;
  empty.source = "test:empty";
  const Camera& camera = box.cameras.front();
  expectError([&] { PathTracer(empty, camera, 8, 8, {}); }, "has no triangles");
  Scene noIndices = empty;
  noIndices.materials = {{.name = "grey"}};
  noIndices.meshes = {testing::horizontalSquare("plane", 0, 1.0f, 0.0f)};
  noIndices.meshes[0].indices.clear();
  expectError([&] { PathTracer(noIndices, camera, 8, 8, {}); }, "test:empty' has no triangles");
}

TEST(BadInput, ImageWithoutPixelsIsAnError) {
  const Scene box = makeCornellBox();
  expectError([&] { PathTracer(box, box.cameras.front(), 0, 8, {}); }, "image size 0x8");
  expectError([&] { PathTracer(box, box.cameras.front(), 8, -1, {}); }, "image size 8x-1");
  expectError([&] { Accumulator(0, 0); }, "at least 1x1");
}

TEST(BadInput, NonFiniteOrDegenerateCameraIsAnError) {
  const Scene box = makeCornellBox();
  Camera camera = box.cameras.front();
  camera.position.x = NAN;
  expectError([&] { PathTracer(box, camera, 8, 8, {}); }, "position is not finite");
  camera = box.cameras.front();
  camera.verticalFov = INFINITY;
  expectError([&] { PathTracer(box, camera, 8, 8, {}); }, "vertical field of view is not finite");
  camera = box.cameras.front();
  camera.up = camera.forward;
  expectError([&] { PathTracer(box, camera, 8, 8, {}); }, "not parallel");
}

TEST(BadInput, MismatchedAccumulatorAndSettingsAreErrors) {
  const Scene box = makeCornellBox();
  const PathTracer tracer(box, box.cameras.front(), 8, 8, {});
  Accumulator wrong(8, 9);
  expectError([&] { tracer.render(wrong, 1, 1); }, "accumulator is 8x9");
  Accumulator right(8, 8);
  expectError([&] { tracer.render(right, -1, 1); }, "negative sample count");
  TracerSettings settings;
  settings.skyRadiance = glm::vec3(-1.0f);
  expectError([&] { PathTracer(box, box.cameras.front(), 8, 8, settings); }, "sky radiance");
}

TEST(BadInput, MalformedMaterialsAndLightsAreNamed) {
  Scene box = makeCornellBox();
  box.materials[0].baseColorTexture = 3;
  expectError([&] { PathTracer(box, box.cameras.front(), 8, 8, {}); },
              "material 'white': base colour texture 3 does not exist");
  box = makeCornellBox();
  box.lights[0].intensity = -1.0f;
  expectError([&] { PathTracer(box, box.cameras.front(), 8, 8, {}); },
              "light 'spot': negative colour or intensity");
}

TEST(BadInput, UnknownOrMissingInstructionSetsAndWidthsAreNamed) {
  const Scene box = makeCornellBox();
  const Camera& camera = box.cameras.front();
  TracerSettings settings;
  settings.engine.isa = "avx9";  // Embree itself would quietly fall back to SSE2
  expectError([&] { PathTracer(box, camera, 8, 8, settings); },
              "instruction set 'avx9' is not one of auto, sse4.2, avx, avx2, avx512");
  settings.engine.isa = "auto";
  settings.engine.packetWidth = 3;
  expectError([&] { PathTracer(box, camera, 8, 8, settings); }, "packet width 3 is not one of");
  settings.engine.packetWidth = 0;
  for (const std::string& isa : embreeInstructionSets()) {
    settings.engine.isa = isa;
    const std::vector<std::string> supported = supportedInstructionSets();
    if (std::find(supported.begin(), supported.end(), isa) == supported.end())
      expectError([&] { PathTracer(box, camera, 8, 8, settings); },
                  "this CPU lacks instruction set '" + isa + "'");
    else
      EXPECT_EQ(PathTracer(box, camera, 8, 8, settings).isa(), isa);
  }
}

}  // namespace
}  // namespace lpvlab

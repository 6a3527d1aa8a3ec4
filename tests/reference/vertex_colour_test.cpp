// Vertex colours (Mesh::colors) at a ray's hit: the three corners' colours interpolated with the
// hit's barycentrics, times the material's albedo (surfaceAlbedo), as the raster passes compute
// it; white for a mesh without them; and a mesh whose colours don't match its positions, or lie
// outside [0, 1], is a named error. (The furnace test renders with them: furnace_test.cpp.)

#include <gtest/gtest.h>

#include "error_support.h"
#include "framework/reference/embree_scene.h"
#include "test_scenes.h"

namespace lpvlab {
namespace {

SurfacePoint hitFromAbove(const EmbreeScene& embree, glm::vec2 at) {
  const glm::vec3 origin(at, 1.0f), direction(0, 0, -1);
  RayPacket packet;
  packet.set(0, origin, direction, 0.0f, 10.0f);
  embree.intersect(packet, false);
  EXPECT_TRUE(packet.hit(0)) << at.x << ", " << at.y;
  return surfaceAt(embree, packet.hitAt(0), origin, direction);
}

TEST(VertexColours, AHitGetsTheCornersColoursInterpolatedTimesTheMaterial) {
  const Scene scene = testing::colouredTriangle();
  const std::vector<SurfaceMaterial> materials = prepareMaterials(scene);
  const EmbreeScene embree(scene, materials);
  for (const glm::vec2 at : {glm::vec2(0.2f, 0.3f), glm::vec2(0.05f, 0.9f), glm::vec2(0.6f, 0.1f)}) {
    const SurfacePoint x = hitFromAbove(embree, at);
    // The point (a, b) of this triangle has barycentrics (1 - a - b, a, b).
    const glm::vec3 expected(1.0f - at.x - at.y, at.x, at.y);
    EXPECT_LT(glm::length(x.color - expected), 1e-5f) << at.x << ", " << at.y;
    EXPECT_LT(glm::length(surfaceAlbedo(x) - expected * glm::vec3(0.5f, 0.8f, 1.0f)), 1e-5f);
  }
  Scene plain = scene;
  plain.meshes[0].colors.clear();
  const EmbreeScene uncoloured(plain, materials);
  const SurfacePoint x = hitFromAbove(uncoloured, {0.2f, 0.3f});
  EXPECT_EQ(x.color, glm::vec3(1.0f));
  EXPECT_EQ(surfaceAlbedo(x), glm::vec3(0.5f, 0.8f, 1.0f));
}

TEST(VertexColours, MismatchedOrOutOfRangeColoursAreNamedErrors) {
  const auto errorFor = [](auto&& change) {
    Scene scene = testing::colouredTriangle();
    change(scene.meshes[0]);
    const std::vector<SurfaceMaterial> materials = prepareMaterials(scene);
    return test::errorOf([&] { EmbreeScene embree(scene, materials); });
  };
  EXPECT_TRUE(test::contains(errorFor([](Mesh& m) { m.colors.pop_back(); }),
                             "mesh 'triangle': has 2 vertex colours for 3 positions"));
  EXPECT_TRUE(test::contains(errorFor([](Mesh& m) { m.colors[1].g = 1.5f; }),
                             "mesh 'triangle': has a vertex colour outside [0, 1]"));
  EXPECT_TRUE(test::contains(errorFor([](Mesh& m) { m.colors[2].b = std::nanf(""); }),
                             "mesh 'triangle': has a vertex colour outside [0, 1]"));
}

}  // namespace
}  // namespace lpvlab

// Meshing into patches: counts, areas, welding, vertex colours and errors.
#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/radiosity/patches.h"
#include "radiosity_scenes.h"

namespace lpvlab {
namespace {

double totalArea(const PatchMesh& mesh) {
  double a = 0.0;
  for (const Patch& p : mesh.patches) a += p.area;
  return a;
}

TEST(Patches, UniformSubdivisionCutsEachTriangleIntoSquareCountPieces) {
  // A 1 x 1 quad: two triangles whose longest edge is the diagonal sqrt(2).
  const Scene scene = test::parallelRectangles(1.0f, 1.0f, 1.0f);
  for (float size : {2.0f, 0.5f, 0.1f}) {
    const PatchMesh mesh = meshPatches(scene, size, 1000000);
    const int m = int(std::ceil(std::sqrt(2.0) / size));
    EXPECT_EQ(mesh.patches.size(), std::size_t(2 * 2 * m * m)) << size;  // 2 quads, 2 triangles
    EXPECT_NEAR(totalArea(mesh), 2.0, 1e-5);
    for (const Patch& p : mesh.patches) {
      EXPECT_LE(glm::distance(p.corners[0], p.corners[1]), size * 1.0001f);
      EXPECT_LE(glm::distance(p.corners[0], p.corners[2]), size * 1.0001f);
      EXPECT_NEAR(glm::length(p.normal), 1.0f, 1e-6f);
    }
    // The welded vertices of one quad's grid: its two triangles share the diagonal's points.
    EXPECT_EQ(mesh.vertexCount, std::size_t(2 * (m + 1) * (m + 1))) << size;
  }
}

TEST(Patches, NormalsFollowTheWindingAndEmissionIsPiTimesRadiance) {
  Scene scene = test::closedCube(glm::vec3(0.5f), glm::vec3(2.0f, 0.0f, 1.0f));
  const PatchMesh mesh = meshPatches(scene, 0.5f, 100000);
  for (const Patch& p : mesh.patches) {
    // Inward: towards the cube's centre.
    EXPECT_GT(glm::dot(p.normal, glm::vec3(0.5f) - p.centroid), 0.0f);
    EXPECT_FLOAT_EQ(p.exitance.x, float(M_PI) * 2.0f);
    EXPECT_FLOAT_EQ(p.exitance.y, 0.0f);
    EXPECT_EQ(p.albedo, glm::vec3(0.5f));
  }
}

TEST(Patches, SplittingMakesFourChildrenOfTheSameArea) {
  const Scene scene = test::parallelRectangles(1.0f, 1.0f, 1.0f);
  const PatchMesh mesh = meshPatches(scene, 2.0f, 1000);
  std::vector<bool> split(mesh.patches.size(), false);
  split[0] = split[3] = true;
  const PatchMesh finer = splitPatches(scene, mesh, split);
  EXPECT_EQ(finer.patches.size(), mesh.patches.size() + 6);
  EXPECT_NEAR(totalArea(finer), totalArea(mesh), 1e-5);
  int children = 0;
  for (const Patch& p : finer.patches) children += p.level == 1;
  EXPECT_EQ(children, 8);
  for (std::size_t p = 1; p < finer.patches.size(); ++p) EXPECT_GE(finer.patches[p].mesh, finer.patches[p - 1].mesh);
}

// Vertex colours linear across a triangle: a patch's albedo is the material's times the colour at
// the patch's centroid (the mean of a linear colour over a triangle is its value there, and the
// patch's 10 sample points average to the centroid), for the uniform meshing and for split
// children alike; the colour is found independently from the centroid's position.
TEST(Patches, VertexColoursGiveEachPatchTheColourAtItsCentroid) {
  Scene scene = testing::colouredTriangle();  // the point (a, b, 0) has colour (1 - a - b, a, b)
  const auto expectCentroidColour = [&](const PatchMesh& patches) {
    for (const Patch& p : patches.patches) {
      const glm::vec3 colour(1.0f - p.centroid.x - p.centroid.y, p.centroid.x, p.centroid.y);
      EXPECT_LT(glm::length(p.albedo - colour * glm::vec3(0.5f, 0.8f, 1.0f)), 1e-5f)
          << "level " << p.level << " at " << p.centroid.x << ", " << p.centroid.y;
    }
  };
  const PatchMesh coarse = meshPatches(scene, 0.3f, 1000);
  EXPECT_EQ(coarse.patches.size(), 25u);  // sqrt(2) / 0.3 -> 5 x 5
  expectCentroidColour(coarse);
  const PatchMesh finer = splitPatches(scene, coarse, std::vector<bool>(coarse.patches.size(), true));
  EXPECT_EQ(finer.patches.size(), 100u);
  expectCentroidColour(finer);

  scene.meshes[0].colors.assign(3, glm::vec3(0.5f, 0.25f, 1.0f));  // uniform: exact products
  for (const Patch& p : meshPatches(scene, 0.3f, 1000).patches)
    EXPECT_EQ(p.albedo, glm::vec3(0.25f, 0.2f, 1.0f));
}

TEST(Patches, DegenerateTrianglesMakeNoPatches) {
  Scene scene = test::parallelRectangles(1.0f, 1.0f, 1.0f);
  Mesh line;
  line.name = "sliver";
  line.positions = {glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(2, 0, 0)};
  line.normals = {glm::vec3(0, 1, 0), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0)};
  line.uvs = {glm::vec2(0), glm::vec2(0), glm::vec2(0)};
  line.indices = {0, 1, 2};
  scene.meshes.push_back(line);
  const PatchMesh mesh = meshPatches(scene, 0.5f, 100000);
  for (const Patch& p : mesh.patches) {
    EXPECT_NE(p.mesh, 2);
    EXPECT_GT(p.area, 0.0f);
  }
}

TEST(Patches, BadSizesAndTooManyPatchesAreNamedErrors) {
  const Scene scene = test::parallelRectangles(1.0f, 1.0f, 1.0f);
  for (float bad : {0.0f, -1.0f, std::numeric_limits<float>::infinity(), std::nanf("")})
    EXPECT_THROW(meshPatches(scene, bad, 1000), Error) << bad;
  try {
    meshPatches(scene, 0.001f, 1000);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("max_patches"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lpvlab

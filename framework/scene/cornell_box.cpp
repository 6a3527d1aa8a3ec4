// The Cornell box as measured by the Cornell Program of Computer Graphics ("Cornell Box Data",
// https://www.graphics.cornell.edu/online/box/data.html), millimetres converted to metres.
// The real box is not quite rectangular: the quads below are the published corners.

#include <array>

#include "framework/scene/scene_loader.h"

namespace lpvlab {
namespace {

using Quad = std::array<glm::vec3, 4>;  // published corners, millimetres

constexpr float kMetresPerMm = 0.001f;

enum class Facing { TowardsCentre, AwayFromCentre };

// Adds a quad as two triangles with their own vertices and flat normals, each wound
// counter-clockwise seen from the side its normal points to. Which side that is comes from a
// reference point: the room's centre (walls face into the room) or a block's centre (its faces
// face out), so the published corner order does not matter.
void addQuad(Mesh& mesh, const Quad& quadMm, const glm::vec3& centreMm, Facing facing) {
  const std::array<std::array<int, 3>, 2> halves{{{0, 1, 2}, {0, 2, 3}}};
  for (const auto& half : halves) {
    glm::vec3 a = quadMm[half[0]], b = quadMm[half[1]], c = quadMm[half[2]];
    glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
    const float towardsCentre = glm::dot(normal, centreMm - (a + b + c) / 3.0f);
    if ((facing == Facing::TowardsCentre) != (towardsCentre > 0.0f)) {
      std::swap(b, c);
      normal = -normal;
    }
    for (const glm::vec3& p : {a, b, c}) {
      mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
      mesh.positions.push_back(p * kMetresPerMm);
      mesh.normals.push_back(normal);
      mesh.uvs.push_back(glm::vec2(0.0f));
    }
  }
}

Mesh roomSurface(const char* name, int material, const Quad& quadMm) {
  const glm::vec3 roomCentreMm{278.0f, 274.4f, 279.6f};
  Mesh mesh;
  mesh.name = name;
  mesh.material = material;
  addQuad(mesh, quadMm, roomCentreMm, Facing::TowardsCentre);
  return mesh;
}

// A block: its top and four sides (it stands on the floor, so the data has no bottom).
Mesh block(const char* name, int material, const Quad& topMm, const std::array<Quad, 4>& sidesMm) {
  const glm::vec3 centreMm =
      (topMm[0] + topMm[1] + topMm[2] + topMm[3]) * 0.25f * glm::vec3(1.0f, 0.5f, 1.0f);
  Mesh mesh;
  mesh.name = name;
  mesh.material = material;
  addQuad(mesh, topMm, centreMm, Facing::AwayFromCentre);
  for (const Quad& side : sidesMm) addQuad(mesh, side, centreMm, Facing::AwayFromCentre);
  return mesh;
}

}  // namespace

Scene makeCornellBox() {
  Scene scene;
  scene.source = "builtin:cornell_box";

  // Lambertian reflectances of the usual Cornell box renderings (as in CornellBox-Original.mtl).
  enum { kWhite, kRed, kGreen };
  scene.materials = {
      {.name = "white", .baseColor = {0.725f, 0.71f, 0.68f}},
      {.name = "red", .baseColor = {0.63f, 0.065f, 0.05f}},
      {.name = "green", .baseColor = {0.14f, 0.45f, 0.091f}},
  };

  scene.meshes = {
      roomSurface("floor", kWhite,
                  {{{552.8f, 0, 0}, {0, 0, 0}, {0, 0, 559.2f}, {549.6f, 0, 559.2f}}}),
      roomSurface("ceiling", kWhite,
                  {{{556.0f, 548.8f, 0}, {556.0f, 548.8f, 559.2f}, {0, 548.8f, 559.2f},
                    {0, 548.8f, 0}}}),
      roomSurface("back wall", kWhite,
                  {{{549.6f, 0, 559.2f}, {0, 0, 559.2f}, {0, 548.8f, 559.2f},
                    {556.0f, 548.8f, 559.2f}}}),
      roomSurface("right wall", kGreen,
                  {{{0, 0, 559.2f}, {0, 0, 0}, {0, 548.8f, 0}, {0, 548.8f, 559.2f}}}),
      roomSurface("left wall", kRed,
                  {{{552.8f, 0, 0}, {549.6f, 0, 559.2f}, {556.0f, 548.8f, 559.2f},
                    {556.0f, 548.8f, 0}}}),
      block("short block", kWhite,
            {{{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}},
            {{{{{290, 0, 114}, {290, 165, 114}, {240, 165, 272}, {240, 0, 272}}},
              {{{130, 0, 65}, {130, 165, 65}, {290, 165, 114}, {290, 0, 114}}},
              {{{82, 0, 225}, {82, 165, 225}, {130, 165, 65}, {130, 0, 65}}},
              {{{240, 0, 272}, {240, 165, 272}, {82, 165, 225}, {82, 0, 225}}}}}),
      block("tall block", kWhite,
            {{{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}},
            {{{{{423, 0, 247}, {423, 330, 247}, {472, 330, 406}, {472, 0, 406}}},
              {{{472, 0, 406}, {472, 330, 406}, {314, 330, 456}, {314, 0, 456}}},
              {{{314, 0, 456}, {314, 330, 456}, {265, 330, 296}, {265, 0, 296}}},
              {{{265, 0, 296}, {265, 330, 296}, {423, 330, 247}, {423, 0, 247}}}}}),
  };

  // The published camera: 35 mm focal length, 25 mm film, so a vertical FOV of
  // 2 atan(12.5 / 35) = 39.31 degrees.
  scene.cameras.push_back({.name = "default",
                           .position = {0.278f, 0.273f, -0.8f},
                           .forward = {0, 0, 1},
                           .up = {0, 1, 0},
                           .verticalFov = glm::radians(39.31f),
                           .nearPlane = 0.01f,
                           .farPlane = 10.0f});

  // The measured light is a 130 x 105 mm Lambertian quad under the ceiling with radiance
  // (17, 12, 4) W/(m^2 sr). lpvlab's injection wants a punctual light, so it is replaced by a
  // spot 1 mm under the ceiling's centre with the same on-axis radiant intensity, radiance times
  // area: colour (17, 12, 4) / 17, intensity 17 * 0.130 * 0.105 W/sr. Its 120 degree cone stays
  // below the horizontal, so the ceiling gets only indirect light, as under the real light.
  scene.lights.push_back({.name = "spot",
                          .type = LightType::Spot,
                          .position = {0.278f, 0.5478f, 0.2795f},
                          .direction = {0, -1, 0},
                          .color = glm::vec3(17.0f, 12.0f, 4.0f) / 17.0f,
                          .intensity = 17.0f * 0.130f * 0.105f,
                          .innerConeAngle = glm::radians(55.0f),
                          .outerConeAngle = glm::radians(60.0f)});
  return scene;
}

}  // namespace lpvlab

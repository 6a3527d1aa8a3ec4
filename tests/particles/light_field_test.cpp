// The light field's capture (framework/particles/light_field.h) against a brute-force ray caster
// over the model's triangles in double precision: every texel of a view is the model seen along
// the view's direction through the texel's point of the view's plane, so where the ray hits, the
// texel must be covered with the hit triangle's albedo and normal and the hit's offset along the
// view direction, and where it misses, uncovered. Rasterisation samples texel centres too, so
// only texels whose ray grazes an edge may differ.

#include "framework/particles/light_field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "crystal_model.h"
#include "framework/core/error.h"
#include "support/pipeline_test_support.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/particles/light_field_views.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

TEST(LightField, EveryViewIsTheModelSeenAlongItsDirection) {
  test::glTestContext();
  const ParticleModel model = test::crystalModel();
  ShaderCompiler shaders;
  const LightFieldSettings settings{.views = {8, 4}, .resolution = 48};
  const LightField field(model, settings, shaders);
  Scene modelScene;
  modelScene.meshes = model.meshes;
  modelScene.materials = model.materials;
  const test::SceneRaycaster caster(modelScene);
  const double r = field.radius();
  const int n = settings.resolution;
  int texels = 0, agree = 0, covered = 0, compared = 0, exact = 0;
  double worstAlbedo = 0.0;
  for (int j = 0; j < settings.views.y; ++j)
    for (int i = 0; i < settings.views.x; ++i) {
      const int layer = j * settings.views.x + i;
      const std::vector<glm::vec4> albedo = field.read(field.albedo(), layer);
      const std::vector<glm::vec4> normal = field.read(field.normalOffset(), layer);
      const glm::dvec3 d = shared::lightFieldViewDirection(i, j, settings.views);
      const glm::dvec3 up = shared::lightFieldUp(d), right = shared::lightFieldRight(d);
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const glm::dvec3 plane = r * ((2.0 * (x + 0.5) / n - 1.0) * right + (2.0 * (y + 0.5) / n - 1.0) * up);
          const auto hit = caster.cast(plane + 2.0 * r * d, -d);
          const glm::vec4 a = albedo[std::size_t(y * n + x)], no = normal[std::size_t(y * n + x)];
          ++texels;
          const bool seen = a.w > 0.5f;
          agree += seen == bool(hit);
          covered += bool(hit);
          if (!hit || !seen) continue;
          ++compared;
          const glm::dvec3 point = plane + 2.0 * r * d - hit->t * d;
          glm::dvec3 expectedNormal = hit->normal;
          if (glm::dot(expectedNormal, d) < 0.0) expectedNormal = -expectedNormal;
          // Half floats hold the offset to about 5e-4 of the model's size.
          exact += std::abs(double(no.w) - glm::dot(point, d)) < 2e-3 &&
                   glm::dot(glm::dvec3(no), expectedNormal) > 1.0 - 1e-3;
          worstAlbedo = std::max(worstAlbedo, double(glm::length(glm::vec3(a) - caster.material(*hit).baseColor)));
        }
    }
  std::cout << "[ light field ] " << covered << " of " << texels << " texels cover the model; capture and "
            << "rays agree at " << agree << "; offset and normal as the ray's at " << exact << " of "
            << compared << "; worst albedo " << worstAlbedo << "\n";
  EXPECT_GT(covered, texels / 10);
  EXPECT_GE(agree, texels - texels / 50);  // edge texels only
  EXPECT_LT(worstAlbedo, 2e-3);  // one material: half-float rounding only
  // A texel whose centre ray grazes a ridge between two faces may show the other face.
  EXPECT_GE(exact, compared - compared / 50);
}

// The bounds of each view's image (what the billboards cut their squares to) hold every texel the
// capture covered, and are tight: each edge within a few texels of a covered texel's centre (a
// texel's margin, half a texel to the centre, and the crystal's pointed tips, whose last texel
// centres fall short of the vertex).
TEST(LightField, EachViewsBoundsHoldItsImageTightly) {
  test::glTestContext();
  const ParticleModel model = test::crystalModel();
  ShaderCompiler shaders;
  const LightFieldSettings settings{.views = {8, 4}, .resolution = 48};
  const LightField field(model, settings, shaders);
  ASSERT_EQ(field.viewBounds().size(), std::size_t(settings.views.x * settings.views.y));
  const int n = settings.resolution;
  const float texel = 2.0f / float(n);
  int outside = 0;
  float loosest = 0.0f;  // texels
  double area = 0.0;
  for (int layer = 0; layer < int(field.viewBounds().size()); ++layer) {
    const glm::vec4 b = field.viewBounds()[std::size_t(layer)];
    const std::vector<glm::vec4> albedo = field.read(field.albedo(), layer);
    glm::vec2 lo(1.0f), hi(-1.0f);  // of the covered texels' centres
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        if (albedo[std::size_t(y * n + x)].w <= 0.0f) continue;
        const glm::vec2 centre(2.0f * (x + 0.5f) / n - 1.0f, 2.0f * (y + 0.5f) / n - 1.0f);
        outside += centre.x < b.x || centre.y < b.y || centre.x > b.z || centre.y > b.w;
        lo = glm::min(lo, centre);
        hi = glm::max(hi, centre);
      }
    loosest = std::max({loosest, (lo.x - b.x) / texel, (lo.y - b.y) / texel, (b.z - hi.x) / texel,
                        (b.w - hi.y) / texel});
    area += double(b.z - b.x) * double(b.w - b.y) / 4.0;
  }
  std::cout << "[ light field ] view bounds: " << outside << " covered texels outside, the loosest edge "
            << loosest << " texels from a covered texel's centre; mean area "
            << area / double(field.viewBounds().size()) << " of the square\n";
  EXPECT_EQ(outside, 0);
  EXPECT_LT(loosest, 4.0f);
}

TEST(LightField, BadSettingsAreErrors) {
  test::glTestContext();
  const ParticleModel model = test::crystalModel();
  ShaderCompiler shaders;
  EXPECT_THROW(LightField(model, LightFieldSettings{.views = {0, 4}, .resolution = 8}, shaders), Error);
  EXPECT_THROW(LightField(model, LightFieldSettings{.views = {4, 4}, .resolution = 0}, shaders), Error);
}

}  // namespace
}  // namespace lpvlab

// A light-field billboard (framework/particles/particle_billboards.h) seen exactly from one of the
// captured directions shows that view of the light field: drawn into the camera's G-buffer by a
// far camera along the view's direction with the view's up vector, whose pixels then lie on the
// view's texel centres, its coverage is the captured coverage and its albedo the captured albedo
// (to half-float rounding), for the nearest view and for interpolation (whose weights there are
// all on that view).

#include "framework/particles/particle_billboards.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "crystal_model.h"
#include "framework/core/error.h"
#include "framework/math/shared.h"
#include "framework/pipeline/raster_passes.h"
#include "gl/gl_test_context.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/particles/light_field_views.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {
namespace {

// Level 0 of a 2D RGBA32F texture, rows from the bottom.
std::vector<glm::vec4> readTexture(const gl::Texture& texture) {
  std::vector<glm::vec4> texels(std::size_t(texture.width()) * std::size_t(texture.height()));
  glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(glm::vec4)), texels.data());
  return texels;
}

void expectTheCapturedView(bool interpolate) {
  test::glTestContext();
  ShaderCompiler shaders;
  const ParticleModel model = test::crystalModel();
  const int resolution = 40;
  const ParticleDrawing drawing{.lightField = true, .views = {8, 4}, .resolution = resolution, .interpolate = interpolate};
  ParticleBillboards billboards(model, drawing, 1, shaders);
  const double size = 0.5, distance = 1000.0;
  Particle particle;
  particle.position = {1.0, 2.0, 3.0};
  particle.size = size;  // orientation: identity, so object and world directions agree
  billboards.update({particle});

  const SceneGpu gpu(test::nothingInView());
  GBufferPass pass(shaders, resolution, resolution, false);
  const double halfWidth = size * billboards.lightField().radius();
  int texels = 0, agree = 0, covered = 0, close = 0;
  for (const auto& [i, j] : {std::pair{0, 1}, std::pair{3, 2}, std::pair{6, 0}, std::pair{5, 3}}) {
    const glm::dvec3 d = shared::lightFieldViewDirection(i, j, drawing.views);
    Camera camera;
    camera.position = glm::vec3(particle.position + distance * d);
    camera.forward = glm::vec3(-d);
    camera.up = glm::vec3(shared::lightFieldUp(d));
    camera.verticalFov = float(2.0 * std::atan(halfWidth / distance));
    camera.nearPlane = float(distance - 2.0);
    camera.farPlane = float(distance + 2.0);
    pass.render(gpu, camera, {&billboards});
    const std::vector<glm::vec4> image = readTexture(pass.gbuffer().albedo);
    const int layer = j * drawing.views.x + i;
    const std::vector<glm::vec4> captured = billboards.lightField().read(billboards.lightField().albedo(), layer);
    for (std::size_t t = 0; t < image.size(); ++t) {
      ++texels;
      const bool seen = image[t].w > 0.5f, capturedSeen = captured[t].w > 0.5f;
      agree += seen == capturedSeen;
      if (!seen || !capturedSeen) continue;
      ++covered;
      close += glm::length(glm::vec3(image[t]) - glm::vec3(captured[t]) / captured[t].w) < 2e-3f;
    }
  }
  std::cout << "[ billboards ] " << (interpolate ? "interpolated" : "nearest") << ": coverage agrees at "
            << agree << " of " << texels << " pixels, albedo at " << close << " of " << covered << "\n";
  EXPECT_GT(covered, texels / 10);
  EXPECT_GE(agree, texels - texels / 100);
  EXPECT_GE(close, covered - covered / 100);
}

TEST(ParticleBillboards, ABillboardSeenFromACapturedDirectionShowsThatView) { expectTheCapturedView(false); }
TEST(ParticleBillboards, InterpolationSeenFromACapturedDirectionShowsThatViewToo) { expectTheCapturedView(true); }

TEST(ParticleBillboards, MoreParticlesThanTheirCapacityAreAnError) {
  test::glTestContext();
  ShaderCompiler shaders;
  ParticleBillboards billboards(test::crystalModel(), ParticleDrawing{.lightField = true, .views = {4, 2}, .resolution = 8}, 2, shaders);
  billboards.update(std::vector<Particle>(2));
  EXPECT_EQ(billboards.count(), 2u);
  EXPECT_THROW(billboards.update(std::vector<Particle>(3)), Error);
}

}  // namespace
}  // namespace lpvlab

#include "framework/particles/light_field.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "framework/core/error.h"
#include "framework/math/shared.h"
#include "framework/pipeline/raster_passes.h"
#include "framework/pipeline/scene_gpu.h"

LPVLAB_SHARED_GLSL_BEGIN
#include "shaders/particles/light_field_views.glsl"
LPVLAB_SHARED_GLSL_END

namespace lpvlab {

namespace capture_kernel {
#include "shaders/particles/capture_interface.glsl"
}

namespace {

int mipLevels(int resolution) { return 1 + int(std::floor(std::log2(double(resolution)))); }

glm::vec3 viewDirection(int i, int j, glm::ivec2 views) {
  return glm::vec3(shared::lightFieldViewDirection(i, j, views));
}

// Each view's image of the model: its vertices projected onto the view's axes (a triangle's image
// lies within its corners'), widened by a texel each side for rasterisation at texel centres
// and clamped to the square.
std::vector<glm::vec4> imageBounds(const ParticleModel& model, const LightFieldSettings& settings, float radius) {
  const float texel = 2.0f / float(settings.resolution);
  std::vector<glm::vec4> bounds;
  for (int j = 0; j < settings.views.y; ++j)
    for (int i = 0; i < settings.views.x; ++i) {
      const glm::dvec3 d = shared::lightFieldViewDirection(i, j, settings.views);
      const glm::vec3 right(shared::lightFieldRight(d)), up(shared::lightFieldUp(d));
      glm::vec2 lo(1.0f), hi(-1.0f);
      for (const Mesh& mesh : model.meshes)
        for (const glm::vec3& p : mesh.positions) {
          const glm::vec2 image(glm::dot(p, right) / radius, glm::dot(p, up) / radius);
          lo = glm::min(lo, image);
          hi = glm::max(hi, image);
        }
      lo = glm::clamp(lo - texel, -1.0f, 1.0f);
      hi = glm::clamp(hi + texel, -1.0f, 1.0f);
      bounds.emplace_back(lo, hi);
    }
  return bounds;
}

}  // namespace

glm::mat4 LightField::clipFromObject(int i, int j, glm::ivec2 views, float radius) {
  const shared::vec3 d = shared::lightFieldViewDirection(i, j, views);
  const glm::vec3 up(shared::lightFieldUp(d));
  const glm::vec3 eye = 2.0f * radius * glm::vec3(d);
  // lookAt's right is cross(forward, up) = cross(-d, up) = up x d: lightFieldRight.
  return glm::ortho(-radius, radius, -radius, radius, radius, 3.0f * radius) *
         glm::lookAt(eye, glm::vec3(0.0f), up);
}

LightField::LightField(const ParticleModel& model, const LightFieldSettings& settings,
                       ShaderCompiler& shaders)
    : settings_(settings) {
  if (settings.views.x < 1 || settings.views.y < 1 || settings.views.x > 1024 || settings.views.y > 1024)
    throw Error("light field: the view grid must have 1 to 1024 azimuths and elevations, not " +
                std::to_string(settings.views.x) + " x " + std::to_string(settings.views.y));
  if (settings.resolution < 1 || settings.resolution > 4096)
    throw Error("light field: a view's resolution must be 1 to 4096 texels, not " +
                std::to_string(settings.resolution));
  GLint maxLayers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
  const int layers = settings.views.x * settings.views.y;
  if (layers > maxLayers)
    throw Error("light field: " + std::to_string(layers) + " views exceed the " +
                std::to_string(maxLayers) + " layers this GL's array textures hold");
  for (const Mesh& mesh : model.meshes)
    for (const glm::vec3& p : mesh.positions) radius_ = std::max(radius_, glm::length(p));
  if (!(radius_ > 0.0f)) throw Error("light field: the model " + model.source + " has no extent");

  const int r = settings.resolution, levels = mipLevels(r);
  albedo_ = gl::Texture(GL_TEXTURE_2D_ARRAY, GL_RGBA16F, r, r, layers, "light field albedo", levels);
  normalOffset_ = gl::Texture(GL_TEXTURE_2D_ARRAY, GL_RGBA16F, r, r, layers, "light field normal", levels);
  gl::Texture depth(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, r, r, 1, "light field capture depth");

  Scene scene;
  scene.source = model.source;
  scene.meshes = model.meshes;
  scene.materials = model.materials;
  scene.textures = model.textures;
  const SceneGpu gpu(scene);
  const Program program = shaders.graphics("raster/scene.vert", "particles/capture.frag");
  program.use();
  for (int j = 0; j < settings.views.y; ++j)
    for (int i = 0; i < settings.views.x; ++i) {
      const int layer = j * settings.views.x + i;
      gl::Framebuffer framebuffer;
      framebuffer.attach(GL_COLOR_ATTACHMENT0, albedo_, layer);
      framebuffer.attach(GL_COLOR_ATTACHMENT1, normalOffset_, layer);
      framebuffer.attach(GL_DEPTH_ATTACHMENT, depth);
      framebuffer.checkComplete("light field view " + std::to_string(layer));
      beginRaster(framebuffer, r, r, 2);
      const glm::mat4 clip = clipFromObject(i, j, settings.views, radius_);
      const glm::vec3 d = viewDirection(i, j, settings.views);
      glUniformMatrix4fv(scene_vertex::LOCATION_CLIP_FROM_WORLD, 1, GL_FALSE, &clip[0][0]);
      glUniform3fv(capture_kernel::LOCATION_VIEW_DIRECTION, 1, &d[0]);
      gpu.draw();
    }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  viewBounds_ = imageBounds(model, settings, radius_);
  viewBoundsBuffer_ = gl::Buffer(viewBounds_.size() * sizeof(glm::vec4), "light field view bounds", viewBounds_.data());
  for (const gl::Texture* t : {&albedo_, &normalOffset_}) {
    glGenerateTextureMipmap(t->id());
    glTextureParameteri(t->id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(t->id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  }
  checkGl("light field capture");
}

std::size_t LightField::memoryBytes() const {
  // Each mip level a quarter of the one before: at most 4/3 of level 0.
  std::size_t bytes = 0;
  for (const gl::Texture* t : {&albedo_, &normalOffset_}) {
    std::size_t level = t->bytes();
    for (int l = 0; l < mipLevels(settings_.resolution); ++l, level /= 4) bytes += level;
  }
  return bytes;
}

std::vector<glm::vec4> LightField::read(const gl::Texture& texture, int layer) const {
  const int r = settings_.resolution;
  std::vector<glm::vec4> texels(std::size_t(r) * std::size_t(r));
  glGetTextureSubImage(texture.id(), 0, 0, 0, layer, r, r, 1, GL_RGBA, GL_FLOAT,
                       GLsizei(texels.size() * sizeof(glm::vec4)), texels.data());
  checkGl("light field read");
  return texels;
}

}  // namespace lpvlab

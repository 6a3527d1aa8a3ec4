#include "framework/pipeline/dual_image.h"

#include "framework/gl/context.h"

namespace lpvlab {

DualImage::DualImage(int width, int height, const std::string& label)
    : gl_(GL_TEXTURE_2D, GL_RGBA32F, width, height, 1, label) {}

void DualImage::toGl() const {
  if (!GlContext::glLoaded()) gl::noGl("image '" + gl_.label() + "' on GL");
  // gl::Texture's writes are not const: the GL object changes, its handle does not.
  auto& texture = const_cast<gl::Texture&>(gl_);
  if (glSide_ == Side::Zero) {
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(texture.id(), 0, GL_RGBA, GL_FLOAT, zero);
  } else if (glSide_ == Side::Stale) {
    uploadImage(host_, texture);
  }
  glSide_ = Side::Current;
}

void DualImage::toHost() const {
  if (hostSide_ == Side::Zero) {
    host_.width = gl_.width();
    host_.height = gl_.height();
    host_.layers = 1;
    host_.texels.assign(std::size_t(host_.width) * host_.height, glm::vec4(0.0f));
  } else if (hostSide_ == Side::Stale) {
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // after GL's image writes
    downloadImage(gl_, host_);  // into the last copy's storage: no allocation
  }
  hostSide_ = Side::Current;
}

gl::Texture& DualImage::texture() {
  toGl();
  hostSide_ = Side::Stale;
  return gl_;
}

HostImage& DualImage::host() {
  toHost();
  glSide_ = Side::Stale;
  return host_;
}

const HostImage& DualImage::hostRead() const {
  toHost();
  return host_;
}

void DualImage::zero() {
  glSide_ = Side::Zero;
  hostSide_ = Side::Zero;
}

}  // namespace lpvlab

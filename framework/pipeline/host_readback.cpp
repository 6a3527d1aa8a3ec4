#include "framework/pipeline/host_readback.h"

#include <algorithm>

#include "framework/core/error.h"

namespace lpvlab {

void downloadFloats(const gl::Buffer& buffer, std::size_t floats, std::vector<float>& host) {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  host.resize(floats);
  buffer.download(host.data(), floats * sizeof(float));
}

void uploadFloats(const std::vector<float>& host, gl::Buffer& buffer) {
  buffer.upload(host.data(), host.size() * sizeof(float));
}

namespace {

// Level 0 of `texture`, every layer, as `format` (one T per texel: a vec4 or a float) into
// `values` (resized), and the image's size.
template <class Image, class T>
void downloadLevel0(const gl::Texture& texture, GLenum format, Image& image, std::vector<T>& values,
                    const char* what) {
  image.width = texture.width();
  image.height = texture.height();
  image.layers = std::max(1, texture.depth());
  values.resize(std::size_t(image.width) * image.height * image.layers);
  glGetTextureImage(texture.id(), 0, format, GL_FLOAT, GLsizei(values.size() * sizeof(T)),
                    values.data());
  checkGl(what);
}

}  // namespace

void downloadImage(const gl::Texture& texture, HostImage& image) {
  downloadLevel0(texture, GL_RGBA, image, image.texels, "reading an image back for the CPU backend");
}

void downloadDepth(const gl::Texture& texture, HostDepthImage& image) {
  downloadLevel0(texture, GL_DEPTH_COMPONENT, image, image.depths,
                 "reading a depth image back for the CPU backend");
}

HostImage downloadImage(const gl::Texture& texture) {
  HostImage image;
  downloadImage(texture, image);
  return image;
}

void uploadImage(const HostImage& image, gl::Texture& texture) {
  if (image.width != texture.width() || image.height != texture.height() || image.layers != 1)
    throw Error("CPU backend: a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                " image cannot replace a " + std::to_string(texture.width()) + "x" +
                std::to_string(texture.height()) + " texture");
  glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT,
                      image.texels.data());
  checkGl("uploading an image from the CPU backend");
}

void HostReadback::newFrame() {
  for (auto& [id, copy] : images_) copy.current = false;
  for (auto& [id, copy] : depths_) copy.current = false;
}

const HostImage& HostReadback::image(const gl::Texture& texture) {
  Copy<HostImage>& copy = images_[texture.id()];
  if (!copy.current) {
    downloadImage(texture, copy.image);  // into last frame's storage: no allocation
    copy.current = true;
  }
  return copy.image;
}

const HostDepthImage& HostReadback::depth(const gl::Texture& texture) {
  Copy<HostDepthImage>& copy = depths_[texture.id()];
  if (!copy.current) {
    downloadDepth(texture, copy.image);
    copy.current = true;
  }
  return copy.image;
}

}  // namespace lpvlab

#include "framework/pipeline/host_readback.h"

#include <algorithm>

#include "framework/core/error.h"

namespace lpvlab {

Image toImage(const HostImage& rgba, int channels, int firstChannel) {
  const int w = rgba.width, h = rgba.height;
  Image image(w, h, channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c)
        image.at(x, h - 1 - y, c) = rgba.texels[std::size_t(y) * w + x][firstChannel + c];
  return image;
}

void downloadFloats(const gl::Buffer& buffer, std::size_t floats, std::vector<float>& host) {
  gl::barrier(GL_BUFFER_UPDATE_BARRIER_BIT);
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

namespace {

// Checks that `image` has the texture's size and layers before an upload.
template <class Image>
void checkUploadSize(const Image& image, const gl::Texture& texture) {
  if (image.width != texture.width() || image.height != texture.height() ||
      image.layers != std::max(1, texture.depth()))
    throw Error("ray-cast raster: a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                "x" + std::to_string(image.layers) + " image cannot fill a " +
                std::to_string(texture.width()) + "x" + std::to_string(texture.height()) + "x" +
                std::to_string(std::max(1, texture.depth())) + " texture");
}

template <class Image>
void sizeLike(const gl::Texture& texture, Image& image, std::size_t& count) {
  image.width = texture.width();
  image.height = texture.height();
  image.layers = std::max(1, texture.depth());
  count = std::size_t(image.width) * image.height * image.layers;
}

}  // namespace

void uploadLayers(const HostImage& image, const gl::Texture& texture) {
  checkUploadSize(image, texture);
  if (texture.target() == GL_TEXTURE_2D_ARRAY)
    glTextureSubImage3D(texture.id(), 0, 0, 0, 0, image.width, image.height, image.layers, GL_RGBA,
                        GL_FLOAT, image.texels.data());
  else
    glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT,
                        image.texels.data());
  checkGl("uploading a host-made raster image");
}

void uploadDepth(const HostDepthImage& depths, const gl::Texture& texture) {
  checkUploadSize(depths, texture);
  if (texture.target() == GL_TEXTURE_2D_ARRAY)
    glTextureSubImage3D(texture.id(), 0, 0, 0, 0, depths.width, depths.height, depths.layers,
                        GL_DEPTH_COMPONENT, GL_FLOAT, depths.depths.data());
  else
    glTextureSubImage2D(texture.id(), 0, 0, 0, depths.width, depths.height, GL_DEPTH_COMPONENT,
                        GL_FLOAT, depths.depths.data());
  checkGl("uploading a host-made depth image");
}

template <class Image, class T>
Image& HostReadback::written(std::map<unsigned, Copy<Image>>& copies, const gl::Texture& texture,
                             std::vector<T> Image::*values) {
  Copy<Image>& copy = copies[texture.id()];
  std::size_t count = 0;
  sizeLike(texture, copy.image, count);
  (copy.image.*values).resize(count);
  copy.current = true;
  return copy.image;
}

HostImage& HostReadback::written(const gl::Texture& texture) {
  return written(images_, texture, &HostImage::texels);
}

HostDepthImage& HostReadback::writtenDepth(const gl::Texture& texture) {
  return written(depths_, texture, &HostDepthImage::depths);
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

#pragma once
// Images of a frame on the CPU for strategies on the CPU backend: read back from GL at most once
// per frame, the first time a CPU strategy asks for one, or made on the host by the ray-cast raster
// passes (host_raster.h), which write them here instead. Texels are RGBA floats, bottom row
// first, as GL stores them.

#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "framework/gl/resources.h"
#include "framework/io/image.h"

namespace lpvlab {

struct HostImage {
  int width = 0, height = 0;
  int layers = 1;                 // of an array texture
  std::vector<glm::vec4> texels;  // texels[x + width * (y + height * layer)], y = 0 the bottom row
};

// A depth texture's level 0 (every layer), one float per texel, bottom row first.
struct HostDepthImage {
  int width = 0, height = 0, layers = 1;
  std::vector<float> depths;  // depths[x + width * (y + height * layer)]
};

// An RGBA image (bottom row first, as GL stores it) flipped to top row first, keeping `channels`
// of its RGBA from `firstChannel` on: a host image as lpvlab's outputs hold it.
Image toImage(const HostImage& rgba, int channels, int firstChannel = 0);

// A frame's reflective shadow maps on the host (LightMaps' RSM textures), one layer per view.
struct RsmImages {
  const HostImage* position = nullptr;  // RGBA: world position, w = 1 where covered
  const HostImage* normal = nullptr;    // RGBA: unit normal
  const HostImage* flux = nullptr;      // RGBA: reflected flux (W per channel), w = 1 where covered
};

// The first `floats` of a GL buffer of floats (a light grid's, the normal grid's) into `host`,
// after GL's shader writes to it, and `host` back: how a CPU strategy reads and adds to what GL
// strategies wrote.
void downloadFloats(const gl::Buffer& buffer, std::size_t floats, std::vector<float>& host);
void uploadFloats(const std::vector<float>& host, gl::Buffer& buffer);

// Level 0 of an RGBA32F texture (every layer of an array texture), and back (2D only).
HostImage downloadImage(const gl::Texture& texture);
void downloadImage(const gl::Texture& texture, HostImage& image);  // reusing image's storage
// Level 0 of a depth texture, reusing image's storage.
void downloadDepth(const gl::Texture& texture, HostDepthImage& image);
void uploadImage(const HostImage& image, gl::Texture& texture);
// Every layer of `image` into a 2D or 2D-array RGBA32F texture of its size, and of `depths` into a
// depth texture's: host-made raster images for GL strategies.
void uploadLayers(const HostImage& image, const gl::Texture& texture);
void uploadDepth(const HostDepthImage& depths, const gl::Texture& texture);

class HostReadback {
public:
  // Marks the last frame's copies out of date (the pipeline calls it as a frame begins); their
  // storage is kept, so a frame's read-backs allocate nothing.
  void newFrame();
  // The texture's texels this frame: read back on the first call of the frame.
  const HostImage& image(const gl::Texture& texture);
  // The same for a depth texture.
  const HostDepthImage& depth(const gl::Texture& texture);
  // The texture's image for this frame made on the host (host_raster.h), sized as the texture
  // (every layer): the caller fills it, and image() / depth() return it this frame without
  // reading GL.
  HostImage& written(const gl::Texture& texture);
  HostDepthImage& writtenDepth(const gl::Texture& texture);

private:
  template <class Image>
  struct Copy {
    Image image;
    bool current = false;  // read back this frame
  };
  std::map<unsigned, Copy<HostImage>> images_;  // by GL texture name
  std::map<unsigned, Copy<HostDepthImage>> depths_;
  // written()'s work for either kind of image: `values` is its texel array.
  template <class Image, class T>
  Image& written(std::map<unsigned, Copy<Image>>& copies, const gl::Texture& texture,
                 std::vector<T> Image::*values);
};

}  // namespace lpvlab

#include "framework/scene/texture_loader.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "framework/core/error.h"

namespace lpvlab {
namespace {

// The file's bytes are kept as they are (sRGB-encoded colour for the usual 8-bit images); only
// the channel layout is made RGBA: grey is copied to R, G and B, and a missing alpha is opaque.
TextureImage readPixels(OIIO::ImageInput& input, const std::string& name) {
  const OIIO::ImageSpec& spec = input.spec();
  const int channels = spec.nchannels;
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) * spec.height * channels);
  if (!input.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data()))
    throwAt(name, "cannot decode image: " + input.geterror());

  TextureImage texture;
  texture.path = name;
  texture.width = spec.width;
  texture.height = spec.height;
  texture.rgba8.resize(static_cast<std::size_t>(spec.width) * spec.height * 4);
  const bool grey = channels < 3;
  const bool hasAlpha = channels == 2 || channels >= 4;
  for (std::size_t i = 0, n = texture.rgba8.size() / 4; i < n; ++i) {
    const std::uint8_t* in = &pixels[i * channels];
    std::uint8_t* out = &texture.rgba8[i * 4];
    out[0] = in[0];
    out[1] = grey ? in[0] : in[1];
    out[2] = grey ? in[0] : in[2];
    out[3] = hasAlpha ? in[grey ? 1 : 3] : 255;
  }
  return texture;
}

// OpenImageIO premultiplies colour by alpha when it reads PNG and similar files unless asked not
// to; lpvlab's textures keep the file's straight (unassociated) colour for alpha masks to cut.
const OIIO::ImageSpec& straightAlpha() {
  static const OIIO::ImageSpec config = [] {
    OIIO::ImageSpec spec;
    spec.attribute("oiio:UnassociatedAlpha", 1);
    return spec;
  }();
  return config;
}

}  // namespace

TextureImage readTextureFile(const std::string& path) {
  auto input = OIIO::ImageInput::open(path, &straightAlpha());
  if (!input) throwAt(path, "cannot open image: " + OIIO::geterror());
  return readPixels(*input, path);
}

TextureImage decodeTexture(const void* data, std::size_t size, const std::string& formatHint,
                      const std::string& name) {
  OIIO::Filesystem::IOMemReader memory(data, size);
  // OpenImageIO picks the format by the name's extension; the bytes come from `memory`. With a
  // configuration, OpenImageIO 2.4 takes the proxy from it rather than from open's argument.
  OIIO::ImageSpec config = straightAlpha();
  OIIO::Filesystem::IOProxy* proxy = &memory;
  config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  auto input = OIIO::ImageInput::open("embedded." + formatHint, &config, proxy);
  if (!input) throwAt(name, "cannot open image: " + OIIO::geterror());
  return readPixels(*input, name);
}

}  // namespace lpvlab

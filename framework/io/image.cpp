#include "framework/io/image.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

#include <OpenImageIO/imageio.h>

#include "framework/core/error.h"
#include "framework/core/atomic_file.h"

namespace lpvlab {

namespace {

// Writes one subimage with OpenImageIO to `file` (the temporary), naming `target` (what the user
// asked for) in errors; the format follows the file's extension.
void writeWithOiio(const std::string& target, const std::string& file, const OIIO::ImageSpec& spec,
                   const void* data) {
  auto out = OIIO::ImageOutput::create(file);
  if (!out) throw Error(target + ": cannot create an image writer: " + OIIO::geterror());
  if (!out->open(file, spec)) throw Error(target + ": cannot open for writing: " + out->geterror());
  if (!out->write_image(spec.format, data)) {
    const std::string message = out->geterror();
    out->close();
    throw Error(target + ": cannot write pixels: " + message);
  }
  if (!out->close()) throw Error(target + ": cannot finish writing: " + out->geterror());
}

std::vector<std::string> channelSuffixes(const std::string& path, const NamedImage& aov) {
  if (aov.image.channels == 3) return {"R", "G", "B"};
  if (aov.image.channels == 1) return {aov.name == "depth" ? "Z" : "Y"};
  throw Error(path + ": AOV '" + aov.name + "' has " + std::to_string(aov.image.channels) +
              " channels; EXR output supports 1 or 3");
}

// sRGB transfer function (IEC 61966-2-1) of a value in [0, 1].
float encodeSrgb(float linear) {
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

}  // namespace

void writeExr(const std::string& path, const std::vector<NamedImage>& aovs,
              const std::vector<std::pair<std::string, std::string>>& metadata) {
  if (aovs.empty()) throw Error(path + ": no AOVs to write");
  const int width = aovs.front().image.width;
  const int height = aovs.front().image.height;
  std::vector<std::string> names;
  for (const NamedImage& aov : aovs) {
    if (aov.image.width != width || aov.image.height != height)
      throw Error(path + ": AOV '" + aov.name + "' is " + std::to_string(aov.image.width) + "x" +
                  std::to_string(aov.image.height) + ", expected " + std::to_string(width) + "x" +
                  std::to_string(height) + " like '" + aovs.front().name + "'");
    if (aov.name.empty()) throw Error(path + ": an AOV has no name");
    for (const std::string& suffix : channelSuffixes(path, aov))
      names.push_back(aov.name + "." + suffix);
  }

  OIIO::ImageSpec spec(width, height, static_cast<int>(names.size()), OIIO::TypeDesc::FLOAT);
  spec.channelnames = names;
  spec.attribute("compression", "zip");
  for (const auto& [key, value] : metadata) spec.attribute(key, value);

  // Interleave every AOV's channels into one pixel, in the order of `names`.
  std::vector<float> pixels(size_t(width) * height * names.size());
  size_t offset = 0;
  for (const NamedImage& aov : aovs) {
    const Image& image = aov.image;
    for (size_t p = 0; p < size_t(width) * height; ++p)
      for (int c = 0; c < image.channels; ++c)
        pixels[p * names.size() + offset + c] = image.pixels[p * image.channels + c];
    offset += image.channels;
  }
  writeAtomically(path,
                  [&](const std::string& file) { writeWithOiio(path, file, spec, pixels.data()); });
}

std::vector<NamedImage> readExr(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw Error(path + ": cannot read: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> pixels(size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
    throw Error(path + ": cannot read pixels: " + in->geterror());

  // Group channel indices by the prefix before the last '.'; channels without one form an AOV
  // named "". OpenEXR stores channels sorted by name (B, G, R); OIIO 2.4 hands them back as
  // R, G, B within a layer, but that is a reader's courtesy, so the order is restored by name.
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::pair<std::string, int>>> groups;
  for (int c = 0; c < spec.nchannels; ++c) {
    const std::string& name = spec.channelnames[c];
    const auto dot = name.rfind('.');
    const std::string prefix = dot == std::string::npos ? "" : name.substr(0, dot);
    if (!groups.count(prefix)) order.push_back(prefix);
    groups[prefix].emplace_back(dot == std::string::npos ? name : name.substr(dot + 1), c);
  }

  std::vector<NamedImage> aovs;
  for (const std::string& prefix : order) {
    auto channels = groups[prefix];
    auto rank = [](const std::string& suffix) {
      const std::string known = "RGBA";
      const auto at = suffix.size() == 1 ? known.find(suffix[0]) : std::string::npos;
      return at == std::string::npos ? known.size() : at;
    };
    std::stable_sort(channels.begin(), channels.end(),
                     [&](const auto& a, const auto& b) { return rank(a.first) < rank(b.first); });
    NamedImage aov{prefix, Image(spec.width, spec.height, static_cast<int>(channels.size()))};
    for (size_t p = 0; p < size_t(spec.width) * spec.height; ++p)
      for (size_t c = 0; c < channels.size(); ++c)
        aov.image.pixels[p * channels.size() + c] = pixels[p * spec.nchannels + channels[c].second];
    aovs.push_back(std::move(aov));
  }
  return aovs;
}

void writePng(const std::string& path, const Image& rgb, float exposureStops, ToneCurve curve,
              float whiteStops) {
  if (rgb.channels != 3)
    throw Error(path + ": a PNG needs an RGB image, got " + std::to_string(rgb.channels) +
                " channels");
  const float scale = std::exp2(exposureStops);
  const double logWhite = std::log1p(std::exp2(double(whiteStops)));
  std::vector<std::uint8_t> bytes(rgb.pixels.size());
  for (size_t p = 0; p < rgb.pixels.size() / 3; ++p) {
    glm::vec3 x;
    for (int c = 0; c < 3; ++c) {
      const float value = rgb.pixels[p * 3 + c];
      if (!std::isfinite(value))
        throw Error(path + ": pixel (" + std::to_string(p % rgb.width) + ", " +
                    std::to_string(p / rgb.width) + ") is not finite (NaN or Inf); " +
                    "refusing to write an image that hides it");
      // Negative radiance (ringing from SH) shows as black rather than breaking the tone curve.
      x[c] = std::max(0.0f, value * scale);
    }
    glm::vec3 display;
    if (curve == ToneCurve::Logarithmic) {
      const float y = 0.2126f * x.r + 0.7152f * x.g + 0.0722f * x.b;
      const float mapped = float(std::log1p(double(y) / 0.18) / logWhite);
      display = y > 0.0f ? glm::min(x * (mapped / y), glm::vec3(1.0f)) : glm::vec3(0.0f);
    } else {
      display = curve == ToneCurve::Reinhard ? x / (1.0f + x) : glm::min(x, glm::vec3(1.0f));
    }
    for (int c = 0; c < 3; ++c)
      bytes[p * 3 + c] = static_cast<std::uint8_t>(std::lround(encodeSrgb(display[c]) * 255.0f));
  }
  OIIO::ImageSpec spec(rgb.width, rgb.height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  writeAtomically(path,
                  [&](const std::string& file) { writeWithOiio(path, file, spec, bytes.data()); });
}

float middleGreyExposure(const Image& rgb) {
  std::vector<float> luminance;
  for (std::size_t i = 0; i + 2 < rgb.pixels.size(); i += std::size_t(rgb.channels)) {
    // Rec. 709 luminance of linear RGB.
    const float y = 0.2126f * rgb.pixels[i] + 0.7152f * rgb.pixels[i + 1] + 0.0722f * rgb.pixels[i + 2];
    if (y > 0.0f && std::isfinite(y)) luminance.push_back(y);
  }
  if (luminance.empty()) return 0.0f;
  auto middle = luminance.begin() + std::ptrdiff_t(luminance.size() / 2);
  std::nth_element(luminance.begin(), middle, luminance.end());
  return std::log2(0.18f / *middle);
}

const Image* findAovOrNull(const std::vector<NamedImage>& aovs, const std::string& name) {
  for (const NamedImage& aov : aovs)
    if (aov.name == name) return &aov.image;
  return nullptr;
}

double imageMean(const Image& image) {
  double sum = 0.0;
  for (float v : image.pixels) sum += v;
  return image.pixels.empty() ? 0.0 : sum / double(image.pixels.size());
}

const Image& findAov(const std::vector<NamedImage>& aovs, const std::string& name) {
  if (const Image* found = findAovOrNull(aovs, name)) return *found;
  std::string names;
  for (const NamedImage& aov : aovs) names += (names.empty() ? "" : ", ") + aov.name;
  throw Error("no output named '" + name + "' (there are: " + names + ")");
}

}  // namespace lpvlab

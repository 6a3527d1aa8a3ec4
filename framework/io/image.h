#pragma once
// Linear float images and their files. Data: EXR (half or float) with named AOVs as channel
// groups ("direct.R", "direct.G", ...), written and read through OpenImageIO. Looking: a
// tone-mapped sRGB PNG. Every file is written to a temporary name and renamed, so a killed run
// never leaves a half-written file that looks whole.

#include <string>
#include <vector>

namespace lpvlab {

struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> pixels;  // row-major, top row first, interleaved channels

  Image() = default;
  Image(int w, int h, int c, float fill = 0.0f)
      : width(w), height(h), channels(c), pixels(size_t(w) * h * c, fill) {}
  float& at(int x, int y, int c) { return pixels[(size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};

// One named output (AOV): "direct", "indirect", "combined", "albedo", "normal", "depth", ...
// Channel names in the file: RGB images get NAME.R/G/B, one-channel images NAME.Z for depth
// and NAME.Y otherwise.
struct NamedImage {
  std::string name;
  Image image;
};

// The AOV called `name`; throws an Error listing the names there are when it is missing.
const Image& findAov(const std::vector<NamedImage>& aovs, const std::string& name);
// The AOV called `name`, or null when there is none.
const Image* findAovOrNull(const std::vector<NamedImage>& aovs, const std::string& name);

// The mean over every pixel and channel (background included); 0 for an empty image.
double imageMean(const Image& image);

// Writes all AOVs (same size) into one multi-channel float EXR; `metadata` key/values become
// string attributes in the header (e.g. the run's configuration hash).
void writeExr(const std::string& path, const std::vector<NamedImage>& aovs,
              const std::vector<std::pair<std::string, std::string>>& metadata = {});
// Reads every AOV back, grouped by the prefix before the '.' in channel names.
std::vector<NamedImage> readExr(const std::string& path);

// How a PNG maps the exposed linear value x (the image times 2^exposureStops) to the display:
//   Reinhard     x / (1 + x) per channel
//   Clamp        min(x, 1) per channel (false colour, heat maps)
//   Logarithmic  the luminance Y to ln(1 + Y / 0.18) / ln(1 + 2^whiteStops), the colour scaled
//                with it (hue kept) and clamped: seed 004's logarithmic display (3.8, fig. 3.17),
//                which shows the radiosity of patches orders of magnitude below a light source's.
//                Middle grey (0.18, where auto-exposure puts the median) shows at 0.1 of white,
//                and white is whiteStops above it, the same for every frame of a sequence.
enum class ToneCurve { Reinhard, Clamp, Logarithmic };

// sRGB PNG of an RGB image scaled by 2^exposureStops through `curve`.
void writePng(const std::string& path, const Image& rgb, float exposureStops = 0.0f,
              ToneCurve curve = ToneCurve::Reinhard, float whiteStops = 10.0f);

// The exposure (stops) that brings the median luminance of the non-black pixels of an RGB image
// to middle grey (0.18), so an image is readable whatever the light's units; 0 for a black image.
float middleGreyExposure(const Image& rgb);

}  // namespace lpvlab

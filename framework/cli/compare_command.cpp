// `lpvlab compare TEST REFERENCE [--aov NAME]... [--json] [--threshold NAME=VALUE]... [--out DIR]`:
// how far one rendering is from another, per AOV, over the pixels with a surface in the
// reference (its depth > 0). TEST and REFERENCE are run directories (their images.exr) or EXR
// files: two runs of one configuration (scripts/gpu-check.sh compares the GL kernels' images with
// the CPU kernels' by it), or a run and its reference (the reference cache's images.exr, whose
// indirect1 layer a run's indirect approximates: --aov indirect=indirect1).
//
// Per AOV: the relative difference (relative_difference.h: mean, 99th percentile, maximum), the
// image metrics (metrics.h: RMSE, relative MSE, LDR-FLIP, HDR-FLIP, SSIM, block nRMSE) and the
// ratio of the means. --threshold gates scripts: exit code 3 when a figure exceeds its bound.

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <set>
#include <utility>

#include <nlohmann/json.hpp>

#include "framework/core/log.h"
#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/experiment/run_outputs.h"
#include "framework/io/image.h"
#include "framework/metrics/metrics.h"
#include "framework/metrics/relative_difference.h"

namespace lpvlab::cli {

namespace {

// Exit code of a comparison with a figure beyond its --threshold (1 and 2 are errors).
constexpr int kOverThreshold = 3;

std::string exrOf(const std::string& path) {
  const std::filesystem::path p(path);
  if (std::filesystem::is_directory(p)) {
    if (!std::filesystem::exists(p / "images.exr"))
      throw Error(path + ": a run directory without images.exr (a sequence's frames are "
                  "frames/<frame>.exr: name one)");
    return (p / "images.exr").string();
  }
  if (!std::filesystem::exists(p)) throw Error(path + ": no such file or directory");
  return path;
}

// The figures --threshold can bound, each an error (larger is worse): name -> (group, key) in
// the JSON of an AOV.
const std::map<std::string, std::pair<std::string, std::string>>& thresholdFigures() {
  static const std::map<std::string, std::pair<std::string, std::string>> figures = {
      {"mean", {"relative_difference", "mean"}}, {"p99", {"relative_difference", "p99"}},
      {"max", {"relative_difference", "max"}},   {"rmse", {"metrics", "rmse"}},
      {"rel_mse", {"metrics", "rel_mse"}},       {"flip", {"metrics", "flip"}},
      {"hdr_flip", {"metrics", "hdr_flip"}},     {"block_nrmse", {"metrics", "block_nrmse"}}};
  return figures;
}

// --threshold NAME=VALUE, checked before any image is read.
std::map<std::string, double> thresholds(const std::vector<std::string>& given) {
  std::map<std::string, double> out;
  for (const std::string& t : given) {
    const auto equals = t.find('=');
    const std::string name = t.substr(0, equals);
    std::string names;
    for (const auto& [figure, _] : thresholdFigures()) names += (names.empty() ? "" : ", ") + figure;
    if (equals == std::string::npos || !thresholdFigures().count(name))
      throw Error("--threshold '" + echoed(t) + "': expected NAME=VALUE with NAME one of " + names);
    try {
      std::size_t used = 0;
      const double value = std::stod(t.substr(equals + 1), &used);
      if (used != t.size() - equals - 1 || !(value >= 0.0)) throw std::invalid_argument("");
      out[name] = value;
    } catch (const std::exception&) {
      throw Error("--threshold '" + echoed(t) + "': the bound must be a number >= 0");
    }
  }
  return out;
}

// "aov" or "test_aov=reference_aov": the test's layer and the reference's it is compared with.
std::pair<std::string, std::string> layers(const std::string& aov) {
  const auto equals = aov.find('=');
  if (equals == std::string::npos) return {aov, aov};
  return {aov.substr(0, equals), aov.substr(equals + 1)};
}

double meanOf(const Image& image, const Image* mask) {
  double sum = 0.0;
  long long n = 0;
  for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p) {
    if (mask && mask->pixels[p] == 0.0f) continue;
    for (int c = 0; c < 3; ++c) sum += image.pixels[p * 3 + c];
    n += 3;
  }
  return n ? sum / double(n) : 0.0;
}

// The signed (t - r) and relative (|t - r| / (|r| + epsilon), relative_difference.h's epsilon)
// differences of one AOV, 0 at background pixels.
std::vector<NamedImage> differenceLayers(const std::string& name, const Image& t, const Image& r,
                                         const Image* mask, double epsilon) {
  Image signedDifference(r.width, r.height, 3), relative(r.width, r.height, 3);
  for (std::size_t p = 0; p < std::size_t(r.width) * r.height; ++p) {
    if (mask && mask->pixels[p] == 0.0f) continue;
    for (int c = 0; c < 3; ++c) {
      signedDifference.pixels[p * 3 + c] = float(double(t.pixels[p * 3 + c]) - r.pixels[p * 3 + c]);
      relative.pixels[p * 3 + c] =
          float(relativeDifferenceOf(t.pixels[p * 3 + c], r.pixels[p * 3 + c], epsilon));
    }
  }
  return {{name + "_signed", std::move(signedDifference)}, {name + "_relative", std::move(relative)}};
}

struct RelativePng {
  std::string path;
  double top = 1.0;  // the value the ramp's top (pale yellow) stands for
  std::string topIs; // which: "the 99th percentile", "the largest value", "1 (no difference)"
};

// <aov>_relative.png in `dir`: each pixel's largest relative difference over its channels through
// the magma ramp from 0 (black) to the comparison's 99th percentile (pale yellow; the largest
// value where that is 0, 1 where both are), with its colour bar; background mid grey.
RelativePng writeRelativePng(const std::string& dir, const std::string& aov,
                                                const NamedImage& relative, const Image* mask,
                                                const RelativeDifference& summary) {
  const Image& rgb = relative.image;
  Image largest(rgb.width, rgb.height, 1);
  for (std::size_t p = 0; p < largest.pixels.size(); ++p)
    largest.pixels[p] = std::max({rgb.pixels[p * 3], rgb.pixels[p * 3 + 1], rgb.pixels[p * 3 + 2]});
  RelativePng png{(std::filesystem::path(dir) / (aov + "_relative.png")).string(), 1.0,
                  "1 (no difference)"};
  if (summary.p99 > 0.0) png = {png.path, summary.p99, "the 99th percentile"};
  else if (summary.max > 0.0) png = {png.path, summary.max, "the largest value"};
  writePng(png.path, withColourBar(falseColour(largest, 0.0f, float(png.top), mask)), 0.0f, ToneCurve::Clamp);
  return png;
}

// What --out writes of one compared AOV besides its difference layers.
struct AovPngs {
  std::string aov;
  RelativeDifference relative;
  HdrFlipMap hdrFlip;
};

// --out: DIR/<aov>_relative.png and DIR/<aov>_hdr_flip.png per compared AOV (`pngs`, whose
// difference layers are `differences`' pairs in order) and DIR/difference.exr; what was written
// goes into `out`.
void writeDifferences(const std::string& dir, const std::vector<AovPngs>& pngs,
                      const std::vector<NamedImage>& differences, const Image* covered,
                      nlohmann::json& out) {
  std::filesystem::create_directories(dir);
  for (std::size_t i = 0; i < pngs.size(); ++i) {
    const AovPngs& a = pngs[i];
    const RelativePng png =
        writeRelativePng(dir, layers(a.aov).first, differences[2 * i + 1], covered, a.relative);
    out["aovs"][a.aov]["relative_png"] = {
        {"path", png.path}, {"range", {0.0, png.top}}, {"top_is", png.topIs}};
    // HDR-FLIP's map on its own scale, 0 (black) to 1 (pale yellow), as FLIP's tool shows it.
    const std::string flipPath =
        (std::filesystem::path(dir) / (layers(a.aov).first + "_hdr_flip.png")).string();
    writePng(flipPath, withColourBar(falseColour(a.hdrFlip.error, 0.0f, 1.0f, covered)), 0.0f,
             ToneCurve::Clamp);
    const HdrFlipExposures& e = a.hdrFlip.exposures;
    out["aovs"][a.aov]["hdr_flip_png"] = {
        {"path", flipPath},
        {"range", {0.0, 1.0}},
        {"exposures", {{"start_stops", e.start}, {"stop_stops", e.stop}, {"count", e.count}}}};
  }
  const std::string path = (std::filesystem::path(dir) / "difference.exr").string();
  // An earlier comparison's differences are replaced, and said to be.
  const bool replaced = std::filesystem::exists(path);
  writeExr(path, differences, {{"lpvlab:test", out["test"].get<std::string>()},
                               {"lpvlab:reference", out["reference"].get<std::string>()}});
  out["difference_exr"] = path;
  out["replaced_an_earlier_difference_exr"] = replaced;
  if (replaced) log::warning(path + ": replaced an earlier comparison's differences");
}

void printTable(const nlohmann::json& out, const std::vector<std::string>& aovs) {
  std::cout << "compare " << out["test"].get<std::string>() << " against "
            << out["reference"].get<std::string>() << " over " << out["mask"].get<std::string>()
            << "\n  relative difference |t - r| / (|r| + eps), eps = 1e-3 mean |r|: mean, p99, max;"
            << " metrics.h's RMSE, relative MSE, LDR-FLIP, HDR-FLIP, SSIM, block nRMSE;"
            << " mean t / mean r\n"
            << std::left << std::setw(12) << "aov" << std::right;
  for (const char* h : {"mean", "p99", "max", "values", "rmse", "rel_mse", "flip", "hdr_flip", "ssim",
                        "block_nrmse", "mean_ratio"})
    std::cout << std::setw(12) << h;
  std::cout << "\n";
  for (const std::string& aov : aovs) {
    const nlohmann::json& a = out["aovs"][aov];
    std::cout << std::left << std::setw(12) << aov << std::right << std::scientific << std::setprecision(3);
    for (const char* k : {"mean", "p99", "max"}) std::cout << std::setw(12) << a["relative_difference"][k].get<double>();
    std::cout << std::setw(12) << a["relative_difference"]["values"].get<long long>();
    for (const char* k : {"rmse", "rel_mse", "flip", "hdr_flip", "ssim", "block_nrmse"}) {
      const nlohmann::json& v = a["metrics"][k];
      if (v.is_string()) std::cout << std::setw(12) << v.get<std::string>();
      else std::cout << std::setw(12) << v.get<double>();
    }
    std::cout << std::setw(12) << a["mean_ratio"].get<double>() << "\n";
  }
}

}  // namespace

int compareCommand(const Options& options) {
  const std::map<std::string, double> bounds = thresholds(options.thresholds);
  const std::string testPath = exrOf(options.images.at(0)), referencePath = exrOf(options.images.at(1));
  const std::vector<NamedImage> test = readExr(testPath), reference = readExr(referencePath);
  std::vector<std::string> aovs = options.aovs;
  if (aovs.empty()) aovs = {"direct", "indirect"};
  const Image* depth = findAovOrNull(reference, "depth");
  const Image mask = depth ? coverageMask(*depth) : Image();
  const Image* covered = depth ? &mask : nullptr;
  nlohmann::json out = {{"test", testPath}, {"reference", referencePath},
                        {"mask", depth ? "the reference's depth > 0" : "every pixel"},
                        {"aovs", nlohmann::json::object()}};
  std::vector<NamedImage> differences;
  std::vector<AovPngs> pngs;  // per AOV, for --out's PNGs
  std::set<std::string> written;  // the test layers --out names its difference layers after
  for (const std::string& aov : aovs) {
    if (!options.out.empty() && !written.insert(layers(aov).first).second)
      throw Error("--aov " + aov + ": another --aov compares '" + layers(aov).first +
                  "' too, and --out would write its difference layers twice");
    const auto [mine, theirs] = layers(aov);
    const Image* t = findAovOrNull(test, mine);
    const Image* r = findAovOrNull(reference, theirs);
    if (!t) throw Error(testPath + ": no AOV '" + mine + "'");
    if (!r) throw Error(referencePath + ": no AOV '" + theirs + "'");
    const RelativeDifference relative = relativeDifference(*t, *r, covered);
    const double meanReference = meanOf(*r, covered);
    HdrFlipMap hdrFlip;  // for --out's PNG
    out["aovs"][aov] = {{"relative_difference", relative.toJson()},
                        {"metrics", computeMetrics(*t, *r, covered, {}, &hdrFlip).toJson()},
                        {"mean_ratio", meanReference != 0.0 ? meanOf(*t, covered) / meanReference : 0.0}};
    if (!options.out.empty()) {
      std::vector<NamedImage> layer = differenceLayers(mine, *t, *r, covered, relative.epsilon);
      differences.insert(differences.end(), layer.begin(), layer.end());
      pngs.push_back({aov, relative, std::move(hdrFlip)});
    }
  }
  // Written once every AOV was compared: an error above leaves nothing behind.
  if (!options.out.empty()) writeDifferences(options.out, pngs, differences, covered, out);
  // Every figure beyond its bound, named (an infinite block nRMSE, written "inf", exceeds any).
  nlohmann::json exceeded = nlohmann::json::array();
  for (const auto& [name, bound] : bounds)
    for (const std::string& aov : aovs) {
      const auto& [group, key] = thresholdFigures().at(name);
      const nlohmann::json& value = out["aovs"][aov][group][key];
      const double v = value.is_string() ? std::numeric_limits<double>::infinity() : value.get<double>();
      if (!(v <= bound)) exceeded.push_back({{"aov", aov}, {"figure", name}, {"value", v}, {"bound", bound}});
    }
  if (!bounds.empty()) out["thresholds_exceeded"] = exceeded;
  if (options.json) {
    std::cout << out.dump(2) << "\n";
  } else {
    printTable(out, aovs);
    if (!options.out.empty()) {
      std::cout << "wrote " << out["difference_exr"].get<std::string>()
                << " (per AOV <aov>_signed: t - r; <aov>_relative: |t - r| / (|r| + eps))\n";
      for (const std::string& aov : aovs) {
        const nlohmann::json& png = out["aovs"][aov]["relative_png"];
        std::cout << "wrote " << png["path"].get<std::string>()
                  << " (the largest channel's relative difference; colour bar from 0 at the bottom "
                     "to "
                  << png["range"][1].get<double>() << ", " << png["top_is"].get<std::string>()
                  << ", at the top)\n";
        const nlohmann::json& flip = out["aovs"][aov]["hdr_flip_png"];
        std::cout << "wrote " << flip["path"].get<std::string>()
                  << " (HDR-FLIP per pixel, 0 black to 1 pale yellow, over exposures "
                  << flip["exposures"]["start_stops"].get<double>() << " to "
                  << flip["exposures"]["stop_stops"].get<double>() << " stops)\n";
      }
    }
  }
  for (const nlohmann::json& e : exceeded) {
    std::ostringstream line;
    line << "compare: " << e["aov"].get<std::string>() << " " << e["figure"].get<std::string>() << " "
         << e["value"].get<double>() << " exceeds --threshold " << e["bound"].get<double>();
    log::warning(line.str());
  }
  return exceeded.empty() ? 0 : kOverThreshold;
}

}  // namespace lpvlab::cli

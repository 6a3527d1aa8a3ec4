// `lpvlab compare TEST REFERENCE [--aov NAME]... [--json]`: how far one rendering is from another
// of the same configuration (relative_difference.h), per AOV, over the pixels with a surface in
// the reference (its depth > 0). TEST and REFERENCE are run directories (their images.exr) or
// EXR files. scripts/gpu-check.sh compares the GL kernels' images with the CPU kernels' by it.

#include <filesystem>
#include <iomanip>
#include <iostream>

#include <nlohmann/json.hpp>

#include "framework/cli/commands.h"
#include "framework/core/error.h"
#include "framework/experiment/run_outputs.h"
#include "framework/io/image.h"
#include "framework/metrics/relative_difference.h"

namespace lpvlab::cli {

namespace {

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

}  // namespace

int compareCommand(const Options& options) {
  const std::string testPath = exrOf(options.images.at(0)), referencePath = exrOf(options.images.at(1));
  const std::vector<NamedImage> test = readExr(testPath), reference = readExr(referencePath);
  std::vector<std::string> aovs = options.aovs;
  if (aovs.empty()) aovs = {"direct", "indirect"};
  const Image* depth = findAovOrNull(reference, "depth");
  const Image mask = depth ? coverageMask(*depth) : Image();
  nlohmann::json out = {{"test", testPath}, {"reference", referencePath},
                        {"mask", depth ? "the reference's depth > 0" : "every pixel"},
                        {"aovs", nlohmann::json::object()}};
  for (const std::string& aov : aovs) {
    const Image* t = findAovOrNull(test, aov);
    const Image* r = findAovOrNull(reference, aov);
    if (!t || !r) throw Error((t ? referencePath : testPath) + ": no AOV '" + aov + "'");
    out["aovs"][aov] = relativeDifference(*t, *r, depth ? &mask : nullptr).toJson();
  }
  if (options.json) {
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::cout << "compare " << testPath << " against " << referencePath
            << ": relative difference |t - r| / (|r| + eps), eps = 1e-3 mean |r|, over "
            << out["mask"].get<std::string>() << "\n"
            << std::left << std::setw(12) << "aov" << std::right << std::setw(12) << "mean"
            << std::setw(12) << "p99" << std::setw(12) << "max" << std::setw(12) << "values" << "\n";
  for (const std::string& aov : aovs) {
    const nlohmann::json& d = out["aovs"][aov];
    std::cout << std::left << std::setw(12) << aov << std::right << std::scientific
              << std::setprecision(3) << std::setw(12) << d["mean"].get<double>() << std::setw(12)
              << d["p99"].get<double>() << std::setw(12) << d["max"].get<double>()
              << std::setw(12) << d["values"].get<long long>() << "\n";
  }
  return 0;
}

}  // namespace lpvlab::cli

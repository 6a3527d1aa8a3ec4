#include "framework/explain/error_budget.h"

#include <algorithm>
#include <cmath>

#include "framework/metrics/block_error.h"
#include "framework/metrics/mask.h"
#include "framework/metrics/pixel_errors.h"

namespace lpvlab {

namespace {

Image plus(const Image& a, const Image* b) {
  if (!b) return a;
  Image out = a;
  for (std::size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] += b->pixels[i];
  return out;
}

// JSON has no infinity (a black reference's block nRMSE).
nlohmann::json finiteOrString(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(value > 0 ? "inf" : "-inf");
}

}  // namespace

ErrorFigures errorFigures(const Image& test, const Image& reference, const Image& mask) {
  // Only the figures the budget reports (computeMetrics would add SSIM and both FLIPs).
  const PixelMask covered = checkInputs("errorFigures", test, reference, &mask);
  const PixelErrors errors = pixelErrors(test, reference, covered, MetricOptions{});
  const double reference_mean = imageMean(reference);
  return {blockNrmse(test, reference, covered), errors.rmse,
          reference_mean > 0.0 ? imageMean(test) / reference_mean : 0.0};
}

nlohmann::json toJson(const ErrorFigures& figures) {
  return {{"block_nrmse", finiteOrString(figures.blockNrmse)},
          {"rmse", figures.rmse},
          {"mean_ratio", figures.meanRatio}};
}

double referenceNoiseBlockNrmse(const Image& reference, const Image& varianceOfMean, const Image& mask) {
  const int block = 8, channels = 3;
  double variances = 0.0, means = 0.0, blocks = 0.0;
  for (int by = 0; by < reference.height; by += block)
    for (int bx = 0; bx < reference.width; bx += block) {
      double count = 0.0, variance[3] = {}, sum[3] = {};
      for (int y = by; y < std::min(by + block, reference.height); ++y)
        for (int x = bx; x < std::min(bx + block, reference.width); ++x) {
          if (mask.at(x, y, 0) <= 0.0f) continue;
          count += 1.0;
          for (int c = 0; c < channels; ++c) {
            variance[c] += std::max(0.0, double(varianceOfMean.at(x, y, c)));
            sum[c] += reference.at(x, y, c);
          }
        }
      if (count == 0.0) continue;
      for (int c = 0; c < channels; ++c) {
        variances += variance[c] / (count * count);
        means += sum[c] / count;
        blocks += 1.0;
      }
    }
  return blocks > 0.0 && means > 0.0 ? std::sqrt(variances / blocks) / (means / blocks) : 0.0;
}

nlohmann::json errorBudget(const ExplainImages& images, const Image* direct, const Image& reference,
                           const Image& mask, bool gridBlocksLight) {
  // The chain, most approximate first (error_budget.h).
  struct Link {
    std::string name;
    const Image* image;
  };
  std::vector<Link> chain = {{"method", &images.method}};
  chain.push_back(gridBlocksLight ? Link{"grid_visible", &images.gridVisible} : Link{"grid", &images.grid});
  if (gridBlocksLight) {
    chain.push_back({"gather_visible", &images.gatherVisible});
  } else {
    chain.push_back({"gather", &images.gather});
    chain.push_back({"gather_visible", &images.gatherVisible});
  }
  std::vector<Image> shown;  // each as the pair's AOV (with the direct light for "combined")
  for (const Link& link : chain) shown.push_back(plus(*link.image, direct));
  nlohmann::json out;
  std::vector<ErrorFigures> errors;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    errors.push_back(errorFigures(shown[i], reference, mask));
    out["images"][chain[i].name] = toJson(errors.back());
    if (images.noise.count(chain[i].name)) out["images"][chain[i].name]["oracle_noise_block_nrmse"] = images.noise.at(chain[i].name);
  }
  // The stage each link replaces, in the chain's order.
  const std::vector<std::string> stages = gridBlocksLight
      ? std::vector<std::string>{"propagation", "rendering"}
      : std::vector<std::string>{"propagation", "rendering", "occlusion"};
  nlohmann::json terms = nlohmann::json::array();
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const ErrorFigures directly = errorFigures(shown[i], shown[i + 1], mask);
    terms.push_back({{"stage", stages[i]},
                     {"replaced_by", chain[i + 1].name},
                     {"block_nrmse_reduction", errors[i].blockNrmse - errors[i + 1].blockNrmse},
                     {"brightness_factor", errors[i + 1].meanRatio > 0.0 ? errors[i].meanRatio / errors[i + 1].meanRatio : 0.0},
                     {"against_replacement", toJson(directly)}});
  }
  terms.push_back({{"stage", "injection"},
                   {"replaced_by", "reference"},
                   {"block_nrmse_reduction", errors.back().blockNrmse},
                   {"brightness_factor", errors.back().meanRatio},
                   {"against_replacement", toJson(errors.back())}});
  out["terms"] = terms;
  out["total"] = toJson(errors.front());
  const double visibleMean = imageMean(images.gatherVisible);
  // Leakage: the light an exact gather without visibility adds to the one with it.
  out["leakage_factor"] = visibleMean > 0.0 ? imageMean(images.gather) / visibleMean : 0.0;
  out["occlusion_ignored"] = toJson(errorFigures(plus(images.gather, direct), reference, mask));
  out["chain"] = nlohmann::json::array();
  for (const Link& link : chain) out["chain"].push_back(link.name);
  return out;
}

}  // namespace lpvlab

#include "framework/core/stats.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

// The p-quantile of sorted data, interpolating linearly between the order statistics at
// position p * (n - 1) (Hyndman & Fan type 7, numpy's default), so results match the analysis
// scripts.
double quantile(const std::vector<double>& sorted, double p) {
  const double position = p * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double t = position - static_cast<double>(below);
  return sorted[below] + t * (sorted[above] - sorted[below]);
}

}  // namespace

Summary summarize(std::vector<double> samples) {
  if (samples.empty()) throw Error("statistics: no samples to summarize");
  for (std::size_t i = 0; i < samples.size(); ++i)
    if (!std::isfinite(samples[i]))
      throw Error("statistics: sample " + std::to_string(i) + " is " +
                  (std::isnan(samples[i]) ? "NaN" : "infinite"));
  std::sort(samples.begin(), samples.end());

  Summary s;
  s.count = static_cast<int>(samples.size());
  s.min = samples.front();
  s.max = samples.back();
  s.median = quantile(samples, 0.5);
  s.q1 = quantile(samples, 0.25);
  s.q3 = quantile(samples, 0.75);

  // Unscaled MAD (no 1.4826 factor): a spread in the samples' own units.
  std::vector<double> deviations;
  deviations.reserve(samples.size());
  for (double x : samples) deviations.push_back(std::abs(x - s.median));
  std::sort(deviations.begin(), deviations.end());
  s.mad = quantile(deviations, 0.5);
  return s;
}

nlohmann::json Summary::toJson() const {
  return {{"count", count}, {"median", median}, {"min", min}, {"max", max},
          {"q1", q1},       {"q3", q3},         {"mad", mad}};
}

}  // namespace lpvlab

#pragma once
// Summary statistics for repeated timings: report medians and spread, never single samples.

#include <vector>

#include <nlohmann/json.hpp>

namespace lpvlab {

struct Summary {
  int count = 0;
  double median = 0, min = 0, max = 0;
  double q1 = 0, q3 = 0;            // quartiles (linear interpolation between order statistics)
  double mad = 0;                   // median absolute deviation from the median
  nlohmann::json toJson() const;
};

Summary summarize(std::vector<double> samples);

}  // namespace lpvlab

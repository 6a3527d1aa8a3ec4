#pragma once
// The choices of `lpvlab tune` between rungs (tune_spec.h): which candidates go on to the next,
// better reference, which is chosen at the end, and the Pareto front of time against error.
// Pure functions of the measured figures, so a resumed tune decides as the first one did.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lpvlab {

// One candidate's figures at one rung: over the tuned views, the mean of the metric and of the
// median frame times.
struct RungResult {
  std::string id;
  double error = 0.0;
  double ms = 0.0;
};

// The goal: the least error within `budgetMs`, or the least time within `maxError`.
struct TuneGoal {
  std::optional<double> budgetMs;
  std::optional<double> maxError;
  bool feasible(const RungResult& r) const {
    return budgetMs ? r.ms <= *budgetMs : r.error <= *maxError;
  }
  // The goal's order: feasible first; among them by error (budget) or by time (error goal);
  // among the infeasible the nearest to feasible (by time, or by error).
  bool better(const RungResult& a, const RungResult& b) const;
};

// The ids of the best ceil(n / eta) of `results` (at least 1) in the goal's order.
std::vector<std::string> promote(const std::vector<RungResult>& results, const TuneGoal& goal, int eta);

// The best of `results` by the goal; nullopt when none is feasible.
std::optional<RungResult> choose(const std::vector<RungResult>& results, const TuneGoal& goal);

// The results no other is both faster and more accurate than (ties kept), by time.
std::vector<RungResult> paretoFront(std::vector<RungResult> results);

}  // namespace lpvlab

#include "framework/tune/successive_halving.h"

#include <algorithm>

namespace lpvlab {

bool TuneGoal::better(const RungResult& a, const RungResult& b) const {
  const bool fa = feasible(a), fb = feasible(b);
  if (fa != fb) return fa;
  const bool byError = budgetMs.has_value() == fa;  // feasible under a budget, or infeasible under an error goal
  if (byError) return a.error != b.error ? a.error < b.error : a.ms < b.ms;
  return a.ms != b.ms ? a.ms < b.ms : a.error < b.error;
}

std::vector<std::string> promote(const std::vector<RungResult>& results, const TuneGoal& goal, int eta) {
  std::vector<RungResult> sorted = results;
  std::stable_sort(sorted.begin(), sorted.end(), [&](const RungResult& a, const RungResult& b) { return goal.better(a, b); });
  const std::size_t keep = std::max<std::size_t>(1, (sorted.size() + std::size_t(eta) - 1) / std::size_t(eta));
  std::vector<std::string> ids;
  for (std::size_t i = 0; i < std::min(keep, sorted.size()); ++i) ids.push_back(sorted[i].id);
  return ids;
}

std::optional<RungResult> choose(const std::vector<RungResult>& results, const TuneGoal& goal) {
  std::optional<RungResult> best;
  for (const RungResult& r : results)
    if (goal.feasible(r) && (!best || goal.better(r, *best))) best = r;
  return best;
}

std::vector<RungResult> paretoFront(std::vector<RungResult> results) {
  std::sort(results.begin(), results.end(), [](const RungResult& a, const RungResult& b) {
    return a.ms != b.ms ? a.ms < b.ms : a.error < b.error;
  });
  std::vector<RungResult> front;
  for (const RungResult& r : results)
    if (front.empty() || r.error < front.back().error ||
        (r.error == front.back().error && r.ms == front.back().ms))
      front.push_back(r);
  return front;
}

}  // namespace lpvlab

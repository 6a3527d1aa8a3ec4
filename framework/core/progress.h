#pragma once
// Progress of long work (references, sweeps, fits) with an estimated time to completion. On a
// terminal it redraws one line; otherwise (logs, CI) it prints a line at most every 10 seconds.

#include <chrono>
#include <iosfwd>
#include <optional>
#include <string>

namespace lpvlab {

class ProgressBar {
public:
  explicit ProgressBar(std::string label);
  // `fraction` of the work is done (0..1); `detail` is shown after the bar (e.g. "64 spp").
  // The ETA is the rate so far times what is left, unless the caller knows better
  // (`etaSeconds`: a resumed sequence, whose bar starts part full, times only this run's frames).
  void update(double fraction, const std::string& detail,
              std::optional<double> etaSeconds = std::nullopt);
  void finish(const std::string& detail);

  // "1h02m", "3m05s", "12s": for ETAs and summaries.
  static std::string formatSeconds(double seconds);

private:
  std::string label_;
  std::chrono::steady_clock::time_point start_, lastPrint_;
  bool terminal_;
};

}  // namespace lpvlab

#pragma once
// The candidates `lpvlab tune` measures: configurations drawn from its [tune.space]
// (tune_spec.h), each a list of overrides as `-s key=value` gives them.

#include <string>
#include <vector>

#include "framework/tune/tune_spec.h"

namespace lpvlab {

struct TuneCandidate {
  std::string id;                      // 10 hex digits of the overrides' hash ("baseline": none)
  std::vector<std::string> overrides;  // "grid.resolution=32"
  std::string name() const;            // "grid.resolution=32, propagation.iterations=16"
};

// The baseline (the file as it is) first, then `spec.candidates` distinct draws (fewer when the
// space holds fewer: a space of choices only is enumerated whole when it is that small), the same
// for the same seed.
std::vector<TuneCandidate> drawCandidates(const TuneSpec& spec);

// The value text of a range's draw u in [0, 1) (tune_spec.h: log, step, integer), clamped to it.
std::string rangeValue(const TuneDimension& dimension, double u);

}  // namespace lpvlab

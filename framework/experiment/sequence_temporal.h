#pragma once
// A sequence frame's temporal figures (framework/metrics/temporal.h): its change from the frame
// before at the same surface points and, with references, the error of that change against the
// references' change. docs/animation.md states the conventions.
//
// The record's "temporal" block, for every frame but the first:
//   at_rest               the scene (lights, geometry) is the previous frame's: only the camera
//                         moved, so a change of a view-independent output is flicker
//   reprojected_fraction  the pixels the previous frame saw, of those the camera sees now
//   change.<aov>          the LPV output's change (TemporalChange), per compared output
//   error.<pair>          per comparison pair with [reference] compare (TemporalError)

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/experiment/experiment.h"
#include "framework/io/image.h"
#include "framework/reference/reference_cache.h"

namespace lpvlab {

// What the next frame compares itself with.
struct FrameState {
  Camera camera;
  std::string sceneHash;
  std::vector<NamedImage> aovs;        // the run's outputs, as written to the frame's EXR
  std::optional<Reference> reference;  // with [reference] compare

  // Keeps of the outputs only what the temporal figures read: depth, normal, the compared run
  // outputs, and the compared reference outputs with their variances.
  void keepOnlyCompared(const ComparisonSettings& comparison);
};

nlohmann::json temporalRecord(const FrameState& now, const FrameState& before,
                              const ComparisonSettings& comparison);

// The sequence's temporal figures from its frame records: per output and pair, the mean and the
// largest relative change (over the frames at rest: the flicker) and relative error.
nlohmann::json temporalSummary(const std::vector<nlohmann::json>& records);

}  // namespace lpvlab

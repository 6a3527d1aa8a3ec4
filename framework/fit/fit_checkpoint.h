#pragma once
// Resuming a fit: `lpvlab fit` writes its progress (every iteration so far, with the parameter
// values after it) to DIR/fit.progress.json, atomically, after every iteration. Run again with
// the same file and overrides into the same DIR, an interrupted fit continues from its last
// iteration (runFit's `resume`) instead of starting over; the file is removed once fit.json and
// the other outputs are written.
//
// The progress belongs to one fit, named by fitKey: a hash of everything that decides the path
// of the solve (the experiment table, the parameters with their initial values, bounds and
// steps, the fitted views, the residual, loss and difference settings). Held-out views,
// max_iterations, rank_tolerance and tile do not change the path, so they may be changed between
// runs (raise max_iterations of an interrupted fit and it goes on further). Progress with another
// key is not resumed.

#include <optional>
#include <string>

#include "framework/fit/fit_problem.h"

namespace lpvlab {

std::string fitKey(const FitSpec& spec);

void writeFitProgress(const std::string& path, const std::string& key, const FitProgress& progress);

// The progress at `path` if it exists and belongs to the fit `key`; nullopt if there is none or
// it is another fit's (`otherFit` set then). A file that cannot be read is an Error naming it.
std::optional<FitProgress> readFitProgress(const std::string& path, const std::string& key,
                                           bool* otherFit = nullptr);

}  // namespace lpvlab

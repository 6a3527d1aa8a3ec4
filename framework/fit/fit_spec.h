#pragma once
// The [fit] table of an experiment file: which strategy constants `lpvlab fit` fits, on which
// views, and how (docs/fitting.md). The rest of the file is the experiment the views start from.
//
//   [fit]
//   parameters = [{ key = "propagation.damping", initial = 1.0, lower = 0.5, upper = 1.5 }]
//                              # (each may also give its own `step`)
//   residual = "linear"        # linear | relative | log   (per pixel and channel)
//   epsilon = 1e-2             # relative and log residuals: radiance added to keep black finite
//   loss = "none"              # none | huber | cauchy, with loss_scale (in residual units)
//   derivatives = "automatic"  # automatic (where the composition carries them) | central
//   step = 1e-3                # central differences: relative step
//   max_iterations = 20
//   rank_tolerance = 1e-3      # singular values of the scaled Jacobian below this, relative to
//                              # the largest, are a direction the images do not determine
//   tile = 16                  # pixels per side of the tiles of the sandwich covariance, within
//                              # which pixel errors may be correlated (fit_problem.h)
//   [[fit.views]]              # the views fitted on: `name`, and any experiment tables (scene,
//   name = "front"             # camera, lights, ...), each replacing the file's table whole
//   [[fit.held_out]]           # views only measured, before and after (same form)
//
// Every bad input is an Error naming the file, the key and the problem: a key that is not a
// real-valued parameter some strategy of the experiment reads, bounds that exclude the initial
// value, no views.

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "framework/experiment/named_views.h"

namespace lpvlab {

struct FitParameter {
  std::string key;        // "propagation.damping": <stage table>.<parameter>
  double initial = 0.0;   // default: the experiment's value (given or the strategy's default)
  double lower = -1e300;  // bounds, inclusive; default unbounded
  double upper = 1e300;
  double step = 0.0;      // relative central-difference step; 0: the fit's `step`
};

using FitViewSpec = NamedView;  // [[fit.views]], [[fit.held_out]]

enum class ResidualKind { Linear, Relative, Log };
enum class LossKind { None, Huber, Cauchy };
enum class DerivativeKind { Automatic, Central };

struct FitSpec {
  std::string file;                       // the experiment file
  toml::table base;                       // its table, `extends`/`include` merged, no [fit]
  std::vector<FitParameter> parameters;
  std::vector<FitViewSpec> views;         // fitted on
  std::vector<FitViewSpec> heldOut;       // measured only
  ResidualKind residual = ResidualKind::Linear;
  double epsilon = 1e-2;
  LossKind loss = LossKind::None;
  double lossScale = 1.0;
  double relativeStep = 1e-3;
  // Automatic: through the frame on dual numbers where the composition carries a parameter's
  // derivatives (fit_problem.h), central differences for the others; Central: all by differences.
  DerivativeKind derivatives = DerivativeKind::Automatic;
  int maxIterations = 20;
  double rankTolerance = 1e-3;
  int tile = 16;

  // The experiment table of a view: the base with the view's tables in place of its own.
  toml::table viewTable(const FitViewSpec& view) const;
};

// Reads the experiment file `path` with the overrides applied (as `lpvlab run -s`).
FitSpec readFitSpec(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from a table already read; `path` names it in messages and anchors relative files.
FitSpec readFitSpec(toml::table root, const std::string& path);

const char* residualName(ResidualKind kind);
const char* lossName(LossKind kind);
const char* derivativeName(DerivativeKind kind);

}  // namespace lpvlab

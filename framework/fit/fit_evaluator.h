#pragma once
// What a fit compares: for parameter values x, each view is rendered by the GL pipeline with x
// written into its experiment table (as `-s key=value` would), and its `indirect` output is
// compared per pixel and channel with the view's target, the path-traced reference's `indirect1`
// (the same pair the metrics compare first). As in the metrics, only the pixels where the camera
// sees a surface count (the run's depth > 0).
//
// Residual of a covered pixel's channel, with a = indirect, b = target, eps = FitSpec::epsilon:
//   linear    a - b
//   relative  (a - b) / sqrt(b^2 + eps)          (its mean square is the metrics' rel_mse)
//   log       log(a + eps) - log(b + eps)
// weighted by 1 / sqrt(3 * covered pixels of the view), so that half the sum of squares is half
// the sum over views of each view's mean square: views of different sizes weigh the same.
// A robust loss rho (FitSpec::loss) is applied to each residual r as sign(r) sqrt(rho(r^2)):
// Ceres applies a LossFunction per residual block, and an image is one block (one rendering per
// evaluation), so the loss is folded into the residuals; the sum of squares is then exactly the
// robust cost sum rho(r^2).

#include <toml++/toml.h>

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/experiment/scene_cache.h"
#include "framework/fit/fit_spec.h"
#include "framework/gl/shader_compiler.h"
#include "framework/io/image.h"
#include "framework/scene/scene.h"

namespace ceres {
class LossFunction;
}

namespace lpvlab {

class Pipeline;

// The fit reads each scene once (SceneCache) and builds the strategies per rendering: they read
// the parameter values.

struct FitView {
  std::string name;
  bool heldOut = false;
  toml::table table;      // the view's experiment table (FitSpec::viewTable)
  Image target;           // RGB, the reference's indirect1
};

// The views of `spec` (fitted, then held out), each with its path-traced reference, rendered or
// reused from the reference cache (framework/reference/reference_cache.h); the scenes are read
// through `scenes` (pass the evaluator's, so that they are read once).
std::vector<FitView> makeFitViews(const FitSpec& spec, SceneCache& scenes);

struct ViewRender {
  Image indirect;         // RGB
  Image mask;             // 1 channel: 1 where the camera sees a surface
};

class FitEvaluator {
public:
  // Needs the GL context current, and on the calling thread for every call; `spec` must outlive
  // the evaluator.
  FitEvaluator(const FitSpec& spec, std::vector<FitView> views, SceneCache scenes = {});

  // `view` rendered with the parameter values `x` (FitSpec::parameters order).
  ViewRender render(const FitView& view, const std::vector<double>& x);

  // The residuals of the fitted views at `x`, residualCount() values (0 at background pixels).
  void residuals(const std::vector<double>& x, double* out);
  // Automatic derivatives (framework/pipeline/dual_frame.h): per parameter, "" if every fitted
  // view's composition carries its derivatives, else why not (then the fit takes central
  // differences for it). FitSpec::derivatives = central refuses every one.
  std::vector<std::string> automaticRefusals();
  // The Jacobian columns of residuals() at `x` for the parameters `which` (indices, each one
  // automaticRefusals accepts) into columns[j], from derivatives through each fitted view's
  // frame: a pass per view per kDualSlots parameters.
  void automaticColumns(const std::vector<double>& x, const std::vector<std::size_t>& which,
                        std::vector<std::vector<double>>& columns);
  int residualCount() const { return residualCount_; }
  // Covered residuals (pixels times channels) of the fitted views at the last evaluation.
  long long coveredResiduals() const { return covered_; }

  // Per view at `x`: {name, held_out, cost (half the view's mean squared residual), metrics of
  // indirect against indirect1 (framework/metrics/metrics.h)}.
  nlohmann::json errors(const std::vector<double>& x);

  // Every parameter vector rendered so far, in order (for tests: the bounds are kept).
  const std::vector<std::vector<double>>& evaluated() const { return evaluated_; }
  const std::vector<FitView>& views() const { return views_; }
  const FitSpec& spec() const { return spec_; }
  const SceneCache& scenes() const { return scenes_; }

private:
  // Residuals of one view into out[0 .. 3 w h); returns the covered count.
  long long viewResiduals(const FitView& view, const ViewRender& render, double* out) const;
  // A view's pipeline with the parameter values `x`; the last frame's outputs.
  std::unique_ptr<Pipeline> pipeline(const FitView& view, const std::vector<double>& x);
  ViewRender outputs(const FitView& view, const Pipeline& pipeline, const std::vector<double>& x) const;
  // One covered residual (see above) from indirect a and target b, and its derivative by a.
  struct Residual {
    double value, slope;
  };
  Residual residualOf(double a, double b, double weight, const ceres::LossFunction* loss) const;
  static double viewWeight(const ViewRender& render);  // 1 / sqrt(3 covered pixels)

  const FitSpec& spec_;
  std::vector<FitView> views_;
  SceneCache scenes_;
  ShaderCompiler shaders_;
  int residualCount_ = 0;
  long long covered_ = 0;
  std::vector<std::vector<double>> evaluated_;
};

}  // namespace lpvlab

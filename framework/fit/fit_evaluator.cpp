#include "framework/fit/fit_evaluator.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <ceres/loss_function.h>

#include "framework/core/error.h"
#include "framework/math/dual.h"
#include "framework/experiment/experiment.h"
#include "framework/metrics/metrics.h"
#include "framework/experiment/experiment_renderer.h"
#include "framework/pipeline/pipeline.h"
#include "framework/reference/reference_cache.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {

namespace {

// x's values written into the view's table, as `-s key=value` would (keys are <stage>.<name>,
// checked by readFitSpec).
toml::table withParameters(const FitSpec& spec, const toml::table& table, const std::vector<double>& x) {
  toml::table t = table;
  for (std::size_t i = 0; i < spec.parameters.size(); ++i) {
    const std::string& key = spec.parameters[i].key;
    const auto dot = key.find('.');
    const std::string stage = key.substr(0, dot);
    if (!t.contains(stage)) t.insert(stage, toml::table{});
    toml::table* stageTable = t[stage].as_table();
    if (!stageTable) throw Error(spec.file + ": key '" + stage + "': expected a table");
    stageTable->insert_or_assign(key.substr(dot + 1), x[i]);
  }
  return t;
}

Image coverage(const Image& depth) {
  Image mask(depth.width, depth.height, 1);
  for (std::size_t i = 0; i < mask.pixels.size(); ++i) mask.pixels[i] = depth.pixels[i] > 0.0f;
  return mask;
}

std::unique_ptr<ceres::LossFunction> makeLoss(const FitSpec& spec) {
  switch (spec.loss) {
    case LossKind::Huber: return std::make_unique<ceres::HuberLoss>(spec.lossScale);
    case LossKind::Cauchy: return std::make_unique<ceres::CauchyLoss>(spec.lossScale);
    case LossKind::None: break;
  }
  return nullptr;
}

}  // namespace

std::vector<FitView> makeFitViews(const FitSpec& spec, SceneCache& scenes) {
  std::vector<FitView> views;
  for (const bool heldOut : {false, true})
    for (const FitViewSpec& v : heldOut ? spec.heldOut : spec.views) {
      FitView view{v.name, heldOut, spec.viewTable(v), {}};
      Experiment e;
      try {
        e = loadExperiment(view.table, spec.file, std::ref(scenes));
      } catch (const Error& error) {
        throw Error("view '" + v.name + "': " + error.what());
      }
      view.target = findAov(ensureReference(e.scene, e.camera, e.reference).aovs, "indirect1");
      views.push_back(std::move(view));
    }
  return views;
}

FitEvaluator::FitEvaluator(const FitSpec& spec, std::vector<FitView> views, SceneCache scenes)
    : spec_(spec), views_(std::move(views)), scenes_(std::move(scenes)) {
  for (const FitView& v : views_)
    if (!v.heldOut) residualCount_ += 3 * v.target.width * v.target.height;
  if (residualCount_ == 0) throw Error(spec.file + ": key 'fit.views': no views to fit on");
}

std::unique_ptr<Pipeline> FitEvaluator::pipeline(const FitView& view, const std::vector<double>& x) {
  Experiment e;
  try {
    e = loadExperiment(withParameters(spec_, view.table, x), spec_.file, std::ref(scenes_));
  } catch (const Error& error) {
    throw Error("view '" + view.name + "': " + error.what());
  }
  if (e.settings.width != view.target.width || e.settings.height != view.target.height)
    throw Error("view '" + view.name + "': the target is " + std::to_string(view.target.width) +
                "x" + std::to_string(view.target.height) + ", the run " +
                std::to_string(e.settings.width) + "x" + std::to_string(e.settings.height));
  for (const ParticleGeometry& particles : e.particles)
    if (particles.drawing().lightField)
      throw Error("view '" + view.name + "': particle system '" + particles.system().name +
                  "' is drawn as a light field, which lpvlab fit does not draw (draw = \"geometry\" "
                  "draws its particles as the scene's meshes)");
  // The residuals compare the indirect light alone: no shadow maps, no direct light (their
  // read-back for the CPU's direct light was most of a rendering's time).
  e.settings.directLight = false;
  RasterPlan raster = chooseExperimentRaster(e);
  return std::make_unique<Pipeline>(e.scene, e.camera, e.settings, std::move(e.method), shaders_,
                                    std::move(raster));
}

// The last frame's indirect image and coverage; an Error for NaN or Inf.
ViewRender FitEvaluator::outputs(const FitView& view, const Pipeline& pipeline,
                                 const std::vector<double>& x) const {
  const std::vector<NamedImage> aovs = pipeline.readOutputs();
  ViewRender out{findAov(aovs, "indirect"), coverage(findAov(aovs, "depth"))};
  for (float v : out.indirect.pixels)
    if (!std::isfinite(v))
      throw Error("view '" + view.name + "': the indirect image holds NaN or Inf at parameters " +
                  nlohmann::json(x).dump());
  return out;
}

ViewRender FitEvaluator::render(const FitView& view, const std::vector<double>& x) {
  evaluated_.push_back(x);
  // The pipeline has no state across frames: the first frame is the one `lpvlab run` writes.
  const std::unique_ptr<Pipeline> p = pipeline(view, x);
  p->renderFrame();
  return outputs(view, *p, x);
}

std::vector<std::string> FitEvaluator::automaticRefusals() {
  std::vector<std::string> why(spec_.parameters.size());
  if (spec_.derivatives == DerivativeKind::Central) {
    why.assign(why.size(), "derivatives = \"central\"");
    return why;
  }
  std::vector<double> x;
  for (const FitParameter& parameter : spec_.parameters) x.push_back(parameter.initial);
  for (const FitView& view : views_) {
    if (view.heldOut) continue;
    const std::unique_ptr<Pipeline> p = pipeline(view, x);
    for (std::size_t j = 0; j < why.size(); ++j)
      if (const std::string refusal = p->derivativeRefusal(spec_.parameters[j].key);
          why[j].empty() && !refusal.empty())
        why[j] = "view '" + view.name + "': " + refusal;
  }
  return why;
}

void FitEvaluator::automaticColumns(const std::vector<double>& x,
                                    const std::vector<std::size_t>& which,
                                    std::vector<std::vector<double>>& columns) {
  const std::size_t n = std::size_t(residualCount_);
  for (std::size_t j : which) columns[j].assign(n, 0.0);
  const std::unique_ptr<ceres::LossFunction> loss = makeLoss(spec_);
  std::size_t offset = 0;  // of the view's residuals
  for (const FitView& view : views_) {
    if (view.heldOut) continue;
    // Up to kDualSlots parameters per pass over the frame.
    for (std::size_t first = 0; first < which.size(); first += std::size_t(kDualSlots)) {
      const std::size_t count = std::min(which.size() - first, std::size_t(kDualSlots));
      std::vector<std::string> seeds;
      for (std::size_t k = 0; k < count; ++k) seeds.push_back(spec_.parameters[which[first + k]].key);
      evaluated_.push_back(x);
      const std::unique_ptr<Pipeline> p = pipeline(view, x);
      const Pipeline::FrameDerivatives d = p->renderDerivatives(seeds);
      const ViewRender render = outputs(view, *p, x);
      const double weight = viewWeight(render);
      for (std::size_t i = 0; i < std::size_t(3) * view.target.width * view.target.height; ++i) {
        if (render.mask.pixels[i / 3] <= 0.0f) continue;
        const double slope =
            residualOf(render.indirect.pixels[i], view.target.pixels[i], weight, loss.get()).slope;
        for (std::size_t k = 0; k < count; ++k) {
          const double derivative = d.derivatives[k].pixels[i];
          if (!std::isfinite(derivative))
            throw Error("view '" + view.name + "': the derivative of the indirect image by '" +
                        seeds[k] + "' holds NaN or Inf at parameters " + nlohmann::json(x).dump());
          columns[which[first + k]][offset + i] = slope * derivative;
        }
      }
    }
    offset += std::size_t(3) * view.target.width * view.target.height;
  }
}

double FitEvaluator::viewWeight(const ViewRender& render) {
  long long covered = 0;
  for (float m : render.mask.pixels) covered += m > 0.0f;
  return covered > 0 ? 1.0 / std::sqrt(3.0 * double(covered)) : 0.0;
}

FitEvaluator::Residual FitEvaluator::residualOf(double a, double b, double weight,
                                                const ceres::LossFunction* loss) const {
  double r = 0.0, slope = 0.0;  // the residual and dr/da, before the weight and the loss
  switch (spec_.residual) {
    case ResidualKind::Linear:
      r = a - b;
      slope = 1.0;
      break;
    case ResidualKind::Relative:
      r = (a - b) / std::sqrt(b * b + spec_.epsilon);
      slope = 1.0 / std::sqrt(b * b + spec_.epsilon);
      break;
    case ResidualKind::Log:
      r = std::log(std::max(a, 0.0) + spec_.epsilon) - std::log(std::max(b, 0.0) + spec_.epsilon);
      slope = a > 0.0 ? 1.0 / (a + spec_.epsilon) : 0.0;
      break;
  }
  r *= weight;
  slope *= weight;
  if (loss) {
    // r' = sign(r) sqrt(rho(r^2)): dr'/dr = rho'(r^2) |r| / sqrt(rho(r^2)), which tends to
    // sqrt(rho'(0)) = 1 at r = 0 for Huber and Cauchy.
    double rho[3];
    loss->Evaluate(r * r, rho);
    const double root = std::sqrt(rho[0]);
    slope *= root > 0.0 ? rho[1] * std::abs(r) / root : std::sqrt(rho[1]);
    r = std::copysign(root, r);
  }
  return {r, slope};
}

long long FitEvaluator::viewResiduals(const FitView& view, const ViewRender& render, double* out) const {
  const std::unique_ptr<ceres::LossFunction> loss = makeLoss(spec_);
  const std::size_t pixels = std::size_t(view.target.width) * view.target.height;
  long long covered = 0;
  for (std::size_t p = 0; p < pixels; ++p) covered += render.mask.pixels[p] > 0.0f;
  const double weight = viewWeight(render);
  for (std::size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < 3; ++c)
      out[3 * p + c] = render.mask.pixels[p] <= 0.0f
                           ? 0.0
                           : residualOf(render.indirect.pixels[3 * p + c],
                                        view.target.pixels[3 * p + c], weight, loss.get())
                                 .value;
  return 3 * covered;
}

void FitEvaluator::residuals(const std::vector<double>& x, double* out) {
  covered_ = 0;
  for (const FitView& view : views_) {
    if (view.heldOut) continue;
    covered_ += viewResiduals(view, render(view, x), out);
    out += 3 * std::size_t(view.target.width) * view.target.height;
  }
}

nlohmann::json FitEvaluator::errors(const std::vector<double>& x) {
  nlohmann::json out = nlohmann::json::array();
  for (const FitView& view : views_) {
    const ViewRender r = render(view, x);
    std::vector<double> residuals(3 * std::size_t(view.target.width) * view.target.height);
    viewResiduals(view, r, residuals.data());
    double cost = 0.0;
    for (double v : residuals) cost += 0.5 * v * v;
    out.push_back({{"view", view.name},
                   {"held_out", view.heldOut},
                   {"cost", cost},
                   {"metrics", computeMetrics(r.indirect, view.target, &r.mask).toJson()}});
  }
  return out;
}

}  // namespace lpvlab

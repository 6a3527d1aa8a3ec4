// [indirect] method = "radiosity": classic radiosity (seed 004) as an indirect-light method. The
// scene is split into patches (framework/radiosity/patches.h), form factors are estimated by the
// hemicube on GL or by Embree rays, the system B = E + rho (P + F B) is solved by Jacobi,
// Gauss-Seidel or progressive shooting, and each pixel shows the irradiance of the patch side it
// sees (flat or Gouraud). Parameters (docs/variants/radiosity.md):
//   patch_size           longest patch edge, m (0: the scene's largest extent / 8)
//   max_patches          a bound on the patches (an error above it, not a silent coarsening)
//   form_factors         "hemicube" (seed 004, 3.5-3.7) or "rays"
//   hemicube_resolution  pixels across the hemicube's top face (even)
//   hemicube_placement   "centroid" (the seed's), "vertices" (three, fig. 3.10) or "jittered" (a
//                        random point and turn per side): framework/radiosity/hemicube.h
//   rays                 form-factor rays per patch side (form_factors = "rays")
//   solver               "gauss_seidel" (the seed's, 3.4), "jacobi" or "shooting" (2.2.3.1)
//   tolerance            relative residual (gathering) or unshot power (shooting) to stop at
//   max_iterations       gathering sweeps (jacobi, gauss_seidel)
//   max_shots            shots (shooting)
//   light_samples        points per patch for the punctual lights' first shot (shadow rays)
//   display              "gouraud" or "flat"
//   one_bounce           show light reflected once before (`indirect1`'s counterpart) instead of
//                        every bounce (`indirect`)
//   adaptive_levels      passes of adaptive subdivision after the uniform solve (0: none); each
//                        splits the patches where radiosity changes fast and solves again
//   adaptive_threshold   a patch splits where a corner's radiosity differs from its own by more
//                        than this times the scene's mean radiosity
//   seed                 of the form-factor rays and of the jittered hemicubes
// Frames redo only what changed: the camera alone, the display; lights, the first shot and the
// solve (everything, with adaptive subdivision: the mesh followed the old light); geometry,
// everything. Form factors are stored (the memory report counts them). The work of adaptive
// passes is counted in the stages whose work it repeats; "refine" counts the passes.

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>

#include "framework/core/error.h"
#include "framework/core/parameters.h"
#include "framework/many_lights/host_gbuffer.h"
#include "framework/pipeline/pipeline.h"
#include "framework/pipeline/raster_inputs.h"
#include "framework/radiosity/hemicube.h"
#include "framework/radiosity/light_irradiance.h"
#include "framework/radiosity/patch_display.h"
#include "framework/radiosity/ray_form_factors.h"
#include "framework/radiosity/solver.h"
#include "framework/reference/material_sampling.h"

namespace lpvlab {

namespace {

class Radiosity : public IndirectMethod {
public:
  explicit Radiosity(Params& p) {
    patchSize_ = p.get<float>("patch_size", 0.0f, {.min = 0.0f, .max = 1e30f});
    maxPatches_ = p.get<int>("max_patches", 200000, {.min = 1, .max = 1 << 29});
    hemicube_ = p.getChoice("form_factors", "hemicube", {"hemicube", "rays"}) == "hemicube";
    formFactorsKey_ = p.where("form_factors");
    if (hemicube_) {
      resolution_ = p.get<int>("hemicube_resolution", 64, {.min = 2, .max = 2048});
      const std::string placement =
          p.getChoice("hemicube_placement", "centroid", {"centroid", "vertices", "jittered"});
      placement_ = placement == "vertices"   ? HemicubePlacement::Vertices
                   : placement == "jittered" ? HemicubePlacement::Jittered
                                             : HemicubePlacement::Centroid;
      if (resolution_ % 2 != 0)
        throw Error(p.where("hemicube_resolution") + ": " + std::to_string(resolution_) +
                    " is odd (the side faces are half the top face's height)");
    } else {
      rays_ = p.get<int>("rays", 1024, {.min = 1, .max = 1 << 24});
    }
    solver_.solver = radiositySolverFromName(
        p.getChoice("solver", "gauss_seidel", {"gauss_seidel", "jacobi", "shooting"}));
    solver_.tolerance = p.get<double>("tolerance", 1e-4, {.min = 0.0, .max = 1.0});
    if (solver_.solver == RadiositySolver::Shooting)
      solver_.maxIterations = p.get<int>("max_shots", 1000000, {.min = 0, .max = 2000000000});
    else
      solver_.maxIterations = p.get<int>("max_iterations", 1000, {.min = 0, .max = 1000000});
    lightSamples_ = p.get<int>("light_samples", 16, {.min = 1, .max = 4096});
    interpolation_ = p.getChoice("display", "gouraud", {"gouraud", "flat"}) == "gouraud"
                         ? PatchInterpolation::Gouraud
                         : PatchInterpolation::Flat;
    oneBounce_ = p.get<bool>("one_bounce", false);
    adaptiveLevels_ = p.get<int>("adaptive_levels", 0, {.min = 0, .max = 8});
    if (adaptiveLevels_ > 0)
      adaptiveThreshold_ = p.get<double>("adaptive_threshold", 0.5, {.min = 1e-6, .max = 1e6});
    seed_ = std::uint64_t(p.get<int>("seed", 1, {.min = 0}));
  }

  std::vector<std::string> stageNames() const override {
    if (adaptiveLevels_ > 0) return {"meshing", "form_factors", "first_shot", "solve", "refine", "indirect"};
    return {"meshing", "form_factors", "first_shot", "solve", "indirect"};
  }
  // Emissive surfaces are patches that shoot (area lights); no RSM.
  std::set<std::string> consumes() const override { return {std::string(raster::kEmission.name)}; }

  // The hemicube is drawn by GL's rasteriser; without GL the form factors are cast by rays.
  void check(const PipelineSettings& settings) const override {
    if (hemicube_ && !settings.gl)
      throw Error(formFactorsKey_ + ": \"hemicube\" draws each patch's hemicube with GL, and this "
                  "run has none (gl.backend = \"none\", or \"auto\" found no GL context); use "
                  "form_factors = \"rays\" or run with GL");
  }

  void prepare(const MethodSetup& setup) override {
    check(setup.settings);
    if (glm::any(glm::greaterThan(setup.settings.skyRadiance, glm::vec3(0.0f))))
      throw Error("radiosity: the sky is not a patch; radiosity runs without [sky] (remove it, or "
                  "use another method)");
    shaders_ = &setup.shaders;
    scene_ = setup.scene;
    lights_ = LightSampler(scene_, prepareMaterials(scene_)).punctual();
  }

  void moveScene(const Scene& scene, bool lightsMoved, bool geometryMoved) override {
    scene_ = scene;
    if (lightsMoved) lights_ = LightSampler(scene_, prepareMaterials(scene_)).punctual(), lightsStale_ = true;
    if (geometryMoved) geometryStale_ = true;
    // An adaptive mesh was refined for the old light: start again from the uniform one.
    if (lightsMoved && adaptiveLevels_ > 0) geometryStale_ = true;
  }

  void render(MethodFrame& frame) override {
    work_ = {};
    // A change starts a new solution: its time is this frame's solution stages alone.
    if (geometryStale_ || lightsStale_) solutionMs_.clear();
    // The solution's stages time themselves too: a run's medians are of frames after the first,
    // which redo only the display while nothing moves, so the cost of reaching the solution is
    // kept apart (statistics: solution_ms), as the report shows it.
    const auto timed = [&](const std::string& name, const std::function<bool()>& work) {
      frame.stage(name, [&] {
        const auto start = std::chrono::steady_clock::now();
        if (!work()) return;
        solutionMs_[name] = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      });
    };
    timed("meshing", [&] {
      if (!geometryStale_) return false;
      remesh();
      geometryStale_ = false;
      lightsStale_ = true;
      return true;
    });
    timed("form_factors", [&] { return makeAllRows(); });
    timed("first_shot", [&] {
      if (!lightsStale_) return false;
      shootFromLights();
      return true;
    });
    timed("solve", [&] {
      if (solved_) return false;
      solve();
      return true;
    });
    if (adaptiveLevels_ > 0)
      timed("refine", [&] {
        // Subdivision where the solution changes fast (seed 004, 2.2.1), a level at a time: the
        // split mesh gets its form factors, first shot and solve anew (rows of a refined mesh are
        // all recomputed: every side now sees the split patches).
        bool refined = false;
        while (level_ < adaptiveLevels_) {
          const std::vector<bool> split = splitFlags();
          if (std::none_of(split.begin(), split.end(), [](bool b) { return b; })) break;
          const auto start = std::chrono::steady_clock::now();
          rebuild(splitPatches(scene_, mesh_, split));
          ++level_;
          makeAllRows();
          shootFromLights();
          solve();
          levels_.push_back({{"level", level_},
                             {"patches", mesh_.patches.size()},
                             {"split", std::count(split.begin(), split.end(), true)},
                             {"ms", std::chrono::duration<double, std::milli>(
                                        std::chrono::steady_clock::now() - start).count()}});
          refined = true;
          work_.passes += 1.0;
        }
        return refined;
      });
    frame.stage("indirect", [&] {
      const HostGBuffer g = hostGBuffer(frame.host, frame.gbuffer);
      work_.displayRays = double(display_->render(frame.camera, g.position, g.normal, g.albedo,
                                                  oneBounce_ ? solution_.firstBounce : solution_.indirect,
                                                  interpolation_, frame.indirect.host()));
      work_.pixels = double(g.position.width) * g.position.height;
    });
  }

  std::map<std::string, std::vector<WorkCount>> work() const override {
    // A row entry read by the solve: a multiply-add of RGB doubles (6 flops) and 8 bytes. Form
    // factors count hemicubes (GL's rasterisation) or rays (Embree's traversal), not modelled.
    std::map<std::string, std::vector<WorkCount>> out;
    out["meshing"] = {{"patch", work_.patches, 40.0, double(sizeof(Patch))}};
    std::vector<WorkCount> ff = {{estimator_ ? estimator_->workUnit() : "row", work_.formFactorWork, 0.0, 0.0}};
    out["form_factors"] = ff;
    out["first_shot"] = {{"shadow ray", work_.shadowRays, 0.0, 0.0}};
    out["solve"] = {{"form factor", work_.solveEntries, 6.0, double(sizeof(FormFactor))}};
    out["indirect"] = {{"display ray", work_.displayRays, 0.0, 0.0}, {"pixel", work_.pixels, 20.0, 64.0}};
    if (adaptiveLevels_ > 0) out["refine"] = {{"adaptive pass", work_.passes, 0.0, 0.0}};
    return out;
  }

  std::size_t memoryBytes() const override {
    std::size_t bytes = mesh_.memoryBytes() + rows_.memoryBytes() +
                        system_.sides() * (sizeof(double) + 3 * sizeof(glm::dvec3)) +
                        4 * solution_.indirect.size() * sizeof(glm::dvec3);
    if (rayScene_) bytes += rayScene_->memoryBytes();
    if (display_) bytes += display_->memoryBytes();
    if (estimator_) bytes += estimator_->memoryBytes();
    return bytes;
  }

  nlohmann::json statistics() const override {
    double sumRows = 0.0;
    std::size_t rowsPresent = 0;
    for (std::size_t i = 0; i < rows_.sides(); ++i)
      if (rows_.has(i)) sumRows += rows_.rowSum(i), ++rowsPresent;
    nlohmann::json out = {
        {"patches", mesh_.patches.size()},
        {"sides", mesh_.sides()},
        {"patch_size_m", resolvedPatchSize_},
        {"form_factors",
         {{"estimator", estimator_ ? estimator_->statistics() : nlohmann::json::object()},
          {"stored", true},
          {"rows", rowsPresent},
          {"entries", rows_.entries()},
          {"bytes", rows_.memoryBytes()},
          {"mean_row_sum", rowsPresent ? sumRows / double(rowsPresent) : 0.0},
          {"reciprocity_error", reciprocity_},
          {"rows_made_during_solve", rowsMadeInSolve_},
          {"seconds_during_solve", formFactorSecondsInSolve_}}},
        {"solver",
         {{"name", radiositySolverName(solver_.solver)},
          {"tolerance", solver_.tolerance},
          {"iterations", solution_.iterations},
          {"converged", solution_.converged},
          {"final_relative", solution_.finalRelative},
          {"convergence", convergenceJson(solution_.log)}}},
        {"solution_ms", solutionMsJson()},
        {"adaptive", {{"levels", adaptiveLevels_}, {"threshold", adaptiveThreshold_}, {"passes", levels_}}},
        {"display", interpolation_ == PatchInterpolation::Gouraud ? "gouraud" : "flat"},
        {"one_bounce", oneBounce_}};
    if (solver_.solver == RadiositySolver::Shooting)
      out["solver"]["energy_W"] = {{"first_shot", solution_.energy.firstShot},
                                   {"absorbed", solution_.energy.absorbed},
                                   {"escaped", solution_.energy.escaped},
                                   {"unshot", solution_.energy.unshot}};
    return out;
  }

private:
  struct FrameWork {
    double patches = 0, formFactorWork = 0, shadowRays = 0, solveEntries = 0, displayRays = 0, pixels = 0,
           passes = 0;
  };

  void remesh() {
    const Bounds b = scene_.bounds();
    const glm::vec3 extent = b.extent();
    sceneSize_ = std::max({extent.x, extent.y, extent.z});
    resolvedPatchSize_ = patchSize_ > 0.0f ? patchSize_ : sceneSize_ / 8.0f;
    rebuild(meshPatches(scene_, resolvedPatchSize_, std::size_t(maxPatches_)));
    level_ = 0;
    levels_ = nlohmann::json::array();
  }

  // Everything made from the mesh, made anew for `mesh`.
  void rebuild(PatchMesh mesh) {
    if (mesh.patches.size() > std::size_t(maxPatches_))
      throw Error("radiosity: adaptive subdivision made " + std::to_string(mesh.patches.size()) +
                  " patches, more than max_patches (" + std::to_string(maxPatches_) +
                  "); raise it, the adaptive_threshold, or lower adaptive_levels");
    estimator_.reset();
    display_.reset();
    rayScene_.reset();
    mesh_ = std::move(mesh);
    rayScene_ = std::make_unique<PatchRayScene>(scene_, mesh_);
    display_ = std::make_unique<PatchDisplay>(mesh_, *rayScene_);
    if (hemicube_)
      estimator_ = std::make_unique<HemicubeFormFactors>(*shaders_, mesh_, resolution_, sceneSize_, placement_, seed_);
    else
      estimator_ = std::make_unique<RayFormFactors>(mesh_, *rayScene_, rays_, seed_);
    rows_ = FormFactorRows(mesh_.sides());
    solver_.rowBatch = estimator_->batch();
    system_ = radiositySystem(mesh_);
    work_.patches += double(mesh_.patches.size());
    solved_ = false;
    lightsStale_ = true;
  }

  // Gathering needs every row; shooting makes its shooters' rows as it goes (in "solve").
  bool makeAllRows() {
    if (solver_.solver == RadiositySolver::Shooting) return false;
    std::vector<std::uint32_t> all(mesh_.sides());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = std::uint32_t(i);
    const std::size_t before = rowsMade_;
    makeRows(all);
    return rowsMade_ != before;
  }

  void shootFromLights() {
    const LightIrradiance shot = lightIrradiance(mesh_, *rayScene_, lights_, lightSamples_);
    system_.lightIrradiance = shot.perSide;
    work_.shadowRays += double(shot.shadowRays);
    solved_ = false;
    lightsStale_ = false;
  }

  void solve() {
    const double before = estimatorSeconds_;
    const std::size_t rowsBefore = rowsMade_;
    solution_ = solveRadiosity(system_, rows_, [&](const std::vector<std::uint32_t>& s) { makeRows(s); }, solver_);
    formFactorSecondsInSolve_ = estimatorSeconds_ - before;
    rowsMadeInSolve_ = rowsMade_ - rowsBefore;
    work_.solveEntries += double(solution_.rowEntriesRead);
    if (solver_.solver != RadiositySolver::Shooting) reciprocity_ = reciprocityError(rows_, system_.area);
    solved_ = true;
  }

  // Patches to split: those below the deepest level where some corner's radiosity (Gouraud's
  // value, either side) differs from the patch's own by more than adaptive_threshold times the
  // scene's mean radiosity (area-weighted over the sides that have any).
  std::vector<bool> splitFlags() const {
    std::vector<glm::dvec3> b(mesh_.sides());
    double weighted = 0.0, area = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      b[i] = system_.exitance[i] + solution_.reflected[i];
      const double sum = b[i].x + b[i].y + b[i].z;
      if (sum > 0.0) weighted += system_.area[i] * sum, area += system_.area[i];
    }
    std::vector<bool> split(mesh_.patches.size(), false);
    if (!(area > 0.0)) return split;
    const double limit = adaptiveThreshold_ * weighted / area;
    const std::vector<glm::vec3> corners = display_->cornerValues(b);
    for (std::size_t p = 0; p < split.size(); ++p) {
      if (mesh_.patches[p].level >= adaptiveLevels_) continue;
      for (std::size_t side = 2 * p; side < 2 * p + 2 && !split[p]; ++side)
        for (int c = 0; c < 3 && !split[p]; ++c) {
          const glm::dvec3 d = glm::abs(glm::dvec3(corners[3 * side + std::size_t(c)]) - b[side]);
          split[p] = d.x + d.y + d.z > limit;
        }
    }
    return split;
  }

  // Wall ms of each solution stage when it last did its work, and their sum: the time from a
  // change of the scene to its solution (the display then costs a frame's "indirect" stage).
  nlohmann::json solutionMsJson() const {
    nlohmann::json out = nlohmann::json::object();
    double total = 0.0;
    for (const auto& [stage, ms] : solutionMs_) out[stage] = ms, total += ms;
    out["total"] = total;
    return out;
  }

  void makeRows(const std::vector<std::uint32_t>& wanted) {
    std::vector<std::uint32_t> sides;
    for (std::uint32_t s : wanted)
      if (!rows_.has(s)) sides.push_back(s);
    if (sides.empty()) return;
    const auto start = std::chrono::steady_clock::now();
    const double before = estimator_->work();
    estimator_->computeRows(sides, rows_);
    work_.formFactorWork += estimator_->work() - before;
    rowsMade_ += sides.size();
    estimatorSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // Parameters.
  float patchSize_ = 0.0f;
  int maxPatches_ = 0;
  bool hemicube_ = true;
  int resolution_ = 64, rays_ = 1024;
  HemicubePlacement placement_ = HemicubePlacement::Centroid;
  std::string formFactorsKey_;  // where form_factors was read, for messages
  SolverSettings solver_;
  int lightSamples_ = 16;
  PatchInterpolation interpolation_ = PatchInterpolation::Gouraud;
  bool oneBounce_ = false;
  int adaptiveLevels_ = 0;
  double adaptiveThreshold_ = 0.0;
  std::uint64_t seed_ = 1;

  // State.
  ShaderCompiler* shaders_ = nullptr;
  Scene scene_;
  std::vector<PunctualLight> lights_;
  float resolvedPatchSize_ = 0.0f, sceneSize_ = 0.0f;
  int level_ = 0;
  nlohmann::json levels_ = nlohmann::json::array();  // per adaptive pass: patches, split, ms
  PatchMesh mesh_;
  std::unique_ptr<PatchRayScene> rayScene_;
  std::unique_ptr<PatchDisplay> display_;
  std::unique_ptr<FormFactorEstimator> estimator_;
  FormFactorRows rows_;
  RadiositySystem system_;
  RadiositySolution solution_;
  bool geometryStale_ = true, lightsStale_ = true, solved_ = false;
  double estimatorSeconds_ = 0.0, formFactorSecondsInSolve_ = 0.0, reciprocity_ = 0.0;
  std::size_t rowsMade_ = 0, rowsMadeInSolve_ = 0;
  std::map<std::string, double> solutionMs_;
  FrameWork work_;
};

}  // namespace

LPVLAB_REGISTER(IndirectMethod, "radiosity",
                "classic radiosity (seed 004): patches, form factors by the hemicube on GL or by "
                "Embree rays, Jacobi, Gauss-Seidel or progressive shooting, flat or Gouraud display",
                Radiosity);

}  // namespace lpvlab

// `lpvlab explain [FILE] [-o DIR] [--vpls N]`: LPV's error against its path-traced reference split
// by stage (docs/explain.md). One frame is rendered, then again with one stage at a time replaced
// by an exact counterpart computed on the CPU from the same RSM (framework/explain/): the error
// each replacement removes is the stage's term. Writes DIR/explain.json (the budget per AOV pair,
// the oracles' noise, the VPLs used) and DIR/explain.exr (the reference's AOVs and every image of
// the chain, for tev or lpvlab compare), each to a temporary name renamed when complete. The
// oracles' images are checkpointed in DIR/partial/ as they are rendered, so a killed explanation
// resumes with them.

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "framework/cli/commands.h"
#include "framework/core/atomic_file.h"
#include "framework/core/error.h"
#include "framework/core/hash.h"
#include "framework/core/parameters.h"
#include "framework/core/log.h"
#include "framework/experiment/experiment_file.h"
#include "framework/experiment/experiment_renderer.h"
#include "framework/experiment/run.h"
#include "framework/experiment/run_outputs.h"
#include "framework/explain/explain_frame.h"
#include "framework/io/provenance.h"
#include "framework/many_lights/ray_scene.h"
#include "framework/reference/reference_cache.h"

namespace lpvlab::cli {

namespace {

namespace fs = std::filesystem;

std::string fixed(double value, int digits = 3) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << value;
  return s.str();
}

std::string figure(const nlohmann::json& value, int digits = 3) {
  return value.is_number() ? fixed(value.get<double>(), digits) : value.get<std::string>();
}

// The budget of one pair as a table on stdout.
void printBudget(const std::string& pair, const nlohmann::json& budget) {
  std::cout << "\n" << pair << "\n  image            block nRMSE   mean/ref   oracle noise\n";
  for (const auto& name : budget["chain"]) {
    const nlohmann::json& image = budget["images"][name.get<std::string>()];
    std::cout << "  " << std::left << std::setw(16) << name.get<std::string>() << std::right
              << std::setw(12) << figure(image["block_nrmse"]) << std::setw(11)
              << fixed(image["mean_ratio"].get<double>()) << std::setw(15)
              << (image.contains("oracle_noise_block_nrmse") ? fixed(image["oracle_noise_block_nrmse"].get<double>()) : "-")
              << "\n";
  }
  std::cout << "  stage         error removed   brightness x   own error (block nRMSE vs replacement)\n";
  for (const nlohmann::json& term : budget["terms"])
    std::cout << "  " << std::left << std::setw(14) << term["stage"].get<std::string>() << std::right
              << std::setw(13) << fixed(term["block_nrmse_reduction"].get<double>()) << std::setw(15)
              << fixed(term["brightness_factor"].get<double>()) << std::setw(13)
              << figure(term["against_replacement"]["block_nrmse"]) << "  (vs "
              << term["replaced_by"].get<std::string>() << ")\n";
  std::cout << "  total " << figure(budget["total"]["block_nrmse"]) << " block nRMSE, mean "
            << fixed(budget["total"]["mean_ratio"].get<double>()) << " x the reference; leakage: "
            << "gathering without visibility is " << fixed(budget["leakage_factor"].get<double>())
            << " x as bright as with it\n  the reference's own noise: "
            << fixed(budget["reference_noise_block_nrmse"].get<double>()) << " block nRMSE\n";
}

// explain.exr: the reference's AOV of each explained pair, every image of the chain, the depth.
void writeLayers(const std::string& path, const ExplainImages& images, const Reference& reference,
                 const ComparisonSettings& comparison, const Image& depth, const std::string& name) {
  std::vector<NamedImage> layers;
  for (const auto& [mine, theirs] : comparison.pairs)
    if (mine == "indirect" || mine == "combined") layers.push_back({"reference_" + theirs, findAov(reference.aovs, theirs)});
  for (const auto& [layer, image] : std::vector<std::pair<std::string, const Image*>>{
           {"method", &images.method}, {"grid", &images.grid}, {"grid_visible", &images.gridVisible},
           {"gather", &images.gather}, {"gather_visible", &images.gatherVisible}})
    layers.push_back({layer, *image});
  layers.push_back({"depth", depth});
  writeExr(path, layers, {{"lpvlab:experiment", name}});
}

// What the oracles' images depend on: the experiment as resolved (its file with the overrides),
// the VPL budget and lpvlab's revision.
// The method's grid and the exact one beside it (grid slices, figs. 8.9/8.10; the report draws
// their middle slices) into `dir`, named in `outputs`. A checkpoint from before the exact grids
// were kept has none: said so.
void writeGrids(const ExplainedFrame& explained, const fs::path& dir, nlohmann::json& outputs) {
  outputs["grid"] = writeGridDump(explained.methodGrid, dir.string(), "grid");
  if (!explained.exactGrid.values.empty())
    outputs["exact_grid"] = writeGridDump(explained.exactGrid, dir.string(), "exact_grid");
  else
    outputs["exact_grid"] = "not written: resumed from a checkpoint without its grids";
}

std::string checkpointKey(const Options& options) {
  toml::table root = options.experiment.empty() ? toml::table{} : readExperimentTable(options.experiment);
  for (const std::string& o : options.overrides) applyOverride(root, o);
  std::ostringstream text;
  text << root << "\nvpls " << options.explainVpls << "\n" << lpvlabRevision();
  return Hasher().text(text.str()).hex();
}

// The oracles' images in DIR/partial/<key>/<name>.exr: an interrupted explanation with the same
// key resumes with them (another key's are removed first).
ExplainCheckpoint checkpointIn(const fs::path& partial, const std::string& key) {
  if (fs::exists(partial) && !fs::exists(partial / key)) fs::remove_all(partial);
  const fs::path dir = partial / key;
  fs::create_directories(dir);
  ExplainCheckpoint checkpoint;
  checkpoint.load = [dir](const std::string& name) -> std::optional<Image> {
    const fs::path file = dir / (name + ".exr");
    if (!fs::exists(file)) return std::nullopt;
    log::info("explain: " + name + " from the checkpoint of an interrupted run");
    return findAov(readExr(file.string()), name);
  };
  checkpoint.save = [dir](const std::string& name, const Image& image) {
    writeExr((dir / (name + ".exr")).string(), {{name, image}});
  };
  return checkpoint;
}

}  // namespace

int explainCommand(const Options& options) {
  Experiment experiment = loadExperiment(options.experiment, options.overrides);
  const std::string out = options.out.empty() ? "runs/" + experiment.name + "-explain" : options.out;
  requireOutputDirectory(out, options.out.empty() ? "output directory" : "--out");
  if (experiment.animation.animated())
    throw Error(experiment.file + ": [animation]: explain renders one frame; drop the animation "
                "(or explain a file without one)");
  if (const std::string why = experiment.method->explainRefusal(); !why.empty())
    throw Error((experiment.file.empty() ? std::string("the built-in default") : experiment.file) + ": " + why);
  const fs::path dir(out);
  if (fs::exists(dir / "explain.json") && !options.force)
    throw Error((options.out.empty() ? "output directory " : "--out ") + out +
                ": holds a finished explanation (explain.json); --force replaces it");

  const Reference reference = ensureReference(experiment.scene, experiment.camera, experiment.reference);
  const RunContext run = openRunContext(experiment);
  if (!run.note.empty()) log::info(run.note);
  ShaderCompiler shaders;
  const Scene scene = experiment.scene;  // the renderer takes the experiment's strategies
  const ComparisonSettings comparison = experiment.comparison;
  ExperimentRenderer renderer(experiment, experiment.animation.frameTime(0), shaders);
  Pipeline& pipeline = renderer.pipeline();
  pipeline.renderFrame();
  const std::vector<NamedImage> aovs = pipeline.readOutputs();
  requireFiniteImages(aovs);
  const RayScene rays(scene);
  ExplainSettings settings;
  settings.vplsPerDraw = std::size_t(options.explainVpls);
  settings.checkpoint = checkpointIn(dir / "partial", checkpointKey(options));
  const ExplainedFrame explained = explainFrame(pipeline, rays.embree(), settings);

  const Image& mask = explained.mask;
  nlohmann::json result = {
      {"experiment", experiment.name},
      {"file", experiment.file},
      {"reference", {{"key", reference.key}, {"samples", reference.samples}}},
      {"vpls", explained.vpls},
      {"grid_blocks_light", explained.gridBlocksLight},
      {"oracle_seconds", explained.seconds},
      {"oracle_clock", "CPU wall clock"},
      {"host", hostInfo()},
      {"created_utc", utcTimestamp()},
      {"lpvlab", lpvlabRevision()},
      {"method", "docs/explain.md"}};
  for (const auto& [mine, theirs] : comparison.pairs) {
    if (mine != "indirect" && mine != "combined") continue;  // direct light has no LPV stage
    const Image* direct = mine == "combined" ? &findAov(aovs, "direct") : nullptr;
    const std::string pair = mine + "_vs_" + theirs;
    const Image& referenceImage = findAov(reference.aovs, theirs);
    result["budgets"][pair] = errorBudget(explained.images, direct, referenceImage, mask,
                                          explained.gridBlocksLight);
    result["budgets"][pair]["reference_noise_block_nrmse"] =
        referenceNoiseBlockNrmse(referenceImage, findAov(reference.aovs, theirs + "_variance"), mask);
  }
  if (!result.contains("budgets"))
    throw Error("[metrics] pairs: none compares indirect or combined, which the budget splits");

  fs::create_directories(dir);
  writeLayers((dir / "explain.exr").string(), explained.images, reference, comparison,
              findAov(aovs, "depth"), experiment.name);
  result["outputs"] = {{"exr", "explain.exr"},
                       {"units", "indirect radiance W/(m^2 sr); depth: view depth in metres"}};
  writeGrids(explained, dir, result["outputs"]);
  writeTextAtomically((dir / "explain.json").string(), result.dump(2) + "\n");
  fs::remove_all(dir / "partial");  // the oracles' checkpoint: the explanation is complete

  std::cout << "explain " << experiment.name << ": " << explained.vpls["per_draw"].get<std::size_t>()
            << " VPLs per draw (" << explained.vpls["draws"].get<int>() << " draws) of "
            << explained.vpls["covered_rsm_texels"].get<std::size_t>() << " RSM texels; reference "
            << reference.samples << " spp\n";
  for (const auto& [pair, budget] : result["budgets"].items()) printBudget(pair, budget);
  std::cout << "\nwrote " << out << "/{explain.json, explain.exr, grid.npy"
            << (explained.exactGrid.values.empty() ? "" : ", exact_grid.npy") << "}\n";
  return 0;
}

}  // namespace lpvlab::cli

// What LPV reports (light_propagation_volumes.h): its work, memory and kernels by strategy, its
// grid's placement and throughput, and the injection flux balance, a diagnostic after the timed
// frames.
#include <iomanip>
#include <sstream>

#include "framework/core/error.h"
#include "framework/math/shared.h"
#include "framework/pipeline/raster_inputs.h"
#include "variants/methods/lpv/light_propagation_volumes.h"

namespace lpvlab {

namespace {

double gridFlux(const std::vector<float>& coefficients, int cells, int coefficientCount) {
  double flux = 0.0;
  for (int channel = 0; channel < LightGrid::kChannels; ++channel)
    for (int cell = 0; cell < cells; ++cell)
      flux += shared::shIntegral(glm::dvec4(
          coefficients[shared::coefficientIndex(channel, 0, coefficientCount, cell, cells)], 0, 0, 0));
  return flux;
}

// Where each light grid sat (finest first; one entry without cascades).
nlohmann::json cascadeLevelsJson(const std::vector<LightGrid>& grids) {
  nlohmann::json levels = nlohmann::json::array();
  for (const LightGrid& grid : grids) {
    const GridGeometry& g = grid.geometry;
    levels.push_back({{"origin", {g.origin.x, g.origin.y, g.origin.z}},
                      {"cell_size", g.cellSize},
                      {"cells", {g.resolution.x, g.resolution.y, g.resolution.z}}});
  }
  return levels;
}

}  // namespace

FrameShape LightPropagationVolumes::frameShape() const {
  FrameShape shape;
  shape.cells = double(settings_.grid.cellCount());
  shape.levels = int(levels_.size());
  shape.coefficients = levels_.front().coefficients;
  shape.rsmTexels = double(lightMaps_->views) * lightMaps_->rsmResolution * lightMaps_->rsmResolution;
  shape.pixels = double(settings_.width) * settings_.height;
  return shape;
}

std::map<std::string, std::vector<WorkCount>> LightPropagationVolumes::work() const {
  std::map<std::string, std::vector<WorkCount>> counts;
  const FrameShape shape = frameShape();
  for (const auto& [table, strategy] : strategies_.all())
    for (const WorkCount& w : strategy->work(shape, requirements_))
      counts[stageOfTable(table)].push_back(w);
  return counts;
}

nlohmann::json LightPropagationVolumes::workReport(bool glKernels) const {
  Requirements requirements = requirements_;
  if (glKernels) requirements.backend = ComputeBackend::Gl;
  const FrameShape shape = frameShape();
  nlohmann::json report = nlohmann::json::object();
  for (const auto& [table, strategy] : strategies_.all()) {
    const std::string stage = stageOfTable(table);
    if (!report.contains(stage)) report[stage] = nlohmann::json::array();
    const std::vector<WorkCount> counts = strategy->work(shape, requirements);
    // A strategy that does not model its work yet is listed by table.
    if (counts.empty() && strategy->name() != "none")
      report[stage].push_back({{"table", table}, {"not_counted", strategy->name()}});
    for (const WorkCount& w : counts) report[stage].push_back(workCountJson(w));
  }
  return report;
}

nlohmann::json LightPropagationVolumes::memoryReport() const {
  std::size_t grids = 0;
  for (const LightGrid& grid : levels_) grids += grid.memoryBytes();
  nlohmann::json bytes = {{"light_grid", grids}};
  for (const ResourceTable& resources : resources_)
    for (const auto& [name, size] : resources.memoryBytes())
      bytes[name] = bytes.value(name, std::size_t(0)) + size;
  for (const auto& [table, strategy] : strategies_.all())
    bytes[table] = bytes.value(table, std::size_t(0)) + strategy->memoryBytes();
  return bytes;
}

std::size_t LightPropagationVolumes::memoryBytes() const {
  const nlohmann::json groups = memoryReport();  // kept: items() refers into it
  std::size_t total = 0;
  for (const auto& [group, bytes] : groups.items()) total += bytes.get<std::size_t>();
  return total;
}

bool LightPropagationVolumes::readsRasterImagesOnGl() const {
  for (const auto& [table, strategy] : strategies_.all())
    if (!strategy->runsOnCpu(requirements_)) return true;
  return false;
}

nlohmann::json LightPropagationVolumes::computeReport() const {
  nlohmann::json stages = nlohmann::json::object();
  for (const auto& [table, strategy] : strategies_.all())
    stages[table] = strategy->runsOnCpu(requirements_) ? "cpu" : "gl";
  return {{"strategies", stages}};
}

// A summary tells LPV's configurations apart by their strategies, grid and iterations.
std::vector<std::string> LightPropagationVolumes::summaryKeys() const {
  return {"injection.type",  "occlusion.type", "propagation.type",
          "rendering.type",  "grid.resolution", "grid.sh_order",
          "cascades.levels", "propagation.iterations"};
}

nlohmann::json LightPropagationVolumes::describe(
    const std::map<std::string, double>& medianStageMs) const {
  const auto propagation = medianStageMs.find("propagation");
  const double ms = propagation == medianStageMs.end() ? 0.0 : propagation->second;
  const double iterations = strategies_.propagation->iterations();
  return {{"propagation_cell_iterations_per_second",
           ms > 0.0 ? double(propagatedCells()) * iterations / (ms * 1e-3) : 0.0},
          {"cascade_levels", cascadeLevelsJson(levels_)}};
}

// The flux bookkeeping of injection (W, RGB summed): what the RSMs reflect, what the grid holds,
// and what each injection added. For an RSM injection, RSM flux minus what it added fell outside
// the grid; other injections (sky light) add flux that is not in the RSMs.
nlohmann::json LightPropagationVolumes::audit() {
  const InjectionBalance balance = measureInjection();
  nlohmann::json added = nlohmann::json::object();
  for (const auto& [table, flux] : balance.byInjection) added[table] = flux;
  nlohmann::json audit = {{"injection_flux_W",
                           {{"rsm", balance.rsmFlux}, {"grid", balance.gridFlux}, {"added_by", added}}}};
  // VPLs binned outside the light grid are dropped: a fixed grid that misses lit surfaces, or a
  // lit surface facing out on the scene's bounds, whose VPLs one cell out lie on the boundary of
  // a grid with one cell of margin (docs/variants.md#energy-audit).
  const double rsmAdded = balance.byInjection.front().second;
  if (strategies_.injection.front()->name() == "rsm_vpl" && balance.rsmFlux > 0.0 &&
      rsmAdded < 0.999 * balance.rsmFlux) {
    std::ostringstream percent;
    percent << std::setprecision(3) << 100.0 * (1.0 - rsmAdded / balance.rsmFlux);
    audit["warnings"].push_back(percent.str() +
                                "% of the RSMs' reflected flux fell outside the light grid and was dropped "
                                "(a fixed grid that misses lit surfaces, or lit surfaces facing out on "
                                "the scene's bounds: grid.margin = 2 keeps their VPLs)");
  }
  // What the strategies' own parameters make suspect (Strategy::warnings), named by table.
  for (const auto& [table, strategy] : strategies_.all())
    for (const std::string& warning : strategy->warnings()) audit["warnings"].push_back(table + ": " + warning);
  return audit;
}

std::vector<float> LightPropagationVolumes::readGrid(bool accumulated, int level) const {
  const LightGrid& grid = levels_.at(std::size_t(level));
  std::vector<float> data(grid.floatsPerGrid());
  (accumulated ? grid.accumulated : grid.current).download(data.data(), data.size() * sizeof(float));
  return data;
}

// Every level's accumulated grid, one after another: each is [channel][coefficient][z][y][x] in
// memory already (shaders/common/grid.glsl), so the levels stack into one C-order array.
GridDump LightPropagationVolumes::dumpGrid() const {
  if (levels_.empty()) throw Error("LPV: no light grid yet (no frame was rendered)");
  const LightGrid& first = levels_.front();
  const glm::ivec3 r = first.geometry.resolution;
  GridDump dump{.shape = {levels_.size(), std::size_t(LightGrid::kChannels), std::size_t(first.coefficients),
                          std::size_t(r.z), std::size_t(r.y), std::size_t(r.x)},
                .axes = {"level", "channel", "coefficient", "z", "y", "x"}};
  nlohmann::json levels = nlohmann::json::array();
  for (int level = 0; level < int(levels_.size()); ++level) {
    const std::vector<float> values = readGrid(true, level);
    dump.values.insert(dump.values.end(), values.begin(), values.end());
    const GridGeometry& g = levels_[std::size_t(level)].geometry;
    levels.push_back({{"origin_m", {g.origin.x, g.origin.y, g.origin.z}}, {"cell_size_m", g.cellSize}});
  }
  dump.description = {
      {"quantity", "the accumulated light grid (injection and every propagation step) after the last frame"},
      {"units", "radiant intensity, W/sr: RGB SH coefficients c_i = integral I(w) Y_i(w) dw of the light travelling in direction w"},
      {"basis", "real SH with the Condon-Shortley phase, index l (l + 1) + m, orthonormal (shaders/common/sh.glsl)"},
      {"sh_order", requirements_.shOrder},
      {"channels", {"r", "g", "b"}},
      {"cells", "cell (x, y, z) spans origin + [x, x+1) cell_size along x, and so on; levels finest first"},
      {"levels", levels}};
  return dump;
}

InjectionBalance LightPropagationVolumes::measureInjection() {
  const int coarsest = int(levels_.size()) - 1;
  Frame frame = this->frame(coarsest);
  const LightGrid& grid = levels_.back();
  clearGrids();
  strategies_.occlusion->inject(frame);
  InjectionBalance balance;
  const auto all = strategies_.all();
  for (std::size_t i = 0; i < strategies_.injection.size(); ++i) {
    strategies_.injection[i]->inject(frame);
    const double total =
        gridFlux(readGrid(false, coarsest), grid.geometry.cellCount(), grid.coefficients);
    balance.byInjection.emplace_back(all[i].first, total - balance.gridFlux);
    balance.gridFlux = total;
  }
  if (!consumed_.count(std::string(raster::kReflectiveShadowMaps.name)))
    return balance;  // no RSM was rendered: no strategy reads one
  // The last frame's RSMs on the host (read back, or made there by the ray-cast raster).
  const HostImage& flux = host_->image(lightMaps_->rsmFlux);
  for (std::size_t i = 0; i < std::size_t(lightMaps_->views) * lightMaps_->rsmResolution * lightMaps_->rsmResolution; ++i)
    balance.rsmFlux += flux.texels[i].r + flux.texels[i].g + flux.texels[i].b;
  return balance;
}

}  // namespace lpvlab

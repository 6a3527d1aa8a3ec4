#include "framework/explain/explain_frame.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <optional>

#include "framework/core/error.h"
#include "framework/core/progress.h"
#include "framework/explain/exact_grid.h"
#include "framework/explain/rsm_vpl_subset.h"
#include "framework/many_lights/host_gbuffer.h"
#include "framework/many_lights/vpl_gather.h"
#include "framework/metrics/block_error.h"
#include "framework/metrics/mask.h"
#include "framework/pipeline/pipeline.h"
#include "framework/pipeline/raster_inputs.h"
#include "framework/reference/embree_scene.h"

namespace lpvlab {

namespace {

// The work's parts, weighted by their (pair) counts for the progress bar's fraction.
class Work {
public:
  Work(double total) : total_(total), bar_("explain") {}
  // Runs `part` of `weight`, which reports its own fraction through the function it is given.
  template <class F>
  double run(const std::string& name, double weight, F&& part) {
    const auto start = std::chrono::steady_clock::now();
    part([&](double fraction) { bar_.update((done_ + weight * fraction) / total_, name); });
    done_ += weight;
    bar_.update(done_ / total_, name);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  void finish() { bar_.finish("oracles done"); }

private:
  double total_, done_ = 0.0;
  ProgressBar bar_;
};

// The VPLs gathered at every covered pixel of `g`, in bands of rows so the bar can move.
Image gatherImage(const HostGBuffer& g, const std::vector<Vpl>& vpls, const EmbreeScene* scene,
                  const std::function<void(double)>& progress) {
  const int width = g.position.width, height = g.position.height, band = 16;
  HostImage out{width, height, 1, std::vector<glm::vec4>(std::size_t(width) * height, glm::vec4(0.0f))};
  GatherSettings settings;
  settings.visibility = scene ? GatherVisibility::Rays : GatherVisibility::None;
  for (int y0 = 0; y0 < height; y0 += band) {
    const int rows = std::min(band, height - y0);
    const auto cut = [&](const HostImage& image) {
      const auto first = image.texels.begin() + std::ptrdiff_t(y0) * width;
      return HostImage{width, rows, 1, std::vector<glm::vec4>(first, first + std::ptrdiff_t(rows) * width)};
    };
    const HostImage position = cut(g.position), normal = cut(g.normal), albedo = cut(g.albedo);
    HostImage part = cut(out);
    gatherVpls(position, normal, albedo, vpls, settings, {.scene = scene}, part);
    std::copy(part.texels.begin(), part.texels.end(), out.texels.begin() + std::ptrdiff_t(y0) * width);
    progress(double(y0 + rows) / height);
  }
  return toImage(out, 3);
}

Image average(const Image& a, const Image& b) {
  Image out = a;
  for (std::size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = 0.5f * (a.pixels[i] + b.pixels[i]);
  return out;
}

// The noise of the mean of two independent draws: half their difference's block RMSE, over the
// mean of their mean (block nRMSE's normalisation). Zero for identical draws.
double noiseOfMean(const Image& a, const Image& b, const Image& mean, const Image& mask) {
  const double meanOfMean = imageMean(mean);
  if (!(meanOfMean > 0.0)) return 0.0;
  const double bNrmse = blockNrmse(a, b, checkInputs("noiseOfMean", a, b, &mask));  // over b's mean
  return 0.5 * bNrmse * imageMean(b) / meanOfMean;
}

// The pixels the camera sees (the G-buffer's position.w), top row first as the outputs are.
Image coveredPixels(const HostGBuffer& g) {
  Image mask = toImage(g.position, 1, 3);
  for (float& m : mask.pixels) m = m > 0.0f ? 1.0f : 0.0f;
  return mask;
}

// Cells of every level of the method's light grid (its dump's spatial and level axes).
double gridCells(const IndirectMethod& method) {
  const GridDump dump = method.dumpGrid();
  double cells = 1.0;
  for (std::size_t axis = 0; axis < dump.axes.size(); ++axis) {
    const std::string& name = dump.axes[axis];
    if (name == "level" || name == "x" || name == "y" || name == "z") cells *= double(dump.shape[axis]);
  }
  return cells;
}

// Each oracle from each draw: [visible][draw] gathers and grids, timed into `seconds`, and the
// exact grids' values (every level's, in order) behind the grid images.
struct OracleRenders {
  Image gathers[2][2], grids[2][2];
  std::vector<float> gridValues[2][2];
};

// A grid's values as a 1-row image, for the checkpoint, and back.
Image valuesImage(const std::vector<float>& values) {
  Image image(int(values.size()), 1, 1);
  image.pixels = values;
  return image;
}

// The checkpoint's name of the exact grids behind the grid image `name`. They are saved before
// the image, so a checkpointed image always has them.
std::string cellsName(const std::string& name) { return name + "_cells"; }

std::vector<float> savedValues(const ExplainCheckpoint& checkpoint, const std::string& name) {
  if (checkpoint.load)
    if (std::optional<Image> saved = checkpoint.load(cellsName(name))) return saved->pixels;
  return {};
}

// `render`'s image, or the checkpoint's copy of it from an interrupted explanation (saved there
// once rendered).
Image checkpointed(const ExplainCheckpoint& checkpoint, const std::string& name,
                   const std::function<Image()>& render) {
  if (checkpoint.load)
    if (std::optional<Image> saved = checkpoint.load(name)) return *saved;
  Image image = render();
  if (checkpoint.save) checkpoint.save(name, image);
  return image;
}

OracleRenders renderOracles(IndirectMethod& method, const HostGBuffer& g, const EmbreeScene& scene,
                            const RsmVplSubset (&draws)[2], int drawCount, double pixels,
                            double cells, const ExplainCheckpoint& checkpoint, nlohmann::json& seconds) {
  // The work in pairs (pixel-VPL, cell-VPL), a shadow ray counted as 4 pairs without one.
  const double n = double(draws[0].vpls.size()) * drawCount;
  Work work(5.0 * n * (pixels + cells));
  OracleRenders out;
  for (int visible = 0; visible < 2; ++visible) {
    const EmbreeScene* rays = visible ? &scene : nullptr;
    const double cost = visible ? 4.0 : 1.0;
    const std::string suffix = visible ? "_visible" : "";
    seconds["gather" + suffix] = work.run("gather" + suffix, cost * n * pixels, [&](auto progress) {
      for (int d = 0; d < drawCount; ++d)
        out.gathers[visible][d] = checkpointed(checkpoint, "gather" + suffix + "_" + std::to_string(d), [&] {
          return gatherImage(g, draws[d].vpls, rays, [&](double f) { progress((d + f) / drawCount); });
        });
    });
    seconds["grid" + suffix] = work.run("grid" + suffix, cost * n * cells, [&](auto progress) {
      for (int d = 0; d < drawCount; ++d) {
        const std::string name = "grid" + suffix + "_" + std::to_string(d);
        std::vector<float> computed;
        out.grids[visible][d] = checkpointed(checkpoint, name, [&] {
          Image image = method.renderFromGrids([&](const GridGeometry& grid, int coefficients) {
            std::vector<float> level = exactLightGrid(draws[d].vpls, grid, coefficients, rays,
                                                      [&](double f) { progress((d + f) / drawCount); });
            computed.insert(computed.end(), level.begin(), level.end());
            return level;
          });
          if (checkpoint.save) checkpoint.save(cellsName(name), valuesImage(computed));
          return image;
        });
        out.gridValues[visible][d] = computed.empty() ? savedValues(checkpoint, name) : std::move(computed);
      }
    });
    if (drawCount == 1) {  // every texel was a VPL: both draws are the one
      out.gathers[visible][1] = out.gathers[visible][0];
      out.grids[visible][1] = out.grids[visible][0];
      out.gridValues[visible][1] = out.gridValues[visible][0];
    }
  }
  work.finish();
  return out;
}

// The mean of the two draws' exact grids in the layout of the method's dump (`like`); no values
// when a draw's are missing (a checkpoint from before they were kept).
GridDump meanGrid(const GridDump& like, const std::vector<float> (&draws)[2]) {
  GridDump mean{like.shape, like.axes, {}, like.description};
  mean.description["quantity"] =
      "the exact light grid (docs/explain.md#the-oracles) from the RSM's VPLs, the mean of two draws";
  if (draws[0].size() != like.values.size() || draws[1].size() != like.values.size()) return mean;
  mean.values.resize(like.values.size());
  for (std::size_t i = 0; i < mean.values.size(); ++i) mean.values[i] = 0.5f * (draws[0][i] + draws[1][i]);
  return mean;
}

}  // namespace

ExplainedFrame explainFrame(Pipeline& pipeline, const EmbreeScene& scene,
                            const ExplainSettings& settings) {
  IndirectMethod& method = pipeline.method();
  if (const std::string why = method.explainRefusal(); !why.empty()) throw Error("explain: " + why);
  if (!pipeline.renders(raster::kReflectiveShadowMaps.name))
    throw Error("explain: the frame rendered no RSM, whose VPLs the oracles gather");
  const LightMaps& maps = pipeline.lightMaps();
  HostReadback& host = pipeline.host();
  const RsmImages rsm{&host.image(maps.rsmPosition), &host.image(maps.rsmNormal), &host.image(maps.rsmFlux)};
  const HostGBuffer g = hostGBuffer(host, pipeline.gbuffer());
  ExplainedFrame out;
  out.mask = coveredPixels(g);
  const Image& mask = out.mask;
  const RsmVplSubset draws[2] = {
      rsmVplSubset(rsm, maps.views, maps.rsmResolution, settings.vplsPerDraw, settings.seed, 0),
      rsmVplSubset(rsm, maps.views, maps.rsmResolution, settings.vplsPerDraw, settings.seed, 1)};
  const int drawCount = draws[0].blockSide > 1 ? 2 : 1;  // else both draws are every texel

  // The method's own image and grid, before the oracles' renders replace them.
  out.images.method = findAov(pipeline.readOutputs(), "indirect");
  out.methodGrid = method.dumpGrid();
  const double cells = gridCells(method);
  out.gridBlocksLight = method.gridBlocksLight();
  out.vpls = {{"covered_rsm_texels", draws[0].coveredTexels},
              {"per_draw", draws[0].vpls.size()},
              {"draws", drawCount},
              {"block_side_texels", draws[0].blockSide}};
  double pixels = 0.0;
  for (float m : mask.pixels) pixels += m;
  const OracleRenders renders =
      renderOracles(method, g, scene, draws, drawCount, pixels, cells, settings.checkpoint, out.seconds);

  ExplainImages& images = out.images;
  const auto set = [&](Image& target, const std::string& name, const Image(&pair)[2]) {
    target = average(pair[0], pair[1]);
    images.noise[name] = noiseOfMean(pair[0], pair[1], target, mask);
  };
  set(images.gather, "gather", renders.gathers[0]);
  set(images.gatherVisible, "gather_visible", renders.gathers[1]);
  set(images.grid, "grid", renders.grids[0]);
  set(images.gridVisible, "grid_visible", renders.grids[1]);
  out.exactGrid = meanGrid(out.methodGrid, renders.gridValues[out.gridBlocksLight ? 1 : 0]);
  return out;
}

}  // namespace lpvlab

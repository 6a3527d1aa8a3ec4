// [indirect] method = "rsm_gather": reflective shadow maps as VPL sources, gathered per pixel
// without visibility (Dachsbacher and Stamminger 2005; seed 001, 3.1). Every covered RSM texel is
// a VPL (vpl.h: its flux is what the RSM stores, the flux its surface patch reflects). Gathering
// every texel for every pixel is too slow at useful RSM sizes (3.1.1), so by default each pixel
// takes a fixed pattern of samples around its own projection into each light view in front of
// which it lies (clamped to the map where it falls outside the view), the texels near it being
// the ones that light it most. Parameters:
//   pattern  "importance": sample offsets at radius R xi1 and angle 2 pi xi2, denser near the
//            projection, each weighted by 2 pi R^2 xi1 / samples (1 / (samples * density)): an
//            unbiased estimate of the sum over the texels within R;
//            "uniform": offsets uniform in the disk, each weighted by pi R^2 / samples;
//            "all": every covered texel of every view, unweighted (no subsampling: the one-
//            bounce instant radiosity of the RSM's texels without visibility)
//   samples  offsets per pixel and light view (importance, uniform)
//   radius   R as a fraction of the RSM's side
//   seed     of the offsets (one pattern for every pixel, as in the paper)
// Texels beyond R of the (clamped) projection are left out by the patterns, and so are views the
// pixel lies behind: their bias, which "all" does not have.
// Runs on the CPU; its one stage is "indirect" (the RSM and G-buffer read-back included).

#include <cmath>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "framework/core/parameters.h"
#include "framework/many_lights/host_gbuffer.h"
#include "framework/many_lights/vpl_gather.h"
#include "framework/pipeline/indirect_method.h"
#include "framework/pipeline/pipeline.h"
#include "framework/pipeline/raster_inputs.h"
#include "framework/reference/random.h"

namespace lpvlab {

namespace {

struct Offset {
  glm::vec2 texels;  // from the projection, in texels
  float weight;
};

class RsmGather : public IndirectMethod {
public:
  explicit RsmGather(Params& p) {
    pattern_ = p.getChoice("pattern", "importance", {"importance", "uniform", "all"});
    samples_ = p.get<int>("samples", 400, {.min = 1, .max = 1 << 20});
    radius_ = p.get<float>("radius", 1.0f, {.min = 1e-6f, .max = 2.0f});
    seed_ = std::uint64_t(p.get<int>("seed", 1, {.min = 0}));
  }

  std::vector<std::string> stageNames() const override { return {"indirect"}; }
  std::set<std::string> consumes() const override {
    return {std::string(raster::kReflectiveShadowMaps.name)};
  }

  void prepare(const MethodSetup& setup) override {
    if (pattern_ == "all") return;
    const float r = radius_ * float(setup.settings.rsmResolution);
    SampleRandom random(seed_, 0, 0);
    for (int i = 0; i < samples_; ++i) {
      const float u1 = random.uniform(), u2 = random.uniform();
      const float angle = 2.0f * float(M_PI) * u2;
      const glm::vec2 unit(std::sin(angle), std::cos(angle));
      if (pattern_ == "importance")
        offsets_.push_back({r * u1 * unit, 2.0f * float(M_PI) * r * r * u1 / float(samples_)});
      else
        offsets_.push_back({r * std::sqrt(u1) * unit, float(M_PI) * r * r / float(samples_)});
    }
  }

  void moveScene(const Scene&, bool, bool) override {}  // the RSMs follow the lights

  void render(MethodFrame& frame) override {
    frame.stage("indirect", [&] {
      const HostGBuffer g = hostGBuffer(frame.host, frame.gbuffer);
      const LightMaps& maps = frame.lightMaps;
      const HostImage& position = frame.host.image(maps.rsmPosition);
      const HostImage& normal = frame.host.image(maps.rsmNormal);
      const HostImage& flux = frame.host.image(maps.rsmFlux);
      if (pattern_ == "all") {
        vpls_.clear();
        for (std::size_t i = 0; i < position.texels.size(); ++i)
          if (position.texels[i].w > 0.0f)
            vpls_.push_back(Vpl{glm::vec3(position.texels[i]), glm::vec3(normal.texels[i]),
                                glm::vec3(flux.texels[i]), 1});
        GatherSettings settings;
        settings.visibility = GatherVisibility::None;
        gatherVpls(g.position, g.normal, g.albedo, vpls_, settings, {}, frame.indirect.host(),
                   &counts_);
        return;
      }
      gatherPattern(g, maps, position, normal, flux, frame.indirect.host());
    });
  }

  std::map<std::string, std::vector<WorkCount>> work() const override {
    return {{"indirect", {{"pixel-texel pair", counts_.pairs, 30.0, 48.0}}}};
  }

  std::size_t memoryBytes() const override {
    return vpls_.capacity() * sizeof(Vpl) + offsets_.capacity() * sizeof(Offset);
  }

  nlohmann::json statistics() const override {
    nlohmann::json out = {{"pattern", pattern_}, {"gathered_pairs", counts_.pairs}};
    if (pattern_ == "all")
      out["vpls"] = vpls_.size();  // every covered texel
    else
      out["samples_per_pixel_and_view"] = samples_;
    return out;
  }

private:
  // Each pixel's pattern around its projection into each light view.
  void gatherPattern(const HostGBuffer& g, const LightMaps& maps, const HostImage& position,
                     const HostImage& normal, const HostImage& flux, HostImage& indirect) {
    const int width = g.position.width, height = g.position.height, side = position.width;
    const std::vector<GpuView>& views = maps.records.views;
    std::vector<double> pairs(static_cast<std::size_t>(height), 0.0);
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
      for (int y = rows.begin(); y != rows.end(); ++y)
        for (int x = 0; x < width; ++x) {
          const std::size_t i = std::size_t(y) * width + x;
          if (!(g.position.texels[i].w > 0.0f)) continue;
          const glm::vec3 p(g.position.texels[i]), n(g.normal.texels[i]), rho(g.albedo.texels[i]);
          glm::dvec3 sum(0.0), unused(0.0);
          for (std::size_t view = 0; view < views.size(); ++view) {
            const glm::vec4 clip = views[view].clipFromWorld * glm::vec4(p, 1.0f);
            if (!(clip.w > 0.0f)) continue;
            // Outside the view, the nearest point of its map (a wall seen from the side face
            // of a point light's cube is lit most by the floor texels along that face's edge).
            const glm::vec2 ndc = glm::clamp(glm::vec2(clip) / clip.w, -1.0f, 1.0f);
            const glm::vec2 centre = (ndc * 0.5f + 0.5f) * float(side);
            for (const Offset& offset : offsets_) {
              const glm::ivec2 t = glm::ivec2(glm::floor(centre + offset.texels));
              if (t.x < 0 || t.y < 0 || t.x >= side || t.y >= side) continue;
              const std::size_t texel = std::size_t(t.x) + std::size_t(side) * (std::size_t(t.y) + std::size_t(side) * view);
              if (!(position.texels[texel].w > 0.0f)) continue;
              const Vpl vpl{glm::vec3(position.texels[texel]), glm::vec3(normal.texels[texel]),
                            offset.weight * glm::vec3(flux.texels[texel]), 1};
              glm::vec3 toVpl;
              float distance = 0.0f;
              const glm::vec3 gfr = vplGeometryTerm(p, n, rho, vpl, 1e-4f, toVpl, distance);
              if (!(gfr.r > 0.0f || gfr.g > 0.0f || gfr.b > 0.0f)) continue;
              pairs[std::size_t(y)] += 1.0;
              addClamped(vpl.flux, gfr, 0.0f, sum, unused);
            }
          }
          indirect.texels[i] += glm::vec4(glm::vec3(sum), 0.0f);
        }
    });
    counts_ = {};
    for (double rowPairs : pairs) counts_.pairs += rowPairs;
  }

  std::string pattern_;
  int samples_ = 400;
  float radius_ = 1.0f;
  std::uint64_t seed_ = 1;
  std::vector<Offset> offsets_;
  std::vector<Vpl> vpls_;
  GatherCounts counts_;
};

}  // namespace

LPVLAB_REGISTER(IndirectMethod, "rsm_gather",
                "reflective shadow maps' texels as VPLs, gathered per pixel without visibility "
                "from an importance-sampled pattern around its projection, or from every texel "
                "(Dachsbacher and Stamminger 2005; seed 001, 3.1)",
                RsmGather);

}  // namespace lpvlab

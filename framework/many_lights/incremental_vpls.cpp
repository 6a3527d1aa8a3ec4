#include "framework/many_lights/incremental_vpls.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <map>

#include "framework/core/error.h"
#include "framework/many_lights/light_paths.h"
#include "framework/reference/embree_scene.h"

namespace lpvlab {

namespace {

double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

bool sameChart(const LightChart& a, const LightChart& b) {
  return a.origin == b.origin && a.axis == b.axis && a.scale == b.scale && a.radiant == b.radiant &&
         a.cosInner == b.cosInner && a.cosOuter == b.cosOuter;
}

// Whether nothing blocks the way from surface point p (normal n) towards the chart's light.
bool seesLight(const EmbreeScene& embree, const LightChart& chart, const glm::vec3& p,
               const glm::vec3& n) {
  float distance = 0.0f;
  const glm::vec3 towards = chart.towardsLight(p, distance);
  const glm::vec3 start = p + embree.epsilon() * n;
  ShadowPacket packet;
  const float end = std::isfinite(distance) ? std::max(0.0f, distance - 2.0f * embree.epsilon())
                                            : std::numeric_limits<float>::infinity();
  packet.set(0, start, towards, 0.0f, end);
  embree.occluded(packet);
  return !packet.occluded(0);
}

}  // namespace

bool IncrementalVpls::stillValid(const RayScene& scene, const LightChart& chart, Kept& vpl,
                                 bool reproject) const {
  const EmbreeScene& embree = scene.embree();
  if (!vpl.onSurface) {
    // Light lost to the sky stays lost while its ray still meets nothing.
    glm::vec3 start, direction;
    chart.ray(vpl.uv, start, direction);
    RayPacket packet;
    packet.set(0, start, direction, 0.0f, std::numeric_limits<float>::infinity());
    embree.intersect(packet, false);
    return !packet.hit(0);
  }
  glm::vec2 uv;
  if (!chart.project(vpl.position, uv)) return false;
  float distance = 0.0f;
  if (!(glm::dot(vpl.normal, chart.towardsLight(vpl.position, distance)) > 0.0f)) return false;
  if (!seesLight(embree, chart, vpl.position, vpl.normal)) return false;
  if (reproject) vpl.uv = uv;
  return true;
}

bool IncrementalVpls::valid(const RayScene& scene, const Vpl& vpl) const {
  for (const LightChart& chart : lightCharts(scene.lights(), scene.bounds(), settings_.placement)) {
    Kept k{0, glm::vec2(0.0f), true, vpl.position, vpl.normal, glm::vec3(1.0f)};
    if (stillValid(scene, chart, k, true)) return true;
  }
  return false;
}

IncrementalVpls::Kept IncrementalVpls::place(const RayScene& scene, const LightChart& chart,
                                             const glm::vec2& uv) {
  glm::vec3 start, direction;
  chart.ray(uv, start, direction);
  RayPacket packet;
  packet.set(0, start, direction, 0.0f, std::numeric_limits<float>::infinity());
  scene.embree().intersect(packet, false);
  Kept k{nextId_++, uv, false, glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
  if (!packet.hit(0)) return k;
  const SurfacePoint x = surfaceAt(scene.embree(), packet.hitAt(0), start, direction);
  k.onSurface = true;
  k.position = x.position;
  k.normal = x.shadingNormal;  // towards the light: surfaceAt turns it to the ray's side
  k.albedo = surfaceAlbedo(x);
  return k;
}

namespace {

// Each chart's share of the target count, by its light's power (a point light's two charts halve
// it); at least one VPL each.
std::vector<int> chartShares(const RayScene& scene, const std::vector<LightChart>& charts, int target) {
  const float radius = charts.empty() ? 1.0f : 0.5f * glm::length(scene.bounds().extent()) * 1.01f + 1e-6f;
  std::vector<double> power;
  double total = 0.0;
  for (const LightChart& chart : charts) {
    const PunctualLight& light = scene.lights()[std::size_t(chart.light)];
    const double halves = light.type == LightType::Point ? 2.0 : 1.0;
    power.push_back(luminance(lightPower(light, radius)) / halves);
    total += power.back();
  }
  std::vector<int> shares;
  for (std::size_t c = 0; c < charts.size(); ++c)
    shares.push_back(std::max(1, int(std::lround(target * (total > 0.0 ? power[c] / total : 1.0 / charts.size())))));
  return shares;
}

// Step 4: the disk's power over each kept point's Voronoi cell (by `triangulation`, which holds
// exactly the kept points), integrated on a grid of `g` x `g` cells over the disk.
template <typename KeptList>
std::vector<glm::dvec3> voronoiFlux(const DiskTriangulation& triangulation, const KeptList& kept,
                                    const LightChart& chart, int g) {
  std::map<int, std::size_t> index;
  for (std::size_t i = 0; i < kept.size(); ++i) index[kept[i].id] = i;
  std::vector<glm::dvec3> flux(kept.size(), glm::dvec3(0.0));
  const double cell = 2.0 / g, area = cell * cell;
  for (int y = 0; y < g && !kept.empty(); ++y)
    for (int x = 0; x < g; ++x) {
      const glm::dvec2 uv(-1.0 + (x + 0.5) * cell, -1.0 + (y + 0.5) * cell);
      if (glm::dot(uv, uv) > 1.0) continue;
      flux[index[triangulation.nearest(uv)]] += glm::dvec3(chart.powerDensity(glm::vec2(uv))) * area;
    }
  return flux;
}

}  // namespace

void IncrementalVpls::updateChart(const RayScene& scene, ChartState& state, bool moved, int share,
                                  IncrementalCounts& counts) {
  const LightChart& chart = state.chart;
  // 1. Validity.
  const std::size_t before = state.kept.size();
  std::erase_if(state.kept, [&](Kept& k) { return !stillValid(scene, chart, k, moved); });
  counts.removedInvalid += int(before - state.kept.size());

  // 2. Removal where the set is densest.
  DiskTriangulation triangulation;
  std::vector<Kept> unique;
  for (const Kept& k : state.kept) {
    try {
      triangulation.insert(glm::dvec2(k.uv), k.id);
      unique.push_back(k);
    } catch (const Error&) {
      ++counts.removedInvalid;  // two VPLs moved onto one point of the disk: one goes
    }
  }
  state.kept = std::move(unique);
  for (int removed = 0; removed < settings_.maxRemovals && triangulation.size() > 1; ++removed) {
    const auto [id, edge] = triangulation.densest();
    if (int(triangulation.size()) <= share && !(edge < 0.5 * triangulation.largestEmptyCircle().second)) break;
    triangulation.remove(id);
    const int removedId = id;  // a structured binding is not captured by lambdas before C++23 in clang 14
    std::erase_if(state.kept, [removedId](const Kept& k) { return k.id == removedId; });
    ++counts.removedDense;
  }

  // 3. Insertion where coverage is poorest.
  const int limit = first_ ? INT_MAX : settings_.maxInsertions;
  for (int inserted = 0; int(triangulation.size()) < share && inserted < limit; ++inserted) {
    // Kept in float, as every later frame's triangulation has it.
    const glm::vec2 centre(triangulation.largestEmptyCircle().first);
    const Kept k = place(scene, chart, centre);
    triangulation.insert(glm::dvec2(centre), k.id);
    state.kept.push_back(k);
    ++counts.inserted;
  }
  const double empty = triangulation.largestEmptyCircle().second;
  if (triangulation.size() > 0)
    counts.coverage = std::max(counts.coverage, empty / std::sqrt(1.0 / double(triangulation.size())));

  // 4. Flux: the disk's power over each VPL's Voronoi cell.
  const std::vector<glm::dvec3> flux = voronoiFlux(triangulation, state.kept, chart, settings_.fluxGrid);
  for (std::size_t i = 0; i < state.kept.size(); ++i) {
    const Kept& k = state.kept[i];
    counts.kept += 1;
    if (!k.onSurface) {
      ++counts.placeholders;
      continue;
    }
    vpls_.push_back(Vpl{k.position, k.normal, glm::vec3(flux[i]) * k.albedo, 1});
  }
}

const std::vector<Vpl>& IncrementalVpls::update(const RayScene& scene, IncrementalCounts& counts) {
  counts = {};
  const std::vector<LightChart> charts = lightCharts(scene.lights(), scene.bounds(), settings_.placement);
  if (charts.size() != charts_.size()) {  // a new run (or lights that changed kind): start over
    charts_.clear();
    for (const LightChart& chart : charts) charts_.push_back({chart, {}});
    first_ = true;
  }
  // A chart whose light has not moved keeps its VPLs' disk points as they were placed: projecting
  // them again would move them by float rounding, and the Voronoi cells' power with them.
  std::vector<bool> moved(charts.size(), true);
  for (std::size_t c = 0; c < charts.size(); ++c) {
    moved[c] = first_ || !sameChart(charts_[c].chart, charts[c]);
    charts_[c].chart = charts[c];
  }
  const std::vector<int> shares = chartShares(scene, charts, settings_.vpls);
  vpls_.clear();
  counts.coverage = 0.0;
  for (std::size_t c = 0; c < charts_.size(); ++c) updateChart(scene, charts_[c], moved[c], shares[c], counts);
  first_ = false;
  return vpls_;
}

}  // namespace lpvlab

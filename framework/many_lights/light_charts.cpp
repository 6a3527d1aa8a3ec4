#include "framework/many_lights/light_charts.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/math/shared.h"

namespace lpvlab {

namespace {

// |uv|^2 up to which a point is inside: a VPL placed on the rim (where incremental instant
// radiosity often inserts) comes back from its surface point a float rounding outside it.
constexpr float kRim = 1.0f + 1e-4f;

// Entries of a power chart's share table: with 16 trapezoids between entries, the share is exact
// to about 1e-7 for a spot's smooth falloff (and exactly linear for a point light).
constexpr int kShareEntries = 1025, kSubsteps = 16;

// The cosine of the chart's power share s (|uv|^2): the inverse of shareAt, by bisection over the
// decreasing table and linear interpolation between its entries.
double cosForShare(const LightChart& chart, double s) {
  const std::vector<double>& share = chart.share;
  const int n = int(share.size());
  s = std::clamp(s, 0.0, 1.0);
  int lo = 0, hi = n - 1;  // share[lo] >= s >= share[hi]
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    (share[mid] >= s ? lo : hi) = mid;
  }
  const double span = share[lo] - share[hi];
  const double t = span > 0.0 ? (share[lo] - s) / span : 0.0;
  return chart.cosRim + (1.0 - chart.cosRim) * (lo + t) / (n - 1);
}

// The power share within the cone of cosine z (linear between the table's entries, extended
// linearly beyond the rim so that a point just outside comes back just above 1).
double shareAt(const LightChart& chart, double z) {
  const int n = int(chart.share.size());
  const double t = (z - chart.cosRim) / (1.0 - chart.cosRim) * (n - 1);
  const int k = std::clamp(int(std::floor(t)), 0, n - 2);
  return chart.share[k] + (chart.share[k + 1] - chart.share[k]) * (t - k);
}

// Fills a point or spot chart's share table from its falloff (1 for a point light).
void makeEqualPower(LightChart& chart) {
  chart.equalPower = true;
  chart.cosRim = chart.spot ? chart.cosOuter : 0.0;
  const auto falloff = [&](double mu) {
    return chart.spot ? shared::spotFalloff(mu, chart.cosInner, chart.cosOuter) : 1.0;
  };
  const double step = (1.0 - chart.cosRim) / (kShareEntries - 1);
  std::vector<double> within(kShareEntries, 0.0);  // integral of the falloff from mu_k to 1
  for (int k = kShareEntries - 2; k >= 0; --k) {
    const double mu0 = chart.cosRim + step * k, h = step / kSubsteps;
    double part = 0.0;
    for (int j = 0; j < kSubsteps; ++j) part += 0.5 * h * (falloff(mu0 + j * h) + falloff(mu0 + (j + 1) * h));
    within[std::size_t(k)] = within[std::size_t(k) + 1] + part;
  }
  chart.share.resize(kShareEntries);
  for (int k = 0; k < kShareEntries; ++k)
    chart.share[std::size_t(k)] = within[0] > 0.0 ? within[std::size_t(k)] / within[0] : 1.0 - double(k) / (kShareEntries - 1);
  chart.densityOverRadiant = 2.0 * within[0];  // the chart's power 2 pi I integral, over pi
}

void basis(LightChart& chart) {
  const glm::vec3 a = chart.axis;
  const glm::vec3 helper = std::abs(a.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  chart.tangent = glm::normalize(glm::cross(a, helper));
  chart.bitangent = glm::cross(a, chart.tangent);
}

}  // namespace

void LightChart::ray(const glm::vec2& uv, glm::vec3& start, glm::vec3& direction) const {
  if (orthographic) {
    start = origin + scale * (uv.x * tangent + uv.y * bitangent);
    direction = axis;
    return;
  }
  start = origin;
  if (equalPower) {
    const float length = glm::length(uv);
    const double z = cosForShare(*this, double(length) * length);
    const float sine = float(std::sqrt(std::max(0.0, 1.0 - z * z)));
    const glm::vec2 around = length > 0.0f ? uv / length : glm::vec2(0.0f);
    direction = glm::normalize(sine * (around.x * tangent + around.y * bitangent) + float(z) * axis);
    return;
  }
  const glm::vec2 raw = uv * scale;
  const float r2 = glm::dot(raw, raw);
  direction = glm::normalize((2.0f * raw.x * tangent + 2.0f * raw.y * bitangent + (1.0f - r2) * axis) /
                             (1.0f + r2));
}

bool LightChart::project(const glm::vec3& p, glm::vec2& uv) const {
  if (orthographic) {
    const glm::vec3 q = p - origin;
    uv = glm::vec2(glm::dot(q, tangent), glm::dot(q, bitangent)) / scale;
    return glm::dot(q, axis) > 0.0f && glm::dot(uv, uv) <= kRim;
  }
  const glm::vec3 d = p - origin;
  const float length = glm::length(d);
  if (!(length > 0.0f)) return false;
  const glm::vec3 u = d / length;
  const float z = glm::dot(u, axis);
  if (!(z > 0.0f)) return false;
  if (equalPower) {
    const double s = shareAt(*this, double(z));
    const glm::vec2 across(glm::dot(u, tangent), glm::dot(u, bitangent));
    const float length = glm::length(across);
    uv = length > 0.0f ? across * float(std::sqrt(std::max(s, 0.0)) / length) : glm::vec2(0.0f);
    return s <= double(kRim);
  }
  uv = glm::vec2(glm::dot(u, tangent), glm::dot(u, bitangent)) / ((1.0f + z) * scale);
  return glm::dot(uv, uv) <= kRim;
}

glm::vec3 LightChart::towardsLight(const glm::vec3& p, float& distance) const {
  if (orthographic) {
    distance = std::numeric_limits<float>::infinity();
    return -axis;
  }
  const glm::vec3 d = origin - p;
  distance = glm::length(d);
  return d / distance;
}

glm::vec3 LightChart::powerDensity(const glm::vec2& uv) const {
  if (orthographic) return radiant * (scale * scale);
  if (equalPower) return radiant * float(densityOverRadiant);
  const glm::vec2 raw = uv * scale;
  const float r2 = glm::dot(raw, raw);
  float falloff = 1.0f;
  if (spot) {
    const float cosTheta = (1.0f - r2) / (1.0f + r2);
    falloff = float(shared::spotFalloff(double(cosTheta), cosInner, cosOuter));
  }
  return radiant * (falloff * 4.0f / ((1.0f + r2) * (1.0f + r2)) * scale * scale);
}

std::vector<LightChart> lightCharts(const std::vector<PunctualLight>& lights, const Bounds& scene,
                                    ChartPlacement placement) {
  const bool power = placement == ChartPlacement::Power;
  std::vector<LightChart> charts;
  const float radius = 0.5f * glm::length(scene.extent()) * 1.01f + 1e-6f;
  for (int i = 0; i < int(lights.size()); ++i) {
    const PunctualLight& light = lights[std::size_t(i)];
    LightChart chart;
    chart.light = i;
    chart.radiant = light.radiant;
    switch (light.type) {
      case LightType::Point:
        chart.origin = light.position;
        for (const glm::vec3 axis : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0)}) {
          chart.axis = axis;
          basis(chart);
          if (power) makeEqualPower(chart);
          charts.push_back(chart);
        }
        break;
      case LightType::Spot:
        chart.origin = light.position;
        chart.axis = light.direction;
        chart.spot = true;
        chart.cosInner = light.cosInner;
        chart.cosOuter = light.cosOuter;
        chart.scale = float(std::tan(0.5 * std::acos(std::clamp(light.cosOuter, -1.0, 1.0))));
        basis(chart);
        if (power) makeEqualPower(chart);
        charts.push_back(chart);
        break;
      case LightType::Directional:
        chart.orthographic = true;
        chart.axis = light.direction;
        chart.scale = radius;
        chart.origin = scene.center() - 2.0f * radius * light.direction;
        basis(chart);
        charts.push_back(chart);
        break;
    }
  }
  return charts;
}

}  // namespace lpvlab

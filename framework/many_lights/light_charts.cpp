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
  const glm::vec2 raw = uv * scale;
  const float r2 = glm::dot(raw, raw);
  start = origin;
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
  const glm::vec2 raw = uv * scale;
  const float r2 = glm::dot(raw, raw);
  float falloff = 1.0f;
  if (spot) {
    const float cosTheta = (1.0f - r2) / (1.0f + r2);
    falloff = float(shared::spotFalloff(double(cosTheta), cosInner, cosOuter));
  }
  return radiant * (falloff * 4.0f / ((1.0f + r2) * (1.0f + r2)) * scale * scale);
}

std::vector<LightChart> lightCharts(const std::vector<PunctualLight>& lights, const Bounds& scene) {
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

#pragma once
// A light's emission drawn on the unit disk, the 2D domain in which incremental instant
// radiosity keeps its VPLs evenly spread ("distances are measured not in the scene but in the
// light's projection", seed 001, 3.2.2). A chart maps a disk point to the ray the light sends
// there, a surface point back to its disk point, and gives the light's power per unit disk area:
//   spot         a paraboloid about the spot's axis, scaled so the outer cone is the rim:
//                raw = (x, y) / (1 + z) of the local direction, uv = raw / tan(outer / 2);
//                power density I falloff(theta) 4 / (1 + |raw|^2)^2 tan(outer / 2)^2
//   point        two such charts, the hemispheres below and above the light (rim at 90 degrees)
//   directional  an orthographic disk across the light covering the scene's bounding sphere
//                (radius R), rays parallel from behind the scene; power density E R^2
// (4 / (1 + |raw|^2)^2 is the paraboloid's solid angle per unit area of raw.)
// These are the "projection" charts of seed 001, 3.2.2: a VPL set spread evenly on them carries
// more power per VPL where the paraboloid is densest (4x at a hemisphere's pole than at its rim)
// and where a spot is brightest. The "power" charts (ChartPlacement::Power) keep the same
// directions but move them radially, so that the disk's area is proportional to the power the
// light sends through it: |uv|^2 is the share of the chart's power within angle theta of the axis,
//   share(theta) = integral_{cos theta}^1 falloff / integral_{cos rim}^1 falloff   (falloff 1: point)
// and the power density is constant, 2 I integral_{cos rim}^1 falloff. A set spread evenly on it
// gives every VPL the same share of the light (Laine et al. 2007 place VPLs by power this way).
// Directional lights are uniform either way.

#include <vector>

#include <glm/glm.hpp>

#include "framework/math/bounds.h"
#include "framework/reference/light_sampler.h"

namespace lpvlab {

enum class ChartPlacement { Projection, Power };

struct LightChart {
  int light = 0;              // index into the scene's lights
  bool orthographic = false;  // directional light
  glm::vec3 origin{0.0f};     // the light's position; a directional light's disk centre
  glm::vec3 axis{0, -1, 0}, tangent{1, 0, 0}, bitangent{0, 0, 1};
  float scale = 1.0f;         // tan(rim angle / 2); the disk's radius in metres (orthographic)
  glm::vec3 radiant{0.0f};    // W/sr (point, spot) or W/m^2 (directional)
  bool spot = false;
  double cosInner = -1.0, cosOuter = -1.0;
  // Power charts: the share of the chart's power within the cone of cos(theta) = cosRim + (1 -
  // cosRim) k / (n - 1), k = 0..n - 1 (from 1 at the rim to 0 on the axis), and the constant
  // power density over radiant.
  bool equalPower = false;
  double cosRim = 0.0;
  std::vector<double> share;
  double densityOverRadiant = 0.0;

  // The ray of disk point uv (|uv| <= 1): its origin and unit direction.
  void ray(const glm::vec2& uv, glm::vec3& start, glm::vec3& direction) const;
  // The disk point of world point p; false where p lies outside the chart (beyond the rim by
  // more than float rounding).
  bool project(const glm::vec3& p, glm::vec2& uv) const;
  // The unit direction from p towards the light, and how far the light is (inf: directional).
  glm::vec3 towardsLight(const glm::vec3& p, float& distance) const;
  // The light's power per unit disk area at uv, W per channel.
  glm::vec3 powerDensity(const glm::vec2& uv) const;
};

// Every light's charts, in light order.
std::vector<LightChart> lightCharts(const std::vector<PunctualLight>& lights, const Bounds& scene,
                                    ChartPlacement placement = ChartPlacement::Projection);

}  // namespace lpvlab

#include "framework/metrics/flip.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "framework/core/error.h"
#include "framework/metrics/flip_color.h"

namespace lpvlab {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Colour difference: exponent qc, and the redistribution of its range (pc, pt).
constexpr double kQc = 0.7;
constexpr double kPc = 0.4;
constexpr double kPt = 0.95;
// Features: edge detector width w in degrees, exponent qf.
constexpr double kW = 0.082;
constexpr double kQf = 0.5;

// One Gaussian of a contrast sensitivity function: a sqrt(pi/b) exp(-pi^2 r^2 / b).
struct CsfGaussian {
  double a, b;
};
struct Csf {
  std::vector<CsfGaussian> gaussians;
};
const std::array<Csf, 3> kCsf = {{
    {{{1.0, 0.0047}}},                // achromatic (Y of YCxCz)
    {{{1.0, 0.0053}}},                // red-green (Cx)
    {{{34.1, 0.04}, {13.5, 0.025}}},  // blue-yellow (Cz)
}};
// The widest Gaussian's b, which sets the radius of all three filters (as in the reference code).
constexpr double kWidestB = 0.04;

// A 2D filter as a weighted sum of separable ones: sum_i weight_i taps_i(x) taps_i(y).
struct SeparableSum {
  std::vector<std::pair<double, Taps>> terms;
};

// s(r) sampled every 1/ppd degrees on the (2R+1)^2 square, normalised to sum 1. A Gaussian
// exp(-pi^2 r^2 / b) has sigma = sqrt(b / (2 pi^2)) degrees, i.e. that times ppd pixels; its 2D
// sum over the square is (sum of its 1D taps)^2.
SeparableSum csfFilter(const Csf& csf, double ppd) {
  const int radius = int(std::ceil(3.0 * std::sqrt(kWidestB / (2.0 * kPi * kPi)) * ppd));
  SeparableSum filter;
  double total = 0.0;
  for (const CsfGaussian& g : csf.gaussians) {
    const Taps taps = gaussianTaps(std::sqrt(g.b / (2.0 * kPi * kPi)) * ppd, radius);
    double sum = 0.0;
    for (double tap : taps) sum += tap;
    const double mass = g.a * std::sqrt(kPi / g.b) * sum * sum;
    filter.terms.emplace_back(mass, normalised(taps));
    total += mass;
  }
  for (auto& term : filter.terms) term.first /= total;
  return filter;
}

Plane apply(const SeparableSum& filter, const Plane& plane) {
  Plane out(plane.width, plane.height);
  for (const auto& [weight, taps] : filter.terms) {
    const Plane part = convolveSeparable(plane, taps, taps, Border::replicate);
    for (std::size_t p = 0; p < out.values.size(); ++p) out[p] += weight * part[p];
  }
  return out;
}

// Positive taps scaled to sum 1, negative ones to sum -1 (zeros stay 0).
Taps balanced(Taps taps) {
  double positive = 0.0, negative = 0.0;
  for (double tap : taps) (tap > 0.0 ? positive : negative) += std::abs(tap);
  for (double& tap : taps) {
    if (tap > 0.0) tap /= positive;
    if (tap < 0.0) tap /= negative;
  }
  return taps;
}

struct FeatureFilters {
  Taps smooth, edge, point;  // along the other axis; first and second derivative along one
};

// The 2D filters -x g(x, y) and (x^2/sd^2 - 1) g(x, y) are a 1D derivative times a 1D Gaussian;
// the sums of their positive and negative parts factor the same way, so balancing the 1D
// derivative and normalising the 1D Gaussian gives exactly the reference code's 2D balancing.
FeatureFilters featureFilters(double ppd) {
  const double sd = 0.5 * kW * ppd;
  const int radius = int(std::ceil(3.0 * sd));
  const Taps g = gaussianTaps(sd, radius);
  FeatureFilters filters{normalised(g), g, g};
  for (int k = -radius; k <= radius; ++k) {
    filters.edge[radius + k] *= -double(k);
    filters.point[radius + k] *= double(k) * k / (sd * sd) - 1.0;
  }
  filters.edge = balanced(filters.edge);
  filters.point = balanced(filters.point);
  return filters;
}

// What FLIP compares of one image: Hunt-adjusted L*a*b* of the CSF-filtered image, and the
// strength of edges and points in its luminance.
struct Prepared {
  std::vector<glm::dvec3> huntLab;
  Plane edges, points;
};

Prepared prepare(const Image& display, const PixelMask& mask,
                 const std::array<SeparableSum, 3>& csf, const FeatureFilters& features) {
  const int w = display.width, h = display.height;
  std::array<Plane, 3> opponent{Plane(w, h), Plane(w, h), Plane(w, h)};
  Plane luminance(w, h);
  for (std::size_t p = 0; p < luminance.values.size(); ++p) {
    const float* rgb = &display.pixels[p * 3];
    const glm::dvec3 linear = mask.covers(p) ? glm::dvec3(rgb[0], rgb[1], rgb[2]) : glm::dvec3(0.0);
    const glm::dvec3 xyz = flip::linearRgbToXyz(linear);
    const glm::dvec3 ycxcz = flip::xyzToYCxCz(xyz);
    for (int c = 0; c < 3; ++c) opponent[c][p] = ycxcz[c];
    luminance[p] = xyz.y;  // = (Y of YCxCz + 16) / 116, the reference code's normalised Y
  }

  Prepared prepared{std::vector<glm::dvec3>(luminance.values.size()), Plane(w, h), Plane(w, h)};
  std::array<Plane, 3> filtered{apply(csf[0], opponent[0]), apply(csf[1], opponent[1]),
                                apply(csf[2], opponent[2])};
  for (std::size_t p = 0; p < prepared.huntLab.size(); ++p) {
    const glm::dvec3 ycxcz(filtered[0][p], filtered[1][p], filtered[2][p]);
    const glm::dvec3 rgb =
        glm::clamp(flip::xyzToLinearRgb(flip::yCxCzToXyz(ycxcz)), glm::dvec3(0.0), glm::dvec3(1.0));
    prepared.huntLab[p] = flip::huntAdjust(flip::xyzToLab(flip::linearRgbToXyz(rgb)));
  }

  const Plane edgeX =
      convolveSeparable(luminance, features.edge, features.smooth, Border::replicate);
  const Plane edgeY =
      convolveSeparable(luminance, features.smooth, features.edge, Border::replicate);
  const Plane pointX =
      convolveSeparable(luminance, features.point, features.smooth, Border::replicate);
  const Plane pointY =
      convolveSeparable(luminance, features.smooth, features.point, Border::replicate);
  for (std::size_t p = 0; p < luminance.values.size(); ++p) {
    prepared.edges[p] = std::hypot(edgeX[p], edgeY[p]);
    prepared.points[p] = std::hypot(pointX[p], pointY[p]);
  }
  return prepared;
}

// The largest HyAB difference in the gamut, to the power qc: between Hunt-adjusted green and blue.
double maxColourDifference() {
  auto huntLab = [](glm::dvec3 rgb) {
    return flip::huntAdjust(flip::xyzToLab(flip::linearRgbToXyz(rgb)));
  };
  return std::pow(flip::hyab(huntLab({0.0, 1.0, 0.0}), huntLab({0.0, 0.0, 1.0})), kQc);
}

}  // namespace

Plane ldrFlip(const Image& testDisplay, const Image& referenceDisplay, const PixelMask& mask,
              double pixelsPerDegree) {
  if (!(pixelsPerDegree > 0.0) || !std::isfinite(pixelsPerDegree))
    throw Error("FLIP: MetricOptions::pixelsPerDegree must be positive and finite, got " +
                std::to_string(pixelsPerDegree));
  const std::array<SeparableSum, 3> csf{csfFilter(kCsf[0], pixelsPerDegree),
                                        csfFilter(kCsf[1], pixelsPerDegree),
                                        csfFilter(kCsf[2], pixelsPerDegree)};
  const FeatureFilters features = featureFilters(pixelsPerDegree);
  const Prepared test = prepare(testDisplay, mask, csf, features);
  const Prepared reference = prepare(referenceDisplay, mask, csf, features);

  const double cmax = maxColourDifference();
  const double knee = kPc * cmax;
  Plane flip(mask.width, mask.height);
  for (std::size_t p = 0; p < flip.values.size(); ++p) {
    if (!mask.covers(p)) continue;
    const double d = std::pow(flip::hyab(test.huntLab[p], reference.huntLab[p]), kQc);
    const double colour =
        d < knee ? kPt / knee * d : kPt + (d - knee) / (cmax - knee) * (1.0 - kPt);
    const double feature = std::pow(std::max(std::abs(reference.edges[p] - test.edges[p]),
                                             std::abs(reference.points[p] - test.points[p])) /
                                        std::sqrt(2.0),
                                    kQf);
    flip[p] = std::pow(colour, 1.0 - feature);
  }
  return flip;
}

}  // namespace lpvlab

// What a VPL sends to a receiver (framework/many_lights/vpl_transfer.h), against closed forms:
//   - a Lambertian point is vpl_gather.h's G f_r, and a glossy point adds rho_s (m + 2) / (2 pi)
//     (w . r)^m times the cosines over d^2;
//   - a virtual spherical light of radius near 0 is its point, and far away (d = 100 r) too;
//   - for a Lambertian receiver that sees the whole cone, the VSL is its point exactly (the cone's
//     integral of cos is (n . axis) pi sin^2(alpha)), which the 16 cone samples reproduce;
//   - the 16 cone samples against a 400 x 400 quadrature of the cone, glossy and cut by the horizon;
//   - near a VSL T stays below cos(theta_vpl) / (pi r^2) times the receiver's albedo, where a
//     point's grows as 1 / d^2.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "framework/many_lights/vpl_gather.h"
#include "framework/many_lights/vpl_transfer.h"

namespace lpvlab {
namespace {

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);
const glm::vec3 kAlbedo(0.5f, 0.4f, 0.3f);

// A VPL at `position` facing down-ish towards the receiver at the origin.
Vpl vplAt(const glm::vec3& position) {
  return {.position = position, .normal = glm::normalize(glm::vec3(0.1f, -1.0f, 0.2f)),
          .flux = glm::vec3(1.0f)};
}

glm::vec3 transfer(const Vpl& vpl, const ReceiverLobe& lobe, const glm::vec3& x = glm::vec3(0.0f)) {
  glm::vec3 toVpl;
  float distance = 0.0f;
  return vplTransfer(x, kUp, kAlbedo, vpl, lobe, 1e-4f, toVpl, distance);
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float relative) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], relative * std::max(std::abs(b[c]), 1e-12f)) << c;
}

TEST(VplTransfer, PointsAreTheClosedForm) {
  const Vpl vpl = vplAt(glm::vec3(0.3f, 0.8f, -0.2f));
  const ReceiverLobe lambertian{.eye = glm::vec3(-1.0f, 1.0f, 0.5f)};
  glm::vec3 toVpl;
  float distance = 0.0f;
  expectNear(transfer(vpl, lambertian), vplGeometryTerm(glm::vec3(0.0f), kUp, kAlbedo, vpl, 1e-4f, toVpl, distance),
             1e-5f);

  ReceiverLobe glossy = lambertian;
  glossy.specularAlbedo = 0.4f;
  glossy.exponent = 6.0f;
  const glm::vec3 w = glm::normalize(vpl.position);
  const glm::vec3 wo = glm::normalize(glossy.eye), r = 2.0f * glm::dot(kUp, wo) * kUp - wo;
  const float cosines = glm::dot(kUp, w) * -glm::dot(vpl.normal, w) / glm::dot(vpl.position, vpl.position);
  const float lobe = 0.4f * 8.0f / float(2.0 * M_PI) * std::pow(std::max(0.0f, glm::dot(w, r)), 6.0f);
  expectNear(transfer(vpl, glossy), (kAlbedo * float(1.0 / M_PI) + glm::vec3(lobe)) * cosines, 1e-5f);
}

TEST(VplTransfer, ASmallOrDistantSphereIsItsPoint) {
  for (const float specular : {0.0f, 0.5f}) {
    const Vpl vpl = vplAt(glm::vec3(0.3f, 0.8f, -0.2f));
    ReceiverLobe point{.specularAlbedo = specular, .exponent = 8.0f, .eye = glm::vec3(-1.0f, 1.0f, 0.5f)};
    ReceiverLobe sphere = point;
    sphere.sphereRadius = 1e-4f;
    expectNear(transfer(vpl, sphere), transfer(vpl, point), 1e-3f);
    sphere.sphereRadius = 0.01f * glm::length(vpl.position);  // d = 100 r
    expectNear(transfer(vpl, sphere), transfer(vpl, point), 2e-3f);
  }
}

TEST(VplTransfer, ALambertianReceiverSeesASphereAsItsPointExactly) {
  const Vpl vpl = vplAt(glm::vec3(0.3f, 0.8f, -0.2f));
  const ReceiverLobe point{.eye = glm::vec3(-1.0f, 1.0f, 0.5f)};
  for (const float radius : {0.1f, 0.3f, 0.6f}) {  // cones of 6 to 38 degrees, above the horizon
    ReceiverLobe sphere = point;
    sphere.sphereRadius = radius;
    expectNear(transfer(vpl, sphere), transfer(vpl, point), 1e-4f);
  }
}

// The cone's samples against a 400 x 400 quadrature: a glossy receiver, and a Lambertian one whose
// horizon cuts the cone (where the closed form does not hold).
void samplesAgreeWithAFineQuadrature(const Vpl& vpl, const ReceiverLobe& sphere, float tolerance) {
  const float d = glm::length(vpl.position);
  const glm::vec3 axis = vpl.position / d;
  const double sinAlpha = sphere.sphereRadius / d, cosAlpha = std::sqrt(1.0 - sinAlpha * sinAlpha);
  glm::vec3 tangent, bitangent;
  orthonormalBasis(axis, tangent, bitangent);
  const PhongBrdf f{.diffuse = kAlbedo, .specular = glm::vec3(sphere.specularAlbedo), .exponent = sphere.exponent};
  const glm::vec3 wo = glm::normalize(sphere.eye);
  constexpr int kFine = 400;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kFine; ++i)
    for (int j = 0; j < kFine; ++j) {
      const double cosTheta = 1.0 - (i + 0.5) / kFine * (1.0 - cosAlpha);
      const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta), phi = 2.0 * M_PI * (j + 0.5) / kFine;
      const glm::vec3 w = glm::vec3(sinTheta * std::cos(phi)) * tangent +
                          glm::vec3(sinTheta * std::sin(phi)) * bitangent + glm::vec3(cosTheta) * axis;
      const glm::vec3 fw = sphere.specularAlbedo > 0.0f ? f.evaluate(kUp, wo, w) : kAlbedo * float(1.0 / M_PI);
      if (glm::dot(kUp, w) > 0.0f) sum += glm::dvec3(fw * glm::dot(kUp, w));
    }
  const double solidAngle = 2.0 * M_PI * (1.0 - cosAlpha);
  const double cosVpl = -glm::dot(vpl.normal, axis);
  const double r2 = double(sphere.sphereRadius) * sphere.sphereRadius;
  const glm::dvec3 expected = sum * (solidAngle / (kFine * kFine) * cosVpl / (M_PI * r2));
  const glm::vec3 sampled = transfer(vpl, sphere);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sampled[c], expected[c], tolerance * expected[c]) << c;
}

TEST(VplTransfer, ASpheresConeSamplesAgreeWithAFineQuadrature) {
  samplesAgreeWithAFineQuadrature(vplAt(glm::vec3(0.3f, 0.8f, -0.2f)),
                                  {.specularAlbedo = 0.5f, .exponent = 8.0f, .sphereRadius = 0.3f,
                                   .eye = glm::vec3(-0.4f, 1.0f, 0.3f)},
                                  0.02f);
  // Low over the horizon: a cone of 37 degrees about a direction 11 degrees up.
  samplesAgreeWithAFineQuadrature(vplAt(glm::vec3(0.8f, 0.16f, 0.1f)),
                                  {.sphereRadius = 0.5f, .eye = glm::vec3(-0.4f, 1.0f, 0.3f)}, 0.03f);
}

TEST(VplTransfer, ASphereStaysBoundedWhereAPointSpikes) {
  const Vpl vpl = vplAt(glm::vec3(0.0f, 1e-3f, 0.0f));  // 1 mm above the receiver
  const ReceiverLobe point{.specularAlbedo = 0.5f, .exponent = 50.0f, .eye = glm::vec3(0.0f, 1.0f, 0.0f)};
  ReceiverLobe sphere = point;
  sphere.sphereRadius = 0.05f;
  const glm::vec3 spike = transfer(vpl, point), bounded = transfer(vpl, sphere);
  const float bound = -vpl.normal.y / float(M_PI * 0.05 * 0.05) * (0.5f + 0.5f);  // albedo <= rho_d + rho_s
  EXPECT_GT(spike.r, 1e4f);
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(std::isfinite(bounded[c]));
    EXPECT_GT(bounded[c], 0.0f);
    EXPECT_LE(bounded[c], bound);
  }
}

}  // namespace
}  // namespace lpvlab

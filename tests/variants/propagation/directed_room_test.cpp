// Directed propagation in a closed room of cells whose six walls all send VPLs (issue 42: the
// Cornell box under a point light, where every surface is lit). Physically two surfaces of one
// normal exchange no light (a point q sends into w.n > 0, a point p receives from w.n < 0), so
// the light a wall gets from its own VPLs is all error; the light it gets from the other walls is
// what one-bounce indirect light is. Per wall W, read as the renderer reads a surface of W's
// normal next to it (the irradiance <L, cosLobe(-n)>, clamped, in the VPL row and the row
// between it and the wall):
//   - standard propagation of every wall's VPLs: S_W; of W's alone: self_W (linear in the light);
//   - directed propagation with release (the default): must not read W's own light (order 1: a
//     lobe about n reads nothing at -n, directed_faces.glsl) and must keep the other walls'
//     light, which reaches W's region through the region boundaries and propagates on as
//     standard: D_W close to S_W - self_W;
//   - directed propagation read literally (release = false), every cell reprojecting all it
//     receives about the normal dilated from its nearest wall: light arriving at a wall is turned
//     back in front of it, and D_W is nearly zero. This test fails on that behaviour, which was
//     directed propagation's before issue 42.
// Both backends, SH order 1 (the orders' ringing lets a little own light through at 2-3:
// directed_test.cpp).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <tuple>

#include "directed_model.h"
#include "order_grid_support.h"
#include "propagation_rig.h"

namespace lpvlab {
namespace {

using namespace test;

constexpr int kSize = 20;         // cells per side of the room's grid
constexpr int kIterations = 24;   // light crosses the room
const glm::ivec3 kRes{kSize, kSize, kSize};

// Wall w (0..5: the grid faces -x, +x, -y, +y, -z, +z) sends VPLs from the cells one in from
// its face (as injection shifts a VPL one cell along its normal, so that the row between holds
// what the wall itself reads); the normal points into the room.
struct Wall {
  int axis;
  int row;           // the VPL row's index along the axis
  int between;       // the row between the VPLs and the wall's plane
  glm::dvec3 normal;
};
Wall wall(int w) {
  const int axis = w / 2;
  const bool low = w % 2 == 0;
  glm::dvec3 n(0.0);
  n[axis] = low ? 1.0 : -1.0;
  return {axis, low ? 1 : kSize - 2, low ? 0 : kSize - 1, n};
}
// The walls' fluxes per VPL cell differ, so that no symmetry hides a wrong sign.
constexpr std::array<double, 6> kWallFlux = {1.0, 0.6, 1.4, 0.8, 0.5, 1.2};

bool onWall(const glm::ivec3& c, const Wall& w) {
  if (c[w.axis] != w.row) return false;
  for (int a = 0; a < 3; ++a)  // the wall's own cells, inside the other walls' rows
    if (a != w.axis && (c[a] < 2 || c[a] > kSize - 3)) return false;
  return true;
}

// The injected light of the walls `mask` selects (bit w: wall w), and every wall's normals
// (the normal grid holds them whether or not their light is loaded: it is the geometry).
Grid wallLight(const OrderGrid& o, unsigned mask) {
  Grid g(o.floats(), 0.0f);
  forEachCell(kRes, [&](const glm::ivec3& c) {
    for (int w = 0; w < 6; ++w) {
      const Wall wl = wall(w);
      if (!(mask >> w & 1u) || !onWall(c, wl)) continue;
      for (int channel = 0; channel < 3; ++channel)
        for (int k = 0; k < o.coefficients; ++k)
          g[o.at(c, channel, k)] += float(kWallFlux[w] * kChannelFlux[channel] / M_PI *
                                          shared::shCosineLobeAt(k, wl.normal));
    }
  });
  return g;
}
std::vector<float> wallNormals() {
  std::vector<float> normals(std::size_t(4) * cells(kRes), 0.0f);
  forEachCell(kRes, [&](const glm::ivec3& c) {
    for (int w = 0; w < 6; ++w) {
      const Wall wl = wall(w);
      if (!onWall(c, wl)) continue;
      const double phi = kWallFlux[w] * injectedFlux();
      const std::size_t i = std::size_t(4) * shared::cellIndex(c, kRes);
      for (int k = 0; k < 3; ++k) normals[i + k] += float(phi * wl.normal[k]);
      normals[i + 3] += float(phi);
    }
  });
  return normals;
}

// What wall w reads of `accumulated` (red channel): the clamped irradiance of a surface facing
// along its normal, summed over its VPL row and the row between, away from the room's edges.
double wallReading(const Grid& accumulated, const OrderGrid& o, int w) {
  const Wall wl = wall(w);
  double sum = 0.0;
  forEachCell(kRes, [&](const glm::ivec3& c) {
    if (c[wl.axis] != wl.row && c[wl.axis] != wl.between) return;
    for (int a = 0; a < 3; ++a)
      if (a != wl.axis && (c[a] < 3 || c[a] > kSize - 4)) return;
    double e = 0.0;
    for (int k = 0; k < o.coefficients; ++k)
      e += accumulated[o.at(c, 0, k)] * shared::shCosineLobeAt(k, -wl.normal);
    sum += std::max(0.0, e);
  });
  return sum;
}

struct Readings {
  std::array<double, 6> wall{};
  double total() const {
    double t = 0.0;
    for (double v : wall) t += v;
    return t;
  }
};

Readings propagate(const std::string& type, toml::table table, unsigned mask, ComputeBackend backend,
                   bool withNormals) {
  const OrderGrid o = orderGrid(kRes, 1);
  PropagationRig rig(type, kRes, std::move(table), 1, false, backend);
  rig.load(wallLight(o, mask));
  if (withNormals) rig.loadNormals(wallNormals());
  rig.propagate();
  const Grid accumulated = rig.accumulated();
  EXPECT_TRUE(allFinite(accumulated));
  Readings r;
  for (int w = 0; w < 6; ++w) r.wall[w] = wallReading(accumulated, o, w);
  return r;
}

class DirectedRoom : public ::testing::TestWithParam<ComputeBackend> {};

TEST_P(DirectedRoom, EachWallLosesOnlyItsOwnLight) {
  const ComputeBackend backend = GetParam();
  const Readings standard = propagate("standard", iterationsTable(kIterations), 0x3f, backend, false);
  Readings self;
  for (int w = 0; w < 6; ++w)
    self.wall[w] = propagate("standard", iterationsTable(kIterations), 1u << w, backend, false).wall[w];
  const Readings directed = propagate("directed", iterationsTable(kIterations), 0x3f, backend, true);
  toml::table literalTable = iterationsTable(kIterations);
  literalTable.insert("release", false);
  const Readings literal = propagate("directed", literalTable, 0x3f, backend, true);

  std::cout << "[ directed room ] wall: standard S, own light self, S - self, directed (release), "
               "directed (literal)\n";
  for (int w = 0; w < 6; ++w) {
    const double others = standard.wall[w] - self.wall[w];
    std::cout << "  wall " << w << ": " << standard.wall[w] << ", " << self.wall[w] << ", " << others
              << ", " << directed.wall[w] << " (" << directed.wall[w] / others << "x), "
              << literal.wall[w] << " (" << literal.wall[w] / others << "x)\n";
    EXPECT_GT(self.wall[w], 0.0) << "standard propagation lights a wall with its own VPLs";
    EXPECT_GT(others, 0.0);
  }
  const double others = standard.total() - self.total();
  std::cout << "  all walls: standard " << standard.total() << ", own light " << self.total()
            << " (" << self.total() / standard.total() << " of it), others' " << others
            << "; directed " << directed.total() << " (" << directed.total() / others
            << "x others'), literal " << literal.total() << " (" << literal.total() / others
            << "x)\n";
  // Release keeps the other walls' light and redirects a wall's own: the other walls' light
  // reaches W's region through its boundary and propagates on as standard, so D_W >= S_W - self_W
  // up to the paths it takes (it leaves the other regions as a lobe about their normal, not as
  // standard propagation's spreading lobes); W's own light, which standard propagation lets
  // linger in front of W and reads at every iteration it stays, is sent to the other walls
  // (flux kept by G(n)), where it is read less often: D_W <= S_W.
  for (int w = 0; w < 6; ++w) {
    EXPECT_GE(directed.wall[w], standard.wall[w] - self.wall[w]) << "wall " << w;
    EXPECT_LE(directed.wall[w], standard.wall[w]) << "wall " << w;
  }
  // Read literally, the reprojection turns the light back in front of every wall.
  EXPECT_LT(literal.total(), 0.1 * others);
}

INSTANTIATE_TEST_SUITE_P(Backends, DirectedRoom,
                         ::testing::Values(ComputeBackend::Gl, ComputeBackend::Cpu),
                         [](const auto& info) {
                           return info.param == ComputeBackend::Cpu ? "cpu" : "gl";
                         });

}  // namespace
}  // namespace lpvlab

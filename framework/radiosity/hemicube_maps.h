#pragma once
// The hemicube's multiplier maps (seed 004, 3.5.1-3.5.3): the delta form factor of each pixel of
// a unit hemicube, the share of the cosine-weighted hemisphere the pixel covers seen from the
// centre of its base. For a pixel of area dA (= (2 / resolution)^2) centred at
//   (u, v) on the top face (distance 1 along the normal, u, v in [-1, 1]):
//       dF = dA / (pi (u^2 + v^2 + 1)^2)                      (shape correction * Lambert cosine)
//   (u, z) on a side face (distance 1 sideways, u in [-1, 1] across, z in [0, 1] up the normal):
//       dF = z dA / (pi (u^2 + z^2 + 1)^2)
// The exact deltas integrate to 1 over the hemicube; these midpoint values sum to 1 minus a
// discretisation error of order resolution^-2 (rawSum). Like the seed, the maps are normalised
// (divided by rawSum), so a side that sees surfaces all round gets form factors summing to 1
// exactly: a closed scene keeps its energy.
//
// Layout: top face resolution x resolution, row-major; the four side faces share one map of
// resolution x resolution/2, row 0 at the base (z near 0), as GL reads back a view whose lower
// half-frustum is cut away.

#include <vector>

namespace lpvlab {

struct HemicubeMaps {
  int resolution = 0;     // pixels across the top face; even
  std::vector<float> top;   // resolution^2
  std::vector<float> side;  // resolution * resolution / 2
  double rawSum = 0.0;      // the unnormalised midpoint sum (1 - discretisation error)
};

// Throws an Error when the resolution is not even and in [2, 8192].
HemicubeMaps hemicubeMaps(int resolution);

}  // namespace lpvlab

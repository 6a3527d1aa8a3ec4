#include "framework/radiosity/hemicube_maps.h"

#include <cmath>
#include <string>

#include "framework/core/error.h"

namespace lpvlab {

HemicubeMaps hemicubeMaps(int resolution) {
  if (resolution < 2 || resolution > 8192 || resolution % 2 != 0)
    throw Error("radiosity: hemicube resolution " + std::to_string(resolution) +
                " must be even and in [2, 8192] (the side faces are half as high)");
  HemicubeMaps maps;
  maps.resolution = resolution;
  const int half = resolution / 2;
  const double pixel = 2.0 / resolution;
  const double area = pixel * pixel;
  auto centre = [&](int i) { return (i + 0.5) * pixel - 1.0; };  // across a face, in [-1, 1]
  std::vector<double> top(std::size_t(resolution) * resolution), side(std::size_t(resolution) * half);
  double sum = 0.0;
  for (int y = 0; y < resolution; ++y)
    for (int x = 0; x < resolution; ++x) {
      const double u = centre(x), v = centre(y), d = u * u + v * v + 1.0;
      top[std::size_t(y) * resolution + x] = area / (M_PI * d * d);
      sum += top[std::size_t(y) * resolution + x];
    }
  for (int y = 0; y < half; ++y)
    for (int x = 0; x < resolution; ++x) {
      const double u = centre(x), z = (y + 0.5) * pixel, d = u * u + z * z + 1.0;
      side[std::size_t(y) * resolution + x] = z * area / (M_PI * d * d);
      sum += 4.0 * side[std::size_t(y) * resolution + x];
    }
  maps.rawSum = sum;
  maps.top.resize(top.size());
  maps.side.resize(side.size());
  for (std::size_t i = 0; i < top.size(); ++i) maps.top[i] = float(top[i] / sum);
  for (std::size_t i = 0; i < side.size(); ++i) maps.side[i] = float(side[i] / sum);
  return maps;
}

}  // namespace lpvlab

#include "framework/fit/fit_covariance.h"

namespace lpvlab {

Eigen::MatrixXd sandwichCovariance(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residuals,
                                   const std::vector<int>& cluster, int clusters) {
  const Eigen::Index p = jacobian.cols();
  // Per cluster, its part of the gradient J_t^T r_t.
  Eigen::MatrixXd gradients = Eigen::MatrixXd::Zero(p, clusters);
  for (Eigen::Index i = 0; i < jacobian.rows(); ++i)
    if (cluster[std::size_t(i)] >= 0)
      gradients.col(cluster[std::size_t(i)]) += jacobian.row(i).transpose() * residuals[i];
  const Eigen::MatrixXd bread = (jacobian.transpose() * jacobian).inverse();
  return bread * (gradients * gradients.transpose()) * bread;
}

int tileClusters(const std::vector<std::pair<int, int>>& viewSizes, int tile, std::vector<int>& cluster) {
  cluster.clear();
  int first = 0;  // the first cluster of the current view
  for (const auto& [width, height] : viewSizes) {
    const int across = (width + tile - 1) / tile, down = (height + tile - 1) / tile;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < 3; ++c) cluster.push_back(first + (y / tile) * across + x / tile);
    first += across * down;
  }
  return first;
}

}  // namespace lpvlab

// The sandwich covariance over tiles (framework/fit/fit_covariance.h) on a case whose answer is
// known: a linear least-squares fit on a 128x128 image whose noise is correlated within 8x8 tiles
// (a random offset per tile plus independent noise per pixel). Over many noise draws, the spread
// of the estimates is what the sandwich deviation says; the usual deviation s^2 (J^T J)^-1, which
// assumes independent residuals, is several times too small.

#include <cmath>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "framework/fit/fit_covariance.h"

namespace lpvlab {
namespace {

TEST(FitCovariance, TileClustersNumberTheTilesOfEachViewInTurn) {
  std::vector<int> cluster;
  // A 5x3 view in 2x2 tiles (3 across, 2 down: 6 tiles), then a 2x2 view (1 tile).
  ASSERT_EQ(tileClusters({{5, 3}, {2, 2}}, 2, cluster), 7);
  ASSERT_EQ(cluster.size(), std::size_t(3 * (15 + 4)));
  const auto of = [&](int pixel) { return cluster[std::size_t(3 * pixel)]; };
  EXPECT_EQ(of(0), 0);
  EXPECT_EQ(of(1), 0);
  EXPECT_EQ(of(2), 1);
  EXPECT_EQ(of(4), 2);       // the last, narrower column of tiles
  EXPECT_EQ(of(5 + 1), 0);   // second row, still the first row of tiles
  EXPECT_EQ(of(10 + 4), 5);  // third row: the second row of tiles
  EXPECT_EQ(of(15), 6);      // the second view
  EXPECT_EQ(cluster[3 * 7 + 2], cluster[3 * 7]);  // a pixel's channels together
}

TEST(FitCovariance, SandwichMatchesTheSpreadOfTileCorrelatedNoiseAndTheNaiveEstimateDoesNot) {
  const int size = 128, tile = 8, draws = 300;
  std::vector<int> cluster;
  const int clusters = tileClusters({{size, size}}, tile, cluster);
  const Eigen::Index n = 3 * size * size;
  // The model: y = a + b u(pixel), u a smooth field in [-1, 1] (as a parameter's effect on an image).
  Eigen::MatrixXd jacobian(n, 2);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int c = 0; c < 3; ++c) {
        const Eigen::Index i = 3 * (y * size + x) + c;
        jacobian(i, 0) = 1.0;
        jacobian(i, 1) = std::sin(0.05 * x) * std::cos(0.03 * y);
      }
  const Eigen::MatrixXd bread = (jacobian.transpose() * jacobian).inverse();
  std::mt19937_64 random(7);
  std::normal_distribution<double> tileNoise(0.0, 0.05), pixelNoise(0.0, 0.02);
  Eigen::MatrixXd estimates(draws, 2);
  Eigen::Vector2d naive = Eigen::Vector2d::Zero(), sandwich = Eigen::Vector2d::Zero();
  for (int d = 0; d < draws; ++d) {
    std::vector<double> offsets(static_cast<std::size_t>(clusters));
    for (double& o : offsets) o = tileNoise(random);
    Eigen::VectorXd noise(n);
    for (Eigen::Index i = 0; i < n; ++i) noise[i] = offsets[std::size_t(cluster[std::size_t(i)])] + pixelNoise(random);
    // Truth (0, 0): the estimate is the least-squares fit to the noise, the residuals what is left.
    const Eigen::Vector2d estimate = bread * jacobian.transpose() * noise;
    const Eigen::VectorXd residuals = noise - jacobian * estimate;
    estimates.row(d) = estimate.transpose();
    const double variance = residuals.squaredNorm() / double(n - 2);
    naive += (variance * bread).diagonal().cwiseSqrt();
    sandwich += sandwichCovariance(jacobian, residuals, cluster, clusters).diagonal().cwiseSqrt();
  }
  naive /= draws;
  sandwich /= draws;
  for (int j = 0; j < 2; ++j) {
    const double spread = std::sqrt(estimates.col(j).squaredNorm() / draws);  // the truth is 0
    // 300 draws know the spread to about 4% (1 sigma); the sandwich is biased low by about
    // p / clusters (256 tiles here).
    EXPECT_NEAR(sandwich[j] / spread, 1.0, 0.15) << "parameter " << j;
    EXPECT_LT(naive[j] / spread, 0.3) << "parameter " << j;
    std::cout << "[ covariance ] parameter " << j << ": spread " << spread << ", sandwich "
              << sandwich[j] << ", naive " << naive[j] << "\n";
  }
}

// Without correlation (independent noise per residual) the two estimates agree.
TEST(FitCovariance, SandwichAgreesWithTheNaiveEstimateForIndependentNoise) {
  const int size = 64, tile = 4;
  std::vector<int> cluster;
  const int clusters = tileClusters({{size, size}}, tile, cluster);
  const Eigen::Index n = 3 * size * size;
  Eigen::MatrixXd jacobian(n, 2);
  std::mt19937_64 random(11);
  std::normal_distribution<double> noise(0.0, 0.1);
  Eigen::VectorXd residuals(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    jacobian(i, 0) = 1.0;
    jacobian(i, 1) = std::cos(0.001 * double(i));
    residuals[i] = noise(random);
  }
  residuals -= jacobian * ((jacobian.transpose() * jacobian).inverse() * jacobian.transpose() * residuals);
  const Eigen::MatrixXd bread = (jacobian.transpose() * jacobian).inverse();
  const Eigen::MatrixXd naive = residuals.squaredNorm() / double(n - 2) * bread;
  const Eigen::MatrixXd sandwich = sandwichCovariance(jacobian, residuals, cluster, clusters);
  for (int j = 0; j < 2; ++j) EXPECT_NEAR(std::sqrt(sandwich(j, j) / naive(j, j)), 1.0, 0.15);
}

}  // namespace
}  // namespace lpvlab

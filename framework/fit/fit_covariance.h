#pragma once
// Covariance of least-squares estimates whose residuals are correlated within groups (image
// tiles): the sandwich (cluster-robust) estimator.
//
// For residuals r(x) with Jacobian J at the solution, the usual estimate (Ceres's covariance
// scaled by the residual variance s^2 = |r|^2 / (n - p)) is s^2 (J^T J)^-1: right when the
// residuals are independent with equal variance. Neighbouring pixels share the LPV's errors
// (a cell's light spreads over many pixels), so they are not, and that estimate is too small.
// Grouping the residuals into clusters t (tiles of the image) that are roughly independent of
// each other, with J_t, r_t the rows of cluster t,
//
//     C = (J^T J)^-1  ( sum_t J_t^T r_t r_t^T J_t )  (J^T J)^-1
//
// is consistent whatever the correlation within a cluster (White 1980; Liang and Zeger 1986): the
// middle term estimates the variance of the gradient J^T r by the sum of its clusters' outer
// products. It needs many clusters (it is biased low with few) and says nothing of correlation
// across tiles (structure larger than a tile).

#include <vector>

#include <Eigen/Dense>

namespace lpvlab {

// `cluster[i]` in [0, clusters) is residual i's cluster, or -1 for a residual left out (a
// background pixel). J^T J must be invertible (the determined parameters' columns only).
Eigen::MatrixXd sandwichCovariance(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residuals,
                                   const std::vector<int>& cluster, int clusters);

// The clusters of a fit's residual vector: the fitted views' images one after the other, each
// pixel's 3 channels together, in tiles of `tile` x `tile` pixels (the last row and column of
// tiles may be smaller). Returns the number of clusters; `cluster` gets one entry per residual.
int tileClusters(const std::vector<std::pair<int, int>>& viewSizes, int tile, std::vector<int>& cluster);

}  // namespace lpvlab

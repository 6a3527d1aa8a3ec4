#pragma once
// Form factors, stored per receiving side (seed 004, equation 2-3): row i holds F_ij for every
// side j that side i sees, the fraction of i's cosine-weighted hemisphere that j covers, so the
// irradiance of i is H_i = sum_j F_ij B_j (B: radiosity, W/m^2). Rows are sparse (a side sees a
// part of the scene), sorted by j, in single precision (the estimators' own error is far larger).
//
// Both estimators fill rows: the hemicube (hemicube.h, GL, from the side's centroid) and ray
// casting (ray_form_factors.h, Embree, from points spread over the side). A row's sum is at most 1;
// the rest of the hemisphere sees nothing (escapes the scene).

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lpvlab {

struct FormFactor {
  std::uint32_t side;
  float value;
};

class FormFactorRows {
public:
  FormFactorRows() = default;
  explicit FormFactorRows(std::size_t sides) : rows_(sides), computed_(sides, false) {}

  std::size_t sides() const { return rows_.size(); }
  bool has(std::size_t i) const { return computed_[i]; }
  std::span<const FormFactor> row(std::size_t i) const { return rows_[i]; }
  void set(std::size_t i, std::vector<FormFactor> row);
  // Frees row i (memory kept only while it is needed).
  void drop(std::size_t i);
  double rowSum(std::size_t i) const;
  std::size_t entries() const { return entries_; }
  std::size_t memoryBytes() const { return entries_ * sizeof(FormFactor) + rows_.size() * sizeof(rows_[0]); }

private:
  std::vector<std::vector<FormFactor>> rows_;
  std::vector<bool> computed_;
  std::size_t entries_ = 0;
};

// Sums contributions per side into a dense scratch row (one per thread), emitting the touched
// sides as a sorted sparse row: the estimators' accumulation.
class RowAccumulator {
public:
  explicit RowAccumulator(std::size_t sides) : values_(sides, 0.0), seen_(sides, 0) {}
  void add(std::uint32_t side, double value) {
    if (!seen_[side]) touched_.push_back(side), seen_[side] = 1;
    values_[side] += value;
  }
  // The row, scaled by `scale`, and the scratch cleared for the next.
  std::vector<FormFactor> take(double scale);

private:
  std::vector<double> values_;
  std::vector<char> seen_;
  std::vector<std::uint32_t> touched_;
};

// What computes rows: the hemicube on GL or rays on Embree.
class FormFactorEstimator {
public:
  virtual ~FormFactorEstimator() = default;
  // Fills the rows of `sides` (indices into the patch mesh's sides).
  virtual void computeRows(const std::vector<std::uint32_t>& sides, FormFactorRows& rows) = 0;
  // Rows it computes at once to best effect (the hemicube's batch of views read back together).
  virtual std::size_t batch() const { return 1; }
  // Its settings and what it has done (pixels read, rays traced), for the manifest.
  virtual nlohmann::json statistics() const = 0;
  // Its cost counters since construction: name -> count (hemicube views, rays).
  virtual double work() const = 0;
  virtual std::string workUnit() const = 0;
  virtual std::size_t memoryBytes() const = 0;
};

}  // namespace lpvlab

namespace lpvlab {

// How far the rows are from reciprocity (A_i F_ij = A_j F_ji for exact form factors), over the
// pairs whose both rows are present: sum |A_i F_ij - A_j F_ji| / sum (A_i F_ij + A_j F_ji), each
// pair counted once (0: reciprocal; the hemicube's and the rays' estimates are not).
double reciprocityError(const FormFactorRows& rows, const std::vector<double>& area);

}  // namespace lpvlab

#include "framework/radiosity/form_factors.h"

#include <algorithm>

namespace lpvlab {

void FormFactorRows::set(std::size_t i, std::vector<FormFactor> row) {
  entries_ -= rows_[i].size();
  entries_ += row.size();
  rows_[i] = std::move(row);
  computed_[i] = true;
}

void FormFactorRows::drop(std::size_t i) {
  entries_ -= rows_[i].size();
  std::vector<FormFactor>().swap(rows_[i]);
  computed_[i] = false;
}

double FormFactorRows::rowSum(std::size_t i) const {
  double sum = 0.0;
  for (const FormFactor& f : rows_[i]) sum += f.value;
  return sum;
}

std::vector<FormFactor> RowAccumulator::take(double scale) {
  std::sort(touched_.begin(), touched_.end());
  std::vector<FormFactor> row;
  row.reserve(touched_.size());
  for (std::uint32_t side : touched_) {
    row.push_back({side, float(values_[side] * scale)});
    values_[side] = 0.0;
    seen_[side] = 0;
  }
  touched_.clear();
  return row;
}

}  // namespace lpvlab

namespace lpvlab {

double reciprocityError(const FormFactorRows& rows, const std::vector<double>& area) {
  double difference = 0.0, total = 0.0;
  for (std::size_t i = 0; i < rows.sides(); ++i) {
    if (!rows.has(i)) continue;
    for (const FormFactor& f : rows.row(i)) {
      const std::size_t j = f.side;
      if (!rows.has(j)) continue;
      const auto back = rows.row(j);
      const auto found = std::lower_bound(back.begin(), back.end(), std::uint32_t(i),
                                          [](const FormFactor& e, std::uint32_t s) { return e.side < s; });
      const double fji = found != back.end() && found->side == i ? double(found->value) : 0.0;
      if (j < i && fji > 0.0) continue;  // counted from j's row
      difference += std::abs(area[i] * f.value - area[j] * fji);
      total += area[i] * f.value + area[j] * fji;
    }
  }
  return total > 0.0 ? difference / total : 0.0;
}

}  // namespace lpvlab

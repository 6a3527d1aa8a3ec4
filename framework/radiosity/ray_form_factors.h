#pragma once
// Form factors by ray casting (seed 004, 2.2.2 "metody vrhani paprsku", 2.2.3.4): from side i,
// `rays` rays leave points spread uniformly over the patch (stratified) in cosine-distributed
// directions over the side's hemisphere; F_ij is the fraction that first hits side j. That is an
// unbiased estimate of the area-to-area form factor (seed 004, equation 2-3), each F_ij a binomial
// proportion with standard error sqrt(F_ij (1 - F_ij) / rays); where the hemicube samples the
// hemisphere from one point (the centroid), rays sample the whole patch.
// Side i's rays draw from their own stream (seed, i): rows do not depend on the thread count.

#include <cstdint>

#include "framework/radiosity/form_factors.h"
#include "framework/radiosity/patch_ray_scene.h"

namespace lpvlab {

class RayFormFactors : public FormFactorEstimator {
public:
  // `mesh` and `scene` must outlive the estimator.
  RayFormFactors(const PatchMesh& mesh, const PatchRayScene& scene, int rays, std::uint64_t seed);

  void computeRows(const std::vector<std::uint32_t>& sides, FormFactorRows& rows) override;
  std::size_t batch() const override { return 64; }
  nlohmann::json statistics() const override;
  double work() const override { return double(traced_); }
  std::string workUnit() const override { return "form-factor ray"; }
  std::size_t memoryBytes() const override { return 0; }

private:
  std::vector<FormFactor> row(std::uint32_t side, RowAccumulator& accumulator) const;

  const PatchMesh& mesh_;
  const PatchRayScene& scene_;
  int rays_;
  std::uint64_t seed_;
  std::size_t traced_ = 0;
};

}  // namespace lpvlab

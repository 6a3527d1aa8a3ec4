#pragma once
// A run's counted work as the columns of a sweep's summary.csv: summary.csv's work.* and
// gpu_work.* columns, and what `lpvlab tune` hands the GPU estimate (analysis/gpu_estimate.py).

#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace lpvlab {

// A manifest's work reports (Pipeline::workReport) as summary columns: per stage the units of
// each kind (work.<stage>.<unit>s), and the multiply-adds and bytes of the modelled kernels; the
// same of the GL kernels (gpu_work.<stage>.*, from the manifest's gpu_work).
std::map<std::string, double> workColumns(const nlohmann::json& manifest);

}  // namespace lpvlab

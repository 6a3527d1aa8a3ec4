#include "framework/experiment/work_columns.h"

namespace lpvlab {

std::map<std::string, double> workColumns(const nlohmann::json& manifest) {
  std::map<std::string, double> columns;
  for (const std::string key : {"work", "gpu_work"}) {
    const auto work = manifest.find(key);
    if (work == manifest.end() || !work->is_object()) continue;
    for (const auto& [stage, counts] : work->items()) {
      if (!counts.is_array()) continue;
      const std::string prefix = key + "." + stage + ".";
      for (const auto& count : counts) {
        if (!count.contains("unit")) continue;
        columns[prefix + count["unit"].get<std::string>() + "s"] += count.value("units", 0.0);
        if (count.value("multiply_adds_per_unit", 0.0) > 0.0)
          columns[prefix + "multiply_adds"] += count.value("multiply_adds", 0.0);
        if (count.value("bytes_per_unit", 0.0) > 0.0)
          columns[prefix + "bytes"] += count.value("bytes", 0.0);
      }
    }
  }
  return columns;
}

}  // namespace lpvlab

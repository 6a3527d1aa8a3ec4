#pragma once
// Reading JSON that lpvlab wrote and may find changed: manifests, frame records and sweep indexes
// read back from disk are navigated by shape, never indexed blindly.

#include <nlohmann/json.hpp>
#include <string>

namespace lpvlab {

// The value at a dotted path ("sequence.frame_records") when every step is an object holding the
// next key; null otherwise (a missing key, or a string where an object belongs).
const nlohmann::json* findPath(const nlohmann::json& j, const std::string& dotted);

}  // namespace lpvlab

#include "framework/experiment/json_path.h"

namespace lpvlab {

const nlohmann::json* findPath(const nlohmann::json& j, const std::string& dotted) {
  const nlohmann::json* node = &j;
  std::size_t start = 0;
  while (true) {
    const auto dot = dotted.find('.', start);
    const std::string part =
        dotted.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    // "name[i]": element i of the array `name` (an array of tables: particles[0].draw).
    const auto open = part.find('[');
    const std::string name = part.substr(0, open);
    if (!node->is_object() || !node->contains(name)) return nullptr;
    node = &(*node)[name];
    if (open != std::string::npos) {
      const std::string digits = part.substr(open + 1, part.size() - open - 2);
      if (part.back() != ']' || digits.empty() ||
          digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9)
        return nullptr;
      const std::size_t index = std::stoul(digits);
      if (!node->is_array() || index >= node->size()) return nullptr;
      node = &(*node)[index];
    }
    if (dot == std::string::npos) return node;
    start = dot + 1;
  }
}

}  // namespace lpvlab

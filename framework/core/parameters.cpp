#include "framework/core/parameters.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

// The source name of values parsed by applyOverride.
constexpr std::string_view kOverrideSource = "command line";

std::string typeName(toml::node_type type) {
  switch (type) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    default: return "a date/time";
  }
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? "(none)" : out;
}

template <class T>
std::string show(const T& v) {
  if constexpr (std::is_same_v<T, std::string>) return "'" + echoed(v) + "'";
  else if constexpr (std::is_arithmetic_v<T>) {
    std::ostringstream s;
    s << v;
    return s.str();
  } else return "value";
}

}  // namespace

Params::Params(const toml::table& table, std::string file, std::string section)
    : state_(std::make_shared<State>()) {
  state_->table = &table;
  state_->file = std::move(file);
  state_->section = std::move(section);
}

std::string Params::dotted(std::string_view key) const {
  return state_->section.empty() ? std::string(key) : state_->section + "." + std::string(key);
}

std::string Params::where(std::string_view key) const {
  std::string location = state_->file;
  if (const toml::node* node = state_->table->get(key)) {
    // A value set by an override (applyOverride) was parsed from "v = VALUE": its line 1 is not a
    // line of the file.
    const auto& src = node->source();
    const bool fromOverride = src.path && *src.path == kOverrideSource;
    if (src.begin.line > 0 && !fromOverride) location += ":" + std::to_string(src.begin.line);
  }
  return location + ": key '" + dotted(key) + "'";
}

const toml::node* Params::lookup(std::string_view key) {
  std::string k(key);
  if (std::find(state_->asked.begin(), state_->asked.end(), k) == state_->asked.end())
    state_->asked.push_back(k);
  return state_->table->get(key);
}

bool Params::has(std::string_view key) { return lookup(key) != nullptr; }

template <class T>
T Params::convert(const toml::node& node, std::string_view key) const {
  auto wrongType = [&](const std::string& expected) -> Error {
    return Error(where(key) + ": expected " + expected + ", got " + typeName(node.type()));
  };
  if constexpr (std::is_same_v<T, bool>) {
    if (auto v = node.value_exact<bool>()) return *v;
    throw wrongType("a boolean");
  } else if constexpr (std::is_same_v<T, int>) {
    if (auto v = node.value_exact<int64_t>()) {
      if (*v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max())
        throw Error(where(key) + ": integer " + std::to_string(*v) + " is too large");
      return static_cast<int>(*v);
    }
    throw wrongType("an integer");
  } else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, float>) {
    std::optional<double> v;
    if (auto i = node.value_exact<int64_t>()) v = static_cast<double>(*i);
    else if (auto d = node.value_exact<double>()) v = *d;
    if (!v) throw wrongType("a number");
    if (!std::isfinite(*v)) throw Error(where(key) + ": value is not finite (NaN or Inf)");
    return static_cast<T>(*v);
  } else if constexpr (std::is_same_v<T, std::string>) {
    if (auto v = node.value_exact<std::string>()) return *v;
    throw wrongType("a string");
  } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    const toml::array* array = node.as_array();
    if (!array) throw wrongType("an array of strings");
    std::vector<std::string> out;
    for (const toml::node& element : *array) {
      auto v = element.value_exact<std::string>();
      if (!v) throw wrongType("an array of strings");
      out.push_back(*v);
    }
    return out;
  } else {
    // glm::vec3 / glm::ivec3: an array of exactly three numbers.
    const toml::array* array = node.as_array();
    if (!array || array->size() != 3) throw wrongType("an array of three numbers");
    T out{};
    for (int i = 0; i < 3; ++i) {
      const toml::node& element = *array->get(static_cast<size_t>(i));
      if constexpr (std::is_same_v<T, glm::ivec3>) {
        auto v = element.value_exact<int64_t>();
        if (!v) throw wrongType("an array of three integers");
        out[i] = static_cast<int>(*v);
      } else {
        std::optional<double> v;
        if (auto n = element.value_exact<int64_t>()) v = static_cast<double>(*n);
        else if (auto d = element.value_exact<double>()) v = *d;
        if (!v) throw wrongType("an array of three numbers");
        if (!std::isfinite(*v)) throw Error(where(key) + ": value is not finite (NaN or Inf)");
        out[i] = static_cast<float>(*v);
      }
    }
    return out;
  }
}

template <class T>
void Params::checkRange(const T& value, const Range<T>& range, std::string_view key) const {
  if constexpr (std::is_arithmetic_v<T>) {
    if (range.min && value < *range.min)
      throw Error(where(key) + ": " + show(value) + " is below the minimum " + show(*range.min));
    if (range.max && value > *range.max)
      throw Error(where(key) + ": " + show(value) + " is above the maximum " + show(*range.max));
  } else if constexpr (std::is_same_v<T, glm::ivec3> || std::is_same_v<T, glm::vec3>) {
    for (int i = 0; i < 3; ++i) {
      if (range.min && value[i] < (*range.min)[i])
        throw Error(where(key) + ": component " + std::to_string(i) + " = " + show(value[i]) +
                    " is below the minimum " + show((*range.min)[i]));
      if (range.max && value[i] > (*range.max)[i])
        throw Error(where(key) + ": component " + std::to_string(i) + " = " + show(value[i]) +
                    " is above the maximum " + show((*range.max)[i]));
    }
  }
}

namespace {
template <class T>
nlohmann::json toJson(const T& v) {
  if constexpr (std::is_same_v<T, glm::vec3> || std::is_same_v<T, glm::ivec3>)
    return nlohmann::json::array({v.x, v.y, v.z});
  else return nlohmann::json(v);
}
}  // namespace

template <class T>
T Params::get(std::string_view key, const T& defaultValue, Range<T> range) {
  const toml::node* node = lookup(key);
  T value = node ? convert<T>(*node, key) : defaultValue;
  if (node) checkRange(value, range, key);
  state_->resolved[std::string(key)] = toJson(value);
  return value;
}

template <class T>
T Params::require(std::string_view key, Range<T> range) {
  if (!state_->table->get(key)) {
    lookup(key);
    throw Error(state_->file + ": missing required key '" + dotted(key) + "'");
  }
  return get<T>(key, T{}, range);
}

std::string Params::getChoice(std::string_view key, const std::string& defaultValue,
                              const std::vector<std::string>& choices) {
  std::string value = get<std::string>(key, defaultValue);
  if (std::find(choices.begin(), choices.end(), value) == choices.end())
    throw Error(where(key) + ": unknown value '" + echoed(value) + "'; valid: " + joined(choices));
  return value;
}

Params Params::table(std::string_view key) {
  static const toml::table empty;
  const toml::node* node = lookup(key);
  if (node && !node->is_table())
    throw Error(where(key) + ": expected a table, got " + typeName(node->type()));
  // Asking twice returns the same handle, so keys read through either count as asked for.
  for (const auto& [name, existing] : state_->children)
    if (name == key) return existing;
  Params child(node ? *node->as_table() : empty, state_->file, dotted(key));
  child.state_->parent = state_;
  state_->children.emplace_back(std::string(key), child);
  return child;
}

Params Params::document() const {
  std::shared_ptr<State> state = state_;
  while (std::shared_ptr<State> parent = state->parent.lock()) state = std::move(parent);
  return Params(std::move(state));
}

std::vector<Params> Params::tables(std::string_view key) {
  std::vector<Params> out;
  const toml::node* node = lookup(key);
  if (!node) return out;
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables())
    throw Error(where(key) + ": expected an array of tables ([[" + dotted(key) + "]])");
  for (size_t i = 0; i < array->size(); ++i) {
    const std::string name = std::string(key) + "[" + std::to_string(i) + "]";
    // As in table(): asking twice returns the same handles, not fresh untracked ones.
    const auto existing = std::find_if(state_->children.begin(), state_->children.end(),
                                       [&](const auto& c) { return c.first == name; });
    if (existing != state_->children.end()) {
      out.push_back(existing->second);
      continue;
    }
    Params child(*array->get(i)->as_table(), state_->file,
                 dotted(key) + "[" + std::to_string(i) + "]");
    child.state_->parent = state_;
    state_->children.emplace_back(name, child);
    out.push_back(child);
  }
  return out;
}

void Params::finish() const {
  for (const auto& [key, node] : *state_->table) {
    const std::string k(key.str());
    if (std::find(state_->asked.begin(), state_->asked.end(), k) != state_->asked.end()) continue;
    std::string location = state_->file;
    if (key.source().begin.line > 0) location += ":" + std::to_string(key.source().begin.line);
    throw Error(location + ": unknown key '" + dotted(k) + "'; valid keys here: " +
                joined(state_->asked));
  }
  for (const auto& child : state_->children) child.second.finish();
}

nlohmann::json Params::resolved() const {
  nlohmann::json out = state_->resolved;
  for (const auto& [key, child] : state_->children) {
    const auto bracket = key.find('[');
    if (bracket == std::string::npos) out[key] = child.resolved();
    else out[key.substr(0, bracket)].push_back(child.resolved());
  }
  return out;
}

template bool Params::get<bool>(std::string_view, const bool&, Range<bool>);
template int Params::get<int>(std::string_view, const int&, Range<int>);
template float Params::get<float>(std::string_view, const float&, Range<float>);
template double Params::get<double>(std::string_view, const double&, Range<double>);
template std::string Params::get<std::string>(std::string_view, const std::string&,
                                              Range<std::string>);
template glm::vec3 Params::get<glm::vec3>(std::string_view, const glm::vec3&, Range<glm::vec3>);
template glm::ivec3 Params::get<glm::ivec3>(std::string_view, const glm::ivec3&,
                                            Range<glm::ivec3>);
template std::vector<std::string> Params::get<std::vector<std::string>>(
    std::string_view, const std::vector<std::string>&, Range<std::vector<std::string>>);
template int Params::require<int>(std::string_view, Range<int>);
template float Params::require<float>(std::string_view, Range<float>);
template double Params::require<double>(std::string_view, Range<double>);
template std::vector<std::string> Params::require<std::vector<std::string>>(
    std::string_view, Range<std::vector<std::string>>);
template std::string Params::require<std::string>(std::string_view, Range<std::string>);
template glm::vec3 Params::require<glm::vec3>(std::string_view, Range<glm::vec3>);
template glm::ivec3 Params::require<glm::ivec3>(std::string_view, Range<glm::ivec3>);

void applyOverride(toml::table& root, std::string_view assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos || eq == 0)
    throw Error("command line: override '" + echoed(assignment) +
                "' is not of the form key=value (e.g. propagation.iterations=16)");
  const std::string path(assignment.substr(0, eq));
  const std::string text(assignment.substr(eq + 1));
  toml::table* table = &root;
  std::string_view rest = path;
  for (auto dot = rest.find('.'); dot != std::string_view::npos; dot = rest.find('.')) {
    const std::string part(rest.substr(0, dot));
    rest.remove_prefix(dot + 1);
    // "name[i]": table i of the array of tables `name` ([[particles]], [[lights]]), which must
    // exist (an override changes a table the file has; it cannot say what the others would be).
    const auto open = part.find('[');
    if (open != std::string::npos) {
      const std::string name = part.substr(0, open), digits = part.substr(open + 1, part.size() - open - 2);
      const bool number = part.back() == ']' && !digits.empty() &&
                          digits.find_first_not_of("0123456789") == std::string::npos && digits.size() < 9;
      if (!number)
        throw Error("command line: override '" + echoed(path) + "': '" + echoed(part) +
                    "' is not of the form name[index] (e.g. particles[0].emitters[1].rate=100)");
      const std::size_t index = std::stoul(digits);
      toml::array* array = table->get(name) ? table->get(name)->as_array() : nullptr;
      if (!array || !array->is_array_of_tables())
        throw Error("command line: override '" + path + "': '" + name +
                    "' is not an array of tables ([[" + name + "]]) here");
      if (index >= array->size())
        throw Error("command line: override '" + path + "': there are " +
                    std::to_string(array->size()) + " [[" + name + "]] tables (indices from 0)");
      table = (*array)[index].as_table();
      continue;
    }
    toml::node* child = table->get(part);
    if (!child) child = &table->insert_or_assign(part, toml::table{}).first->second;
    if (!child->is_table())
      throw Error("command line: override '" + path + "': '" + part + "' is not a table");
    table = child->as_table();
  }
  // Parse the value as TOML; a bare word that isn't valid TOML is taken as a string
  // (propagation.type=directed). A value that starts as a table, an array or a quoted string
  // must parse: taken as a string it would be blamed on the file later ("expected a table").
  toml::table parsed;
  try {
    parsed = toml::parse(std::string_view("v = " + text), kOverrideSource);
  } catch (const toml::parse_error& e) {
    const std::size_t first = text.find_first_not_of(" \t");
    if (first != std::string::npos && std::string_view("{[\"'").find(text[first]) != std::string_view::npos)
      throw Error("command line: override '" + echoed(path) + "': its value '" + echoed(text) +
                  "' is not valid TOML: " + std::string(e.description()));
    parsed = toml::table{{"v", text}};
  }
  table->insert_or_assign(std::string(rest), std::move(*parsed.get("v")));
}

toml::table readTomlFile(const std::string& path) {
  // toml++ reports a missing file as a parse error at line 0, column 0; say what happened.
  if (std::filesystem::is_directory(path)) throw Error(path + ": is a directory, not a TOML file");
  if (!std::filesystem::is_regular_file(path)) throw Error(path + ": file not found");
  try {
    return toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    const auto& src = e.source();
    throw Error(path + ":" + std::to_string(src.begin.line) + ":" +
                std::to_string(src.begin.column) + ": " + std::string(e.description()));
  }
}

}  // namespace lpvlab

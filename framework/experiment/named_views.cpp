#include "framework/experiment/named_views.h"

#include "framework/core/error.h"

namespace lpvlab {

namespace {

std::string lineOf(const toml::node& node) {
  const auto& src = node.source();
  return src.begin.line > 0 ? ":" + std::to_string(src.begin.line) : "";
}

}  // namespace

std::vector<NamedView> readNamedViews(const toml::table& owner, const std::string& ownerName,
                                      const std::string& key, const std::string& file) {
  std::vector<NamedView> out;
  const toml::node* node = owner.get(key);
  if (!node) return out;
  const std::string full = ownerName + "." + key;
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables())
    throw Error(file + lineOf(*node) + ": key '" + full + "': expected an array of tables ([[" + full +
                "]] with a name and experiment keys)");
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::table& t = *array->get(i)->as_table();
    const std::string where = file + lineOf(t) + ": key '" + full + "[" + std::to_string(i) + "]";
    const toml::node* name = t.get("name");
    if (!name || !name->is_string())
      throw Error(where + ".name': every view needs a name (a string)");
    NamedView view{name->as_string()->get(), t};
    view.keys.erase("name");
    for (const NamedView& other : out)
      if (other.name == view.name) throw Error(where + ".name': '" + view.name + "' is used twice");
    for (const auto& [k, v] : view.keys)
      if (k.str() == ownerName || k.str() == "sweep")
        throw Error(where + "." + std::string(k.str()) + "': a view cannot have a [" +
                    std::string(k.str()) + "] table");
    out.push_back(std::move(view));
  }
  return out;
}

toml::table withView(const toml::table& base, const NamedView& view) {
  // Whole tables are replaced, not merged: a view's camera given by position must not inherit
  // the file's camera name (and a view's scene is not mixed with the file's).
  toml::table t = base;
  for (const auto& [key, node] : view.keys) t.insert_or_assign(key, node);
  return t;
}

}  // namespace lpvlab

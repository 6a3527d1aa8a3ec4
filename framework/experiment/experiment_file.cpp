#include "framework/experiment/experiment_file.h"

#include <algorithm>
#include <filesystem>
#include <vector>

#include "framework/core/error.h"
#include "framework/core/parameters.h"

namespace lpvlab {

namespace fs = std::filesystem;

namespace {

std::string canonicalName(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(path), ec);
  return ec ? fs::absolute(path).lexically_normal().string() : p.string();
}

// A relative scene file reference of `table` (read from `file`) made absolute, so that it keeps
// meaning the same file wherever the table is written or merged: scene.file and every
// particles[i].model.
void absolutizeReference(toml::table& owner, const char* key, const std::string& file) {
  toml::node* node = owner.get(key);
  if (!node || !node->is_string()) return;
  const std::string ref = node->as_string()->get();
  if (ref.rfind("builtin:", 0) == 0 || ref.rfind("shared:", 0) == 0) return;
  const fs::path p(ref);
  if (p.is_absolute()) return;
  owner.insert_or_assign(key, fs::absolute(fs::path(file).parent_path() / p).lexically_normal().string());
}

toml::table readChain(const std::string& path, std::vector<std::string>& stack, bool isBase) {
  const std::string canonical = canonicalName(path);
  if (std::find(stack.begin(), stack.end(), canonical) != stack.end()) {
    std::string chain;
    for (const std::string& f : stack) chain += f + " -> ";
    throw Error(path + ": key 'extends': cycle: " + chain + canonical);
  }
  stack.push_back(canonical);
  toml::table table = readTomlFile(path);
  const auto where = [&](const toml::node& node, const std::string& key) {
    const auto& src = node.source();
    return path + (src.begin.line > 0 ? ":" + std::to_string(src.begin.line) : "") + ": key '" +
           key + "'";
  };
  // This file's keys are merged over its base (`extends`), then over its `include` files, in
  // order: a parameter file (e.g. a fit's fitted.toml) overrides the base, the file itself both.
  toml::table merged;
  if (toml::node* ext = table.get("extends")) {
    if (!ext->is_string())
      throw Error(where(*ext, "extends") + ": expected a string (a file name relative to this file)");
    const fs::path basePath = fs::path(path).parent_path() / ext->as_string()->get();
    if (!fs::is_regular_file(basePath))
      throw Error(path + ": key 'extends': base file " + basePath.string() + " not found");
    merged = readChain(basePath.string(), stack, true);
  }
  if (toml::node* inc = table.get("include")) {
    const toml::array* files = inc->as_array();
    if (!files)
      throw Error(where(*inc, "include") + ": expected a list of file names relative to this file");
    for (const toml::node& f : *files) {
      if (!f.is_string())
        throw Error(where(*inc, "include") + ": expected a list of file names relative to this file");
      const fs::path included = fs::path(path).parent_path() / f.as_string()->get();
      if (!fs::is_regular_file(included))
        throw Error(path + ": key 'include': file " + included.string() + " not found");
      mergeTables(merged, readChain(included.string(), stack, true));
    }
  }
  if (table.contains("extends") || table.contains("include")) {
    table.erase("extends");
    table.erase("include");
    mergeTables(merged, table);
    table = std::move(merged);
  }
  if (isBase) absolutizeSceneFile(table, path);
  stack.pop_back();
  return table;
}

}  // namespace

void absolutizeSceneFile(toml::table& table, const std::string& file) {
  if (toml::table* scene = table["scene"].as_table()) absolutizeReference(*scene, "file", file);
  if (toml::array* particles = table["particles"].as_array())
    for (toml::node& system : *particles)
      if (toml::table* t = system.as_table()) absolutizeReference(*t, "model", file);
}

void mergeTables(toml::table& base, const toml::table& over) {
  for (const auto& [key, node] : over) {
    toml::node* existing = base.get(key.str());
    if (existing && existing->is_table() && node.is_table()) {
      mergeTables(*existing->as_table(), *node.as_table());
      continue;
    }
    base.insert_or_assign(key, node);
  }
}

toml::table readExperimentTable(const std::string& path) {
  std::vector<std::string> stack;
  return readChain(path, stack, false);
}

}  // namespace lpvlab

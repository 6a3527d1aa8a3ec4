#include "framework/experiment/sweep_expansion.h"

#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "framework/core/error.h"
#include "framework/core/hash.h"
#include "framework/core/parameters.h"
#include "framework/experiment/experiment_file.h"

namespace lpvlab {

namespace fs = std::filesystem;

namespace {

// The TOML text a configuration runs with: `root` (extends merged) without its [sweep] table,
// `overrides` applied, relative scene files made absolute. Both its id and its configs/<id>.toml
// come from this one text.
std::string resolvedText(const toml::table& root, const std::string& file,
                         const std::vector<std::string>& overrides) {
  toml::table table = root;
  table.erase("sweep");
  for (const std::string& o : overrides) applyOverride(table, o);
  absolutizeSceneFile(table, file);
  std::ostringstream s;
  s << toml::toml_formatter(table);
  return s.str();
}

// One swept list: its dotted key and values.
struct SweptList {
  std::string key;
  std::vector<std::string> texts;   // TOML value text, for overrides
  std::vector<std::string> plain;   // readable text, for names and the summary
};

std::string plainText(const toml::node& node) {
  if (const auto* s = node.as_string()) return s->get();
  return tomlValueText(node);
}

void collectLists(const toml::table& table, const std::string& prefix, const std::string& where,
                  std::vector<SweptList>& out) {
  for (const auto& [k, node] : table) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const toml::table* sub = node.as_table()) {
      collectLists(*sub, key, where, out);
      continue;
    }
    const toml::array* array = node.as_array();
    if (!array)
      throw Error(where + ": key '" + key + "': expected a list of values to sweep over");
    if (array->empty())
      throw Error(where + ": key '" + key + "': empty list: the sweep expands to nothing");
    SweptList list{key, {}, {}};
    for (const toml::node& v : *array) {
      list.texts.push_back(tomlValueText(v));
      list.plain.push_back(plainText(v));
    }
    out.push_back(std::move(list));
  }
}

struct SweepSpec {
  std::vector<SweptList> product, zip;
};

SweepSpec readSweep(const toml::table& root, const std::string& file) {
  SweepSpec spec;
  const toml::node* node = root.get("sweep");
  if (!node) return spec;
  const toml::table* sweep = node->as_table();
  if (!sweep) throw Error(file + ": key 'sweep': expected a table with product and/or zip");
  // An empty [sweep] would run the base configuration alone, with no word that nothing is swept.
  if (sweep->empty())
    throw Error(file + ": key 'sweep': empty: give product and/or zip (or run the file with "
                "`lpvlab run`)");
  for (const auto& [k, value] : *sweep) {
    const std::string name(k.str());
    if (name != "product" && name != "zip")
      throw Error(file + ": key 'sweep." + name + "': unknown (valid keys: product, zip)");
    const toml::table* lists = value.as_table();
    if (!lists)
      throw Error(file + ": key 'sweep." + name + "': expected a table of \"key\" = [values]");
    collectLists(*lists, "", file + ": sweep." + name, name == "product" ? spec.product : spec.zip);
    if ((name == "product" ? spec.product : spec.zip).empty())
      throw Error(file + ": key 'sweep." + name + "': empty: the sweep expands to nothing");
  }
  if (!spec.zip.empty()) {
    bool equal = true;
    for (const SweptList& l : spec.zip) equal = equal && l.texts.size() == spec.zip[0].texts.size();
    if (!equal) {
      std::string detail;
      for (const SweptList& l : spec.zip)
        detail += (detail.empty() ? "" : ", ") + l.key + " (" + std::to_string(l.texts.size()) + " values)";
      throw Error(file + ": key 'sweep.zip': lists of unequal length: " + detail);
    }
  }
  return spec;
}

// More than this is a mistake (every configuration is a directory and a run), and the expansion
// itself would exhaust memory long before the product overflowed.
constexpr std::size_t kMostConfigurations = 100000;

// FNV-1a mixes its high bits poorly for inputs that differ in one character; a splitmix64
// finaliser spreads every input bit before the first 10 hex digits are taken.
std::string shortId(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  char buffer[17];
  std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(x));
  return std::string(buffer, 10);
}

std::string leaf(const std::string& key) {
  const auto dot = key.rfind('.');
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

}  // namespace

std::string tomlValueText(const toml::node& node) {
  toml::table wrapper;
  wrapper.insert("v", node);
  std::ostringstream s;
  s << toml::toml_formatter(wrapper, toml::format_flags::none);
  std::string text = s.str();
  const auto eq = text.find('=');
  text = text.substr(eq + 1);
  const auto b = text.find_first_not_of(" \t\n");
  const auto e = text.find_last_not_of(" \t\n");
  return b == std::string::npos ? "" : text.substr(b, e - b + 1);
}

std::vector<std::string> sweptKeys(const toml::table& root, const std::string& file) {
  const SweepSpec spec = readSweep(root, file);
  std::set<std::string> keys;
  for (const SweptList& l : spec.product) keys.insert(l.key);
  for (const SweptList& l : spec.zip) keys.insert(l.key);
  return {keys.begin(), keys.end()};
}

std::size_t checkSweep(const toml::table& root, const std::string& file) {
  const SweepSpec spec = readSweep(root, file);
  std::set<std::string> seen;
  for (const auto* group : {&spec.zip, &spec.product})
    for (const SweptList& l : *group)
      if (!seen.insert(l.key).second)
        throw Error(file + ": key 'sweep': '" + l.key + "' is swept twice");
  const std::size_t zipCount = spec.zip.empty() ? 1 : spec.zip[0].texts.size();
  std::size_t productCount = 1;
  for (const SweptList& l : spec.product) {
    // Checked before it can overflow: ten lists of a hundred values are 1e20 configurations.
    if (l.texts.size() > kMostConfigurations / productCount / zipCount)
      throw Error(file + ": key 'sweep': expands to more than " +
                  std::to_string(kMostConfigurations) + " configurations (at '" + l.key +
                  "'); split it into several sweeps");
    productCount *= l.texts.size();
  }
  return zipCount * productCount;
}

std::vector<SweepConfiguration> expandSweep(const toml::table& root, const std::string& file,
                                            const std::vector<std::string>& extraOverrides) {
  checkSweep(root, file);
  const SweepSpec spec = readSweep(root, file);
  // Readable names use the last component of a key unless two swept keys share it.
  std::map<std::string, int> leafCount;
  for (const auto* group : {&spec.zip, &spec.product})
    for (const SweptList& l : *group) ++leafCount[leaf(l.key)];
  auto label = [&](const std::string& k) { return leafCount[leaf(k)] > 1 ? k : leaf(k); };

  // Choices: one per zip index, times every combination of the product lists (last fastest).
  const std::size_t zipCount = spec.zip.empty() ? 1 : spec.zip[0].texts.size();
  std::size_t productCount = 1;
  for (const SweptList& l : spec.product) productCount *= l.texts.size();

  std::vector<SweepConfiguration> out;
  for (std::size_t z = 0; z < zipCount; ++z) {
    for (std::size_t p = 0; p < productCount; ++p) {
      SweepConfiguration c;
      c.overrides = extraOverrides;
      std::vector<std::pair<const SweptList*, std::size_t>> picks;
      for (const SweptList& l : spec.zip) picks.push_back({&l, z});
      std::size_t rest = p;
      std::vector<std::size_t> indices(spec.product.size());
      for (std::size_t i = spec.product.size(); i-- > 0;) {
        indices[i] = rest % spec.product[i].texts.size();
        rest /= spec.product[i].texts.size();
      }
      for (std::size_t i = 0; i < spec.product.size(); ++i) picks.push_back({&spec.product[i], indices[i]});
      for (const auto& [list, index] : picks) {
        c.overrides.push_back(list->key + "=" + list->texts[index]);
        c.values.push_back({list->key, list->plain[index]});
        c.name += (c.name.empty() ? "" : ",") + label(list->key) + "=" + list->plain[index];
      }
      if (c.name.empty()) c.name = "base";
      // The id is the hash of everything the configuration runs with, not of its swept values
      // alone: a changed base value (or -s) is another configuration, never a finished one.
      c.id = shortId(Hasher().text(resolvedText(root, file, c.overrides)).digest());
      out.push_back(std::move(c));
    }
  }
  return out;
}

std::vector<SweepConfiguration> expandSweep(const std::string& file,
                                            const std::vector<std::string>& extraOverrides) {
  toml::table root = readExperimentTable(file);
  for (const std::string& o : extraOverrides) applyOverride(root, o);
  return expandSweep(root, file, extraOverrides);
}

std::string configurationToml(const toml::table& root, const std::string& file,
                              const SweepConfiguration& configuration) {
  std::ostringstream s;
  s << "# lpvlab sweep configuration " << configuration.id << " (" << configuration.name
    << ") of " << fs::absolute(file).lexically_normal().string() << "\n";
  for (const std::string& o : configuration.overrides) s << "# override: " << o << "\n";
  s << "\n" << resolvedText(root, file, configuration.overrides) << "\n";
  return s.str();
}

std::string configurationToml(const std::string& file, const SweepConfiguration& configuration) {
  return configurationToml(readExperimentTable(file), file, configuration);
}

std::string sweepHash(const toml::table& root, const std::string& file) {
  toml::table resolved = root;
  absolutizeSceneFile(resolved, file);
  std::ostringstream s;
  s << toml::toml_formatter(resolved);
  return Hasher().text(s.str()).hex();
}

}  // namespace lpvlab

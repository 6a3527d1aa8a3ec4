#include "framework/experiment/sweep.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "framework/core/error.h"
#include "framework/core/hash.h"
#include "framework/core/parameters.h"
#include "framework/experiment/experiment.h"
#include "framework/experiment/json_path.h"
#include "framework/experiment/scene_cache.h"
#include "framework/io/atomic_file.h"
#include "framework/reference/reference_cache.h"

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

void absolutizeSceneFile(toml::table& table, const std::string& file) {
  if (toml::table* scene = table["scene"].as_table()) absolutizeReference(*scene, "file", file);
  if (toml::array* particles = table["particles"].as_array())
    for (toml::node& system : *particles)
      if (toml::table* t = system.as_table()) absolutizeReference(*t, "model", file);
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

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string jsonText(const nlohmann::json* j) {
  if (!j || j->is_null()) return "";
  if (j->is_string()) return j->get<std::string>();
  return j->dump();
}

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw Error(path.string() + ": cannot open");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw Error(path.string() + ": " + e.what());
  }
}

}  // namespace

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

std::vector<SweepConfiguration> expandSweep(const toml::table& root, const std::string& file,
                                            const std::vector<std::string>& extraOverrides) {
  const SweepSpec spec = readSweep(root, file);
  std::set<std::string> seen;
  for (const auto* group : {&spec.zip, &spec.product})
    for (const SweptList& l : *group)
      if (!seen.insert(l.key).second)
        throw Error(file + ": key 'sweep': '" + l.key + "' is swept twice");
  // Readable names use the last component of a key unless two swept keys share it.
  std::map<std::string, int> leafCount;
  for (const std::string& k : seen) ++leafCount[leaf(k)];
  auto label = [&](const std::string& k) { return leafCount[leaf(k)] > 1 ? k : leaf(k); };

  // Choices: one per zip index, times every combination of the product lists (last fastest).
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

std::vector<std::string> checkConfigurations(
    const toml::table& root, const std::string& file,
    const std::vector<SweepConfiguration>& configurations) {
  std::vector<std::string> referenceKeys;
  SceneCache scenes;
  std::string sweepWhere = file;
  if (const toml::node* sweep = root.get("sweep"); sweep && sweep->source().begin.line > 0)
    sweepWhere += ":" + std::to_string(sweep->source().begin.line);
  for (const SweepConfiguration& c : configurations) {
    toml::table table = root;
    table.erase("sweep");
    table.erase("fit");
    for (const std::string& o : c.overrides) applyOverride(table, o);
    try {
      const Experiment e = loadExperiment(table, file, std::ref(scenes));
      referenceKeys.push_back(e.compareWithReference ? referenceKey(e.scene, e.camera, e.reference)
                                                     : "");
    } catch (const Error& error) {
      throw Error(sweepWhere + ": key 'sweep': configuration " + c.name +
                  " fails: " + error.what());
    }
  }
  return referenceKeys;
}

std::string configurationToml(const std::string& file, const SweepConfiguration& configuration) {
  std::ostringstream s;
  s << "# lpvlab sweep configuration " << configuration.id << " (" << configuration.name
    << ") of " << fs::absolute(file).lexically_normal().string() << "\n";
  for (const std::string& o : configuration.overrides) s << "# override: " << o << "\n";
  s << "\n" << resolvedText(readExperimentTable(file), file, configuration.overrides) << "\n";
  return s.str();
}

std::string sweepHash(const toml::table& root, const std::string& file) {
  toml::table resolved = root;
  absolutizeSceneFile(resolved, file);
  std::ostringstream s;
  s << toml::toml_formatter(resolved);
  return Hasher().text(s.str()).hex();
}

namespace {

// `value` with every array left out, objects kept (nested ones too).
nlohmann::json withoutArrays(const nlohmann::json& value) {
  if (!value.is_object()) return value;
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, child] : value.items())
    if (!child.is_array()) out[key] = withoutArrays(child);
  return out;
}


// A manifest's work reports (Pipeline::workReport) as summary columns: per stage the units of
// each kind (work.<stage>.<unit>s), and the multiply-adds and bytes of the modelled kernels; the
// same of the GL kernels (gpu_work.<stage>.*, from the manifest's gpu_work).
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

// A manifest's per-repeat stage times (timing.samples.stage_ms; "gpu_ms" in manifests written
// before stage times were labelled by their clock, which have no timing.clock), or nullptr.
const nlohmann::json* stageSamples(const nlohmann::json& manifest) {
  if (const auto* s = findPath(manifest, "timing.samples.stage_ms")) return s;
  return findPath(manifest, "timing.samples.gpu_ms");
}

// summarise's body: `reading` names the file whose values it reads, for the error when one has
// an unexpected structure (a string where a number belongs, say: nlohmann's type errors).
SummaryResult summarise(const std::string& dir, std::string& reading) {
  const fs::path root(dir);
  if (!fs::is_directory(root)) throw Error(dir + ": not a directory");
  std::vector<std::string> swept;
  std::map<std::string, std::string> names;
  if (!fs::exists(root / "sweep.json"))
    throw Error(dir + ": not a sweep directory (no sweep.json, which `lpvlab sweep FILE --out DIR` "
                "writes)");
  reading = (root / "sweep.json").string();
  const nlohmann::json index = readJson(root / "sweep.json");
  for (const auto& k : index.value("swept_keys", nlohmann::json::array())) swept.push_back(k.get<std::string>());
  for (const auto& c : index.value("configurations", nlohmann::json::array()))
    names[c.value("id", "")] = c.value("name", "");
  const std::vector<std::string> fixed = {"indirect.method",  "injection.type",   "occlusion.type",
                                          "propagation.type", "rendering.type",
                                          "grid.resolution",  "grid.sh_order",
                                          "cascades.levels",  "propagation.iterations",
                                          "scene.file"};
  std::vector<std::string> params = swept;
  for (const std::string& k : fixed)
    if (std::find(params.begin(), params.end(), k) == params.end()) params.push_back(k);

  SummaryResult result;
  std::vector<std::pair<std::string, nlohmann::json>> manifests;
  std::vector<fs::path> subdirs;
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.is_directory() && entry.path().filename() != "configs" && entry.path().filename() != "logs")
      subdirs.push_back(entry.path());
  std::sort(subdirs.begin(), subdirs.end());
  for (const fs::path& sub : subdirs) {
    const std::string id = sub.filename().string();
    if (!names.count(id)) {
      result.foreign.push_back(id);
      continue;
    }
    if (!fs::exists(sub / "manifest.json")) {
      result.incomplete.push_back(id);
      continue;
    }
    reading = (sub / "manifest.json").string();
    nlohmann::json manifest = readJson(sub / "manifest.json");
    // A row is a timed frame: a manifest without timing samples has none to give.
    const auto* samples = stageSamples(manifest);
    const auto* total = samples ? findPath(*samples, "total") : nullptr;
    if (!total || !total->is_array() || total->empty()) {
      result.dropped.push_back({id, "its manifest.json has no timing.samples.stage_ms.total"});
      continue;
    }
    manifests.push_back({id, std::move(manifest)});
    result.complete.push_back(id);
  }
  // Particle systems' drawing, where a sweep does not set it: the report tells geometry from light
  // fields by it.
  const bool anyParticles = std::any_of(manifests.begin(), manifests.end(), [](const auto& m) {
    const auto* p = findPath(m.second, "particles");
    return p && p->is_array() && !p->empty();
  });
  if (anyParticles && std::find(params.begin(), params.end(), "particles[0].draw") == params.end())
    params.push_back("particles[0].draw");
  std::set<std::string> stages, memoryGroups, workKeys;
  std::map<std::string, std::map<std::string, double>> workById;
  std::set<std::pair<std::string, std::string>> metrics;
  std::set<std::string> temporalColumns;
  // Figures of a run beside its timings: another indirect method's (its manifest's
  // indirect_method.statistics), each number outside arrays as method.<path> (e.g.
  // method.clamp.removed_fraction; arrays, such as a solver's convergence log, stay in the
  // manifest), and the particles' counts summed over the systems (particles.alive at frame 0,
  // particles.capacity, particles.triangles).
  std::map<std::string, std::map<std::string, double>> figuresById;
  std::set<std::string> figureColumns;
  for (const auto& [id, m] : manifests) {
    reading = (root / id / "manifest.json").string();
    if (const auto* statistics = findPath(m, "indirect_method.statistics"); statistics) {
      const nlohmann::json flat = withoutArrays(*statistics).flatten();  // "/clamp/c" -> value
      for (const auto& [path, value] : flat.items())
        if (value.is_number()) {
          std::string column = "method" + path;
          std::replace(column.begin(), column.end(), '/', '.');
          figuresById[id][column] = value.get<double>();
          figureColumns.insert(column);
        }
    }
    if (const auto* particles = findPath(m, "particles"); particles && particles->is_array())
      for (const auto& system : *particles)
        for (const auto& [figure, key] : {std::pair{"alive", "alive_at_frame_0"},
                                          std::pair{"capacity", "capacity"},
                                          std::pair{"triangles", "triangles"}}) {
          const std::string column = std::string("particles.") + figure;
          figuresById[id][column] += system.at(key).get<double>();
          figureColumns.insert(column);
        }
    workById[id] = workColumns(m);
    for (const auto& [key, _] : workById[id]) workKeys.insert(key);
    if (const auto* g = findPath(m, "memory_bytes"); g && g->is_object())
      for (const auto& [group, _] : g->items())
        if (group != "total") memoryGroups.insert(group);
    if (const auto* s = stageSamples(m); s && s->is_object())
      for (const auto& [stage, _] : s->items()) stages.insert(stage);
    if (const auto* s = findPath(m, "timing.samples.wall_ms"); s && s->is_object())
      for (const auto& [stage, _] : s->items()) stages.insert(stage);
    // A sequence's temporal figures (sequence_temporal.h): its frames' relative change and error.
    if (const auto* records = findPath(m, "sequence.frame_records"); records && records->is_array())
      for (const auto& record : *records)
        if (const auto* t = findPath(record, "temporal"); t && t->is_object())
          for (const char* group : {"change", "error"})
            if (const auto* g = findPath(*t, group); g && g->is_object())
              for (const auto& [name, _] : g->items())
                temporalColumns.insert(std::string("temporal.") + group + "." + name + ".relative");
    if (const auto* c = findPath(m, "reference.comparison"); c && c->is_object())
      for (const auto& [pair, value] : c->items())
        if (value.is_object() && value.contains("metrics") && value["metrics"].is_object())
          for (const auto& [metric, _] : value["metrics"].items()) metrics.insert({pair, metric});
  }

  std::ostringstream csv;
  std::vector<std::string> header = {"config_id", "config_name", "repeat", "run_dir"};
  for (const std::string& k : params) header.push_back("param." + k);
  // Each stage's time by its clock, and the clock (where the stage ran): gl_timer_query on the
  // GL renderer, cpu_wall_clock on the CPU; both named in timed_on.*.
  for (const std::string& s : stages) header.push_back("time." + s + ".ms");
  for (const std::string& s : stages) header.push_back("time." + s + ".clock");
  for (const std::string& s : stages) header.push_back("wall_ms." + s);
  header.push_back("timed_on.gl");
  header.push_back("timed_on.cpu");
  header.push_back("memory_bytes");
  for (const std::string& g : memoryGroups) header.push_back("memory_bytes." + g);
  header.push_back("cells");
  for (const std::string& k : workKeys) header.push_back(k);
  for (const auto& [pair, metric] : metrics) header.push_back("metric." + pair + "." + metric);
  for (const std::string& column : figureColumns) header.push_back(column);
  if (!temporalColumns.empty()) header.push_back("temporal.at_rest");
  for (const std::string& column : temporalColumns) header.push_back(column);
  // A run's warnings (run_outputs.h's resultWarnings: a black image, a solve that did not
  // converge), joined, when any run of the sweep has them.
  const bool anyWarnings = std::any_of(manifests.begin(), manifests.end(), [](const auto& m) {
    const auto* w = findPath(m.second, "warnings");
    return w && w->is_array() && !w->empty();
  });
  if (anyWarnings) header.push_back("warnings");
  for (std::size_t i = 0; i < header.size(); ++i) csv << (i ? "," : "") << csvField(header[i]);
  csv << "\n";

  for (const auto& [id, m] : manifests) {
    reading = (root / id / "manifest.json").string();
    const nlohmann::json config = m.value("configuration", nlohmann::json::object());
    std::size_t repeats = 0;
    const nlohmann::json* samples = stageSamples(m);
    if (const auto* s = findPath(*samples, "total"); s && s->is_array()) repeats = s->size();
    // Cells per propagation iteration: every cascade level's (one level without cascades).
    std::string cells;
    const auto cellsOf = [](const nlohmann::json& counts) {
      long long product = 1;
      for (const auto& v : counts) product *= v.get<long long>();
      return product;
    };
    if (const auto* levels = findPath(m, "cascade_levels"); levels && levels->is_array()) {
      long long total = 0;
      for (const auto& level : *levels) total += cellsOf(level.at("cells"));
      cells = std::to_string(total);
    } else if (const auto* c = findPath(config, "grid.resolved.cells"); c && c->is_array()) {
      cells = std::to_string(cellsOf(*c));
    }
    for (std::size_t r = 0; r < repeats; ++r) {
      std::vector<std::string> row = {id, names.count(id) ? names[id] : "", std::to_string(r), id};
      for (const std::string& k : params) row.push_back(jsonText(findPath(config, k)));
      const auto sample = [&](const nlohmann::json* bySource, const std::string& s) {
        const nlohmann::json* v = nullptr;
        if (bySource && bySource->contains(s) && (*bySource)[s].is_array() && r < (*bySource)[s].size())
          v = &(*bySource)[s][r];
        row.push_back(jsonText(v));
      };
      for (const std::string& s : stages) sample(samples, s);
      const auto* clock = findPath(m, "timing.clock");
      for (const std::string& s : stages) row.push_back(jsonText(clock ? findPath(*clock, s) : nullptr));
      for (const std::string& s : stages) sample(findPath(m, "timing.samples.wall_ms"), s);
      row.push_back(jsonText(findPath(m, "libraries.gl_renderer")));
      row.push_back(jsonText(findPath(m, "host.cpu")));
      row.push_back(jsonText(findPath(m, "memory_bytes.total")));
      for (const std::string& g : memoryGroups) {
        const auto* groups = findPath(m, "memory_bytes");
        row.push_back(jsonText(groups && groups->contains(g) ? &(*groups)[g] : nullptr));
      }
      row.push_back(cells);
      const std::map<std::string, double>& work = workById[id];
      for (const std::string& k : workKeys) {
        const auto found = work.find(k);
        const nlohmann::json value = found == work.end() ? nlohmann::json() : nlohmann::json(found->second);
        row.push_back(jsonText(found == work.end() ? nullptr : &value));
      }
      // A sequence's rows are its frames, in order: each gets its frame's figures (the run's
      // are their mean over frames).
      const nlohmann::json* frame = nullptr;
      if (const auto* records = findPath(m, "sequence.frame_records");
          records && records->is_array() && r < records->size())
        frame = &(*records)[r];
      for (const auto& [pair, metric] : metrics) {
        const nlohmann::json* v = nullptr;
        if (const auto* c = frame ? findPath(*frame, "reference.comparison") : nullptr;
            c && c->contains(pair) && (*c)[pair].contains("metrics") &&
            (*c)[pair]["metrics"].contains(metric))
          v = &(*c)[pair]["metrics"][metric];
        else if (const auto* c = findPath(m, "reference.comparison"); c && c->contains(pair)) {
          const nlohmann::json& entry = (*c)[pair];
          if (entry.contains("metrics") && entry["metrics"].contains(metric)) v = &entry["metrics"][metric];
        }
        row.push_back(jsonText(v));
      }
      for (const std::string& column : figureColumns) {
        const auto& figures = figuresById[id];
        const auto found = figures.find(column);
        row.push_back(found == figures.end() ? "" : nlohmann::json(found->second).dump());
      }
      if (!temporalColumns.empty()) {
        row.push_back(jsonText(frame ? findPath(*frame, "temporal.at_rest") : nullptr));
        for (const std::string& column : temporalColumns)
          row.push_back(jsonText(frame ? findPath(*frame, column) : nullptr));
      }
      if (anyWarnings) {
        std::string joined;
        if (const auto* w = findPath(m, "warnings"); w && w->is_array())
          for (const auto& warning : *w)
            if (warning.is_string()) joined += (joined.empty() ? "" : "; ") + warning.get<std::string>();
        row.push_back(joined);
      }
      for (std::size_t i = 0; i < row.size(); ++i) csv << (i ? "," : "") << csvField(row[i]);
      csv << "\n";
      ++result.rows;
    }
  }
  writeTextAtomically((root / "summary.csv").string(), csv.str());
  return result;
}

}  // namespace

SummaryResult writeSweepSummary(const std::string& dir) {
  std::string reading = dir;
  try {
    return summarise(dir, reading);
  } catch (const nlohmann::json::exception& e) {
    throw Error(reading + ": not what lpvlab writes there (" + e.what() +
                "); rerun that configuration, or delete the file");
  }
}

}  // namespace lpvlab

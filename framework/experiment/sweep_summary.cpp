#include "framework/experiment/sweep_summary.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "framework/core/error.h"
#include "framework/experiment/json_path.h"
#include "framework/experiment/work_columns.h"
#include "framework/core/atomic_file.h"
#include "framework/pipeline/pipeline.h"

namespace lpvlab {

namespace fs = std::filesystem;

namespace {

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

// `value` with every array left out, objects kept (nested ones too).
nlohmann::json withoutArrays(const nlohmann::json& value) {
  if (!value.is_object()) return value;
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, child] : value.items())
    if (!child.is_array()) out[key] = withoutArrays(child);
  return out;
}

// A manifest's per-repeat stage times (timing.samples.stage_ms; "gpu_ms" in manifests written
// before stage times were labelled by their clock, which have no timing.clock), or nullptr.
const nlohmann::json* stageSamples(const nlohmann::json& manifest) {
  if (const auto* s = findPath(manifest, "timing.samples.stage_ms")) return s;
  return findPath(manifest, "timing.samples.gpu_ms");
}

// What sweep.json says: the swept keys, and each recorded configuration's name by id.
struct SweepIndex {
  std::vector<std::string> swept;
  std::map<std::string, std::string> names;
};

SweepIndex readIndex(const fs::path& root, std::string& reading) {
  // Without sweep.json the directory is a run's, or a parent of unrelated runs: a summary of it
  // would be empty or a mixture.
  if (!fs::exists(root / "sweep.json"))
    throw Error(root.string() + ": not a sweep directory (no sweep.json, which `lpvlab sweep FILE "
                "--out DIR` writes)" +
                (fs::exists(root / "manifest.json") ? "; it holds a single run's manifest.json" : ""));
  reading = (root / "sweep.json").string();
  const nlohmann::json index = readJson(root / "sweep.json");
  SweepIndex out;
  for (const auto& k : index.value("swept_keys", nlohmann::json::array())) out.swept.push_back(k.get<std::string>());
  for (const auto& c : index.value("configurations", nlohmann::json::array()))
    out.names[c.value("id", "")] = c.value("name", "");
  return out;
}

using Manifests = std::vector<std::pair<std::string, nlohmann::json>>;

// The manifests of the recorded configurations that have timed frames, by id (sorted); every
// other directory is sorted into `result` as foreign, incomplete or dropped.
Manifests readManifests(const fs::path& root, const SweepIndex& index, SummaryResult& result,
                        std::string& reading) {
  std::vector<fs::path> subdirs;
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.is_directory() && entry.path().filename() != "configs" && entry.path().filename() != "logs")
      subdirs.push_back(entry.path());
  std::sort(subdirs.begin(), subdirs.end());
  Manifests manifests;
  for (const fs::path& sub : subdirs) {
    const std::string id = sub.filename().string();
    if (!index.names.count(id)) {
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
    const auto* total = samples ? findPath(*samples, kTotalTime) : nullptr;
    if (!total || !total->is_array() || total->empty()) {
      result.dropped.push_back({id, "its manifest.json has no timing.samples.stage_ms.total"});
      continue;
    }
    manifests.push_back({id, std::move(manifest)});
    result.complete.push_back(id);
  }
  return manifests;
}

// The columns beyond the fixed ones: what any of the manifests has, each set sorted.
struct Columns {
  std::vector<std::string> params;  // the swept keys, then those the manifests name (summary_keys)
  // The stages in the order the runs ran them (timing.stage_order: a merge of every manifest's,
  // first seen first), then any a manifest has without an order (older manifests), sorted.
  std::vector<std::string> stages;
  std::set<std::string> memoryGroups, workKeys, temporal, figures;
  std::set<std::pair<std::string, std::string>> metrics;  // pair, metric
  bool warnings = false;
  // Per id: the work counts (workColumns) and the figures beside the timings: another indirect
  // method's statistics, each number outside arrays as method.<path> (e.g.
  // method.clamp.removed_fraction; arrays, such as a solver's convergence log, stay in the
  // manifest), and the particles' counts summed over the systems (particles.alive at frame 0,
  // particles.capacity, particles.triangles).
  std::map<std::string, std::map<std::string, double>> workById, figuresById;

  void add(const std::string& id, const nlohmann::json& m);
};

void Columns::add(const std::string& id, const nlohmann::json& m) {
  if (const auto* statistics = findPath(m, "indirect_method.statistics"); statistics) {
    const nlohmann::json flat = withoutArrays(*statistics).flatten();  // "/clamp/c" -> value
    for (const auto& [path, value] : flat.items())
      if (value.is_number()) {
        std::string column = "method" + path;
        std::replace(column.begin(), column.end(), '/', '.');
        figuresById[id][column] = value.get<double>();
        figures.insert(column);
      }
  }
  if (const auto* particles = findPath(m, "particles"); particles && particles->is_array())
    for (const auto& system : *particles)
      for (const auto& [figure, key] : {std::pair{"alive", "alive_at_frame_0"},
                                        std::pair{"capacity", "capacity"},
                                        std::pair{"triangles", "triangles"}}) {
        const std::string column = std::string("particles.") + figure;
        figuresById[id][column] += system.at(key).get<double>();
        figures.insert(column);
      }
  workById[id] = workColumns(m);
  for (const auto& [key, _] : workById[id]) workKeys.insert(key);
  if (const auto* g = findPath(m, "memory_bytes"); g && g->is_object())
    for (const auto& [group, _] : g->items())
      if (group != "total") memoryGroups.insert(group);
  const auto addStage = [&](const std::string& stage) {
    if (std::find(stages.begin(), stages.end(), stage) == stages.end()) stages.push_back(stage);
  };
  if (const auto* order = findPath(m, "timing.stage_order"); order && order->is_array())
    for (const auto& stage : *order)
      if (stage.is_string()) addStage(stage.get<std::string>());
  for (const nlohmann::json* s : {stageSamples(m), findPath(m, "timing.samples.wall_ms")})
    if (s && s->is_object())
      for (const auto& [stage, _] : s->items()) addStage(stage);
  // A sequence's temporal figures (sequence_temporal.h): its frames' relative change and error.
  if (const auto* records = findPath(m, "sequence.frame_records"); records && records->is_array())
    for (const auto& record : *records)
      if (const auto* t = findPath(record, "temporal"); t && t->is_object())
        for (const char* group : {"change", "error"})
          if (const auto* g = findPath(*t, group); g && g->is_object())
            for (const auto& [name, _] : g->items())
              temporal.insert(std::string("temporal.") + group + "." + name + ".relative");
  if (const auto* c = findPath(m, "reference.comparison"); c && c->is_object())
    for (const auto& [pair, value] : c->items())
      if (value.is_object() && value.contains("metrics") && value["metrics"].is_object())
        for (const auto& [metric, _] : value["metrics"].items()) metrics.insert({pair, metric});
  // A run's warnings (run_outputs.h's resultWarnings: a black image, a solve that did not
  // converge): a column when any run of the sweep has them.
  if (const auto* w = findPath(m, "warnings"); w && w->is_array() && !w->empty()) warnings = true;
}

// Merges a run's summary_keys (run_outputs.h: the keys that tell its configuration apart, in its
// order) into `params`, whose first `swept` are the swept keys: a new key goes right after the
// key before it in the run's list (swept keys skipped), so the order of every run is kept, e.g.
// another method's [method, scene] and LPV's [method, its strategies..., scene] give LPV's.
void mergeSummaryKeys(const nlohmann::json& keys, std::size_t swept, std::vector<std::string>& params) {
  std::string previous;  // the run's last key that is not swept
  for (const auto& entry : keys) {
    const std::string key = entry.get<std::string>();
    const auto at = std::find(params.begin(), params.end(), key);
    if (at != params.end()) {
      if (std::size_t(at - params.begin()) >= swept) previous = key;
      continue;
    }
    const auto after = previous.empty() ? params.end() : std::find(params.begin(), params.end(), previous);
    params.insert(after == params.end() ? params.end() : after + 1, key);
    previous = key;
  }
}

Columns columnsOf(const SweepIndex& index, const Manifests& manifests, const fs::path& root,
                  std::string& reading) {
  Columns columns;
  columns.params = index.swept;
  for (const auto& [id, m] : manifests) {
    reading = (root / id / "manifest.json").string();
    columns.add(id, m);
    if (const auto* keys = findPath(m, "summary_keys"); keys && keys->is_array())
      mergeSummaryKeys(*keys, index.swept.size(), columns.params);
  }
  // The sums after every stage of every run: the method's stages, the shared ones, the total.
  for (const char* sum : {kMethodTime, kSharedTime, kTotalTime}) {
    const auto at = std::find(columns.stages.begin(), columns.stages.end(), sum);
    if (at == columns.stages.end()) continue;
    columns.stages.erase(at);
    columns.stages.push_back(sum);
  }
  return columns;
}

std::vector<std::string> headerOf(const Columns& c) {
  std::vector<std::string> header = {"config_id", "config_name", "repeat", "run_dir"};
  for (const std::string& k : c.params) header.push_back("param." + k);
  // Each stage's time by its clock, and the clock (where the stage ran): gl_timer_query on the
  // GL renderer, cpu_wall_clock on the CPU; both named in timed_on.*.
  for (const std::string& s : c.stages) header.push_back("time." + s + ".ms");
  for (const std::string& s : c.stages) header.push_back("time." + s + ".clock");
  for (const std::string& s : c.stages) header.push_back("wall_ms." + s);
  for (const char* fixed : {"timed_on.gl", "timed_on.cpu", "memory_bytes"}) header.push_back(fixed);
  for (const std::string& g : c.memoryGroups) header.push_back("memory_bytes." + g);
  header.push_back("cells");
  for (const std::string& k : c.workKeys) header.push_back(k);
  for (const auto& [pair, metric] : c.metrics) header.push_back("metric." + pair + "." + metric);
  for (const std::string& column : c.figures) header.push_back(column);
  if (!c.temporal.empty()) header.push_back("temporal.at_rest");
  for (const std::string& column : c.temporal) header.push_back(column);
  if (c.warnings) header.push_back("warnings");
  return header;
}

// Cells per propagation iteration: every cascade level's (one level without cascades).
std::string cellsOf(const nlohmann::json& m) {
  const auto product = [](const nlohmann::json& counts) {
    long long p = 1;
    for (const auto& v : counts) p *= v.get<long long>();
    return p;
  };
  if (const auto* levels = findPath(m, "cascade_levels"); levels && levels->is_array()) {
    long long total = 0;
    for (const auto& level : *levels) total += product(level.at("cells"));
    return std::to_string(total);
  }
  if (const auto* c = findPath(m, "configuration.grid.resolved.cells"); c && c->is_array())
    return std::to_string(product(*c));
  return "";
}

// A metric of repeat `frame`'s record (a sequence's frames each have theirs), else the run's.
const nlohmann::json* metricOf(const nlohmann::json& m, const nlohmann::json* frame,
                               const std::string& pair, const std::string& metric) {
  for (const nlohmann::json* source : {frame, &m}) {
    const auto* c = source ? findPath(*source, "reference.comparison") : nullptr;
    if (c && c->contains(pair) && (*c)[pair].contains("metrics") && (*c)[pair]["metrics"].contains(metric))
      return &(*c)[pair]["metrics"][metric];
  }
  return nullptr;
}

// Repeat r's row of one manifest, in headerOf's order.
std::vector<std::string> rowOf(const Columns& c, const std::string& id, const std::string& name,
                               const nlohmann::json& m, std::size_t r, const std::string& cells) {
  const nlohmann::json config = m.value("configuration", nlohmann::json::object());
  std::vector<std::string> row = {id, name, std::to_string(r), id};
  for (const std::string& k : c.params) row.push_back(jsonText(findPath(config, k)));
  const auto sample = [&](const nlohmann::json* bySource, const std::string& s) {
    const nlohmann::json* v = nullptr;
    if (bySource && bySource->contains(s) && (*bySource)[s].is_array() && r < (*bySource)[s].size())
      v = &(*bySource)[s][r];
    row.push_back(jsonText(v));
  };
  for (const std::string& s : c.stages) sample(stageSamples(m), s);
  const auto* clock = findPath(m, "timing.clock");
  for (const std::string& s : c.stages) row.push_back(jsonText(clock ? findPath(*clock, s) : nullptr));
  for (const std::string& s : c.stages) sample(findPath(m, "timing.samples.wall_ms"), s);
  for (const char* path : {"libraries.gl_renderer", "host.cpu", "memory_bytes.total"})
    row.push_back(jsonText(findPath(m, path)));
  const auto* groups = findPath(m, "memory_bytes");
  for (const std::string& g : c.memoryGroups)
    row.push_back(jsonText(groups && groups->contains(g) ? &(*groups)[g] : nullptr));
  row.push_back(cells);
  const auto number = [](const std::map<std::string, double>& values, const std::string& key) {
    const auto found = values.find(key);
    return found == values.end() ? std::string() : nlohmann::json(found->second).dump();
  };
  for (const std::string& k : c.workKeys) row.push_back(number(c.workById.at(id), k));
  // A sequence's rows are its frames, in order: each gets its frame's figures (the run's are
  // their mean over frames).
  const nlohmann::json* frame = nullptr;
  if (const auto* records = findPath(m, "sequence.frame_records");
      records && records->is_array() && r < records->size())
    frame = &(*records)[r];
  for (const auto& [pair, metric] : c.metrics) row.push_back(jsonText(metricOf(m, frame, pair, metric)));
  const auto figures = c.figuresById.find(id);
  for (const std::string& column : c.figures)
    row.push_back(figures == c.figuresById.end() ? "" : number(figures->second, column));
  if (!c.temporal.empty()) {
    row.push_back(jsonText(frame ? findPath(*frame, "temporal.at_rest") : nullptr));
    for (const std::string& column : c.temporal)
      row.push_back(jsonText(frame ? findPath(*frame, column) : nullptr));
  }
  if (c.warnings) {
    std::string joined;
    if (const auto* w = findPath(m, "warnings"); w && w->is_array())
      for (const auto& warning : *w)
        if (warning.is_string()) joined += (joined.empty() ? "" : "; ") + warning.get<std::string>();
    row.push_back(joined);
  }
  return row;
}

void writeLine(std::ostringstream& csv, const std::vector<std::string>& fields) {
  for (std::size_t i = 0; i < fields.size(); ++i) csv << (i ? "," : "") << csvField(fields[i]);
  csv << "\n";
}

// writeSweepSummary's body: `reading` names the file whose values it reads, for the error when
// one has an unexpected structure (a string where a number belongs, say: nlohmann's type errors).
SummaryResult summarise(const std::string& dir, std::string& reading) {
  const fs::path root(dir);
  if (!fs::is_directory(root)) throw Error(dir + ": not a directory");
  const SweepIndex index = readIndex(root, reading);
  SummaryResult result;
  const Manifests manifests = readManifests(root, index, result, reading);
  const Columns columns = columnsOf(index, manifests, root, reading);
  std::ostringstream csv;
  writeLine(csv, headerOf(columns));
  for (const auto& [id, m] : manifests) {
    reading = (root / id / "manifest.json").string();
    const std::size_t repeats = findPath(*stageSamples(m), kTotalTime)->size();
    const std::string cells = cellsOf(m);
    for (std::size_t r = 0; r < repeats; ++r, ++result.rows)
      writeLine(csv, rowOf(columns, id, index.names.at(id), m, r, cells));
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

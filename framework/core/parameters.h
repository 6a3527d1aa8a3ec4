#pragma once
// Parameters read from an experiment file (TOML), tracked the way pbrt-v4 and Mitsuba 3 track
// theirs: every key a strategy or stage asks for is remembered, and finish() turns any key that
// was never asked for into an error naming the file, the line and the keys that are valid. A
// typo therefore never silently runs the default. Values out of range are errors, never clamped.
//
// Every value read (given or defaulted) is recorded in resolved(), which goes into the run's
// manifest, so a run can be repeated from its manifest alone.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

namespace lpvlab {

template <class T>
struct Range {
  std::optional<T> min;            // inclusive
  std::optional<T> max;            // inclusive
};

class Params {
public:
  // `table` must outlive this object; `file` is how messages name the source, `section` the
  // dotted path of this table in the file ("" for the root).
  Params(const toml::table& table, std::string file, std::string section = "");

  // A value with a default. Supported T: bool, int, double, float, std::string, glm::vec3,
  // glm::ivec3 (arrays of three numbers), std::vector<std::string>.
  template <class T>
  T get(std::string_view key, const T& defaultValue, Range<T> range = {});
  // A value that must be present.
  template <class T>
  T require(std::string_view key, Range<T> range = {});
  // Whether the key is present (marks it as known, so it is not reported as unused).
  bool has(std::string_view key);
  // A value restricted to a set of names (strategy names, enums); the error lists them.
  std::string getChoice(std::string_view key, const std::string& defaultValue,
                        const std::vector<std::string>& choices);

  // A sub-table (e.g. [propagation]); nullopt when absent. An absent table reads as empty.
  Params table(std::string_view key);
  // Arrays of tables ([[lights]]).
  std::vector<Params> tables(std::string_view key);
  // The whole file's root table, whose keys are tracked together with this one's: for a reader
  // whose parameters span several tables (LPV's method reads [indirect] and its stages' tables).
  // The root itself for a root.
  Params document() const;

  // Throws an Error for every key present in the table that nobody asked for.
  void finish() const;

  // Every value asked for, given or defaulted, as JSON (nested for sub-tables).
  nlohmann::json resolved() const;

  const std::string& file() const { return state_->file; }
  std::string where(std::string_view key) const;  // "file:line: key 'section.key'"

private:
  struct State {
    const toml::table* table;
    std::string file;
    std::string section;
    std::vector<std::string> asked;           // keys asked for, in order
    nlohmann::json resolved = nlohmann::json::object();
    std::vector<std::pair<std::string, Params>> children;
    std::weak_ptr<State> parent;  // weak: the parent owns its children
  };
  explicit Params(std::shared_ptr<State> state) : state_(std::move(state)) {}
  std::shared_ptr<State> state_;  // Params is a cheap handle: copies share tracking state

  const toml::node* lookup(std::string_view key);
  std::string dotted(std::string_view key) const;
  template <class T>
  T convert(const toml::node& node, std::string_view key) const;
  template <class T>
  void checkRange(const T& value, const Range<T>& range, std::string_view key) const;
};

// Applies "a.b.c=value" overrides (value parsed as a TOML value, falling back to a string) to a
// table, creating sub-tables as needed. "name[i]" in the path is table i of an existing array of
// tables ("particles[0].emitters[0].rate=400"). Used for command-line overrides and sweeps.
void applyOverride(toml::table& root, std::string_view assignment);

// Reads a TOML file; a syntax error names the file, line and column.
toml::table readTomlFile(const std::string& path);

}  // namespace lpvlab

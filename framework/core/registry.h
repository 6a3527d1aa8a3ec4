#pragma once
// A static, in-process registry of named strategies per stage (injection, propagation, ...).
// A variant file registers itself with LPVLAB_REGISTER(Interface, "name", "description", Type);
// the experiment file's `type = "name"` is the file's name, so one search finds it. Asking for an
// unknown name is an error that lists the known ones.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/core/parameters.h"

namespace lpvlab {

template <class Interface>
class Registry {
public:
  using Factory = std::function<std::unique_ptr<Interface>(Params&)>;
  struct Entry {
    std::string description;
    Factory factory;
    // Top-level tables of the experiment file it reads beyond its own (empty for most: a
    // strategy reads its stage's table, a method [indirect]). LPV's method reads its stages'.
    std::vector<std::string> tables;
  };

  static Registry& instance() {
    static Registry registry;
    return registry;
  }

  bool add(const std::string& name, std::string description, Factory factory,
           std::vector<std::string> tables = {}) {
    entries_[name] = Entry{std::move(description), std::move(factory), std::move(tables)};
    return true;
  }

  // Creates the strategy named by `params`'s `type` key (or `defaultName`), reading its
  // parameters from the same table. Interface must have setRegisteredName(std::string).
  std::unique_ptr<Interface> create(Params& params, const std::string& defaultName) const {
    const std::string name = params.getChoice("type", defaultName, names());
    std::unique_ptr<Interface> strategy = entries_.at(name).factory(params);
    strategy->setRegisteredName(name);
    return strategy;
  }

  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& [name, entry] : entries_) out.push_back(name);
    return out;
  }
  const std::map<std::string, Entry>& entries() const { return entries_; }

private:
  std::map<std::string, Entry> entries_;
};

#define LPVLAB_CONCAT_INNER(a, b) a##b
#define LPVLAB_CONCAT(a, b) LPVLAB_CONCAT_INNER(a, b)
#define LPVLAB_REGISTER(Interface, name, description, Type)                                  \
  static const bool LPVLAB_CONCAT(lpvlabRegistered_, __LINE__) =                            \
      ::lpvlab::Registry<Interface>::instance().add(                                        \
          name, description,                                                                \
          [](::lpvlab::Params& params) -> std::unique_ptr<Interface> {                       \
            return std::make_unique<Type>(params);                                          \
          })
// The same, for an implementation that also reads the experiment file's top-level tables named
// after the description, e.g. LPVLAB_REGISTER_READING(IndirectMethod, "lpv", "...", Lpv, "grid").
#define LPVLAB_REGISTER_READING(Interface, name, description, Type, ...)                     \
  static const bool LPVLAB_CONCAT(lpvlabRegistered_, __LINE__) =                            \
      ::lpvlab::Registry<Interface>::instance().add(                                        \
          name, description,                                                                \
          [](::lpvlab::Params& params) -> std::unique_ptr<Interface> {                       \
            return std::make_unique<Type>(params);                                          \
          },                                                                                \
          std::vector<std::string>{__VA_ARGS__})

}  // namespace lpvlab

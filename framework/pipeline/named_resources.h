#pragma once
// Named resources: the data one strategy makes for another within a frame, beyond the light grid
// every stage shares (the geometry volume, its surfaces' albedo, the VPLs' normals, ...).
//
// A strategy declares what it produces and consumes (Strategy::declare, with a ResourceUses);
// the composition check (composition.h) refuses a consumed resource that no strategy produces,
// naming both, and the pipeline then allocates each resource that is both produced and used,
// once per cascade level, and clears it before each frame's occlusion. A resource produced but
// used by nobody is not allocated, and its producer, seeing that (Requirements::has), skips it.
//
// A resource type T is declared by its key, next to the type:
//   inline constexpr ResourceKey<NormalGrid> kNormalGrid{"normal_grid", "the VPLs' ..."};
// T is constructed from (const ResourceSetup&, the producer's arguments to produces(), ...), and
// has memoryBytes() and clear(); one that follows the light grid's placement has
// place(const GridGeometry& lightGrid), which the pipeline calls whenever it moves the level.
// Adding a resource is adding its type and key; the framework never names one.

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <typeindex>
#include <utility>
#include <vector>

#include "framework/math/grid_geometry.h"

namespace lpvlab {

enum class ComputeBackend;

// What allocating a resource of one light-grid level needs.
struct ResourceSetup {
  const GridGeometry& grid;  // the level's light grid (its placement, its cell counts)
  int shOrder = 1;
  ComputeBackend backend;
};

template <class T>
struct ResourceKey {
  std::string_view name;         // as messages and the manifest's memory report show it
  std::string_view description;  // what it holds, for messages
};

// A resource of one level, whatever its type.
class AnyResource {
public:
  virtual ~AnyResource() = default;
  virtual void* get() = 0;
  virtual std::type_index type() const = 0;
  virtual std::size_t memoryBytes() const = 0;
  virtual void clear() = 0;
  virtual void place(const GridGeometry& lightGrid) = 0;
};

template <class T>
class StoredResource final : public AnyResource {
public:
  template <class... Args>
  explicit StoredResource(const ResourceSetup& setup, const Args&... args) : value_(setup, args...) {}
  void* get() override { return &value_; }
  std::type_index type() const override { return typeid(T); }
  std::size_t memoryBytes() const override { return value_.memoryBytes(); }
  void clear() override { value_.clear(); }
  void place(const GridGeometry& lightGrid) override {
    if constexpr (requires { value_.place(lightGrid); }) value_.place(lightGrid);
  }

private:
  T value_;
};

using ResourceAllocator = std::function<std::unique_ptr<AnyResource>(const ResourceSetup&)>;

// One strategy's (or the experiment's) declared uses of resources.
class ResourceUses {
public:
  enum class Kind {
    Produces,  // the strategy writes it, if some other strategy uses it
    Consumes,  // the strategy cannot run without it: refused if nobody produces it
    Reads,     // the strategy uses it if some strategy produces it (e.g. occlusion by a GV)
  };
  struct Use {
    std::string name, description;
    Kind kind;
    std::string why;             // for Consumes: what needs it (for the refusal), or "" 
    ResourceAllocator allocate;  // for Produces: how the pipeline makes it
  };

  // `args` are given to T's constructor after the ResourceSetup (e.g. a GV's first occluded
  // iteration, which its producer fixes for the run).
  template <class T, class... Args>
  void produces(const ResourceKey<T>& key, Args... args) {
    uses_.push_back({std::string(key.name), std::string(key.description), Kind::Produces, "",
                     [=](const ResourceSetup& setup) -> std::unique_ptr<AnyResource> {
                       return std::make_unique<StoredResource<T>>(setup, args...);
                     }});
  }
  // `why`: the parameter or purpose that needs it, named when nobody produces it.
  template <class T>
  void consumes(const ResourceKey<T>& key, std::string why = "") {
    uses_.push_back(
        {std::string(key.name), std::string(key.description), Kind::Consumes, std::move(why), {}});
  }
  template <class T>
  void reads(const ResourceKey<T>& key) {
    uses_.push_back({std::string(key.name), std::string(key.description), Kind::Reads, "", {}});
  }
  const std::vector<Use>& uses() const { return uses_; }

private:
  std::vector<Use> uses_;
};

// The resources of one level, by name: owned (the pipeline's) or borrowed (a test's own).
class ResourceTable {
public:
  // Borrows `value` (it must outlive the table).
  template <class T>
  void put(const ResourceKey<T>& key, T& value) {
    entries_.insert_or_assign(std::string(key.name), Entry{typeid(T), &value, nullptr});
  }
  void adopt(const std::string& name, std::unique_ptr<AnyResource> resource);

  // The resource, or null when the run has none of that name.
  template <class T>
  T* find(const ResourceKey<T>& key) const {
    const auto it = entries_.find(key.name);
    if (it == entries_.end()) return nullptr;
    checkType(key.name, it->second.type, typeid(T));
    return static_cast<T*>(it->second.value);
  }
  // The resource; an Error naming it when the run has none (a strategy that consumes it was
  // given a table the pipeline did not make, e.g. in a test).
  template <class T>
  T& get(const ResourceKey<T>& key) const {
    if (T* value = find(key)) return *value;
    throwMissing(key.name);
  }

  void clear();                                  // every owned resource, before a frame
  void place(const GridGeometry& lightGrid);     // every owned resource, when the level moves
  std::map<std::string, std::size_t> memoryBytes() const;  // owned ones, by name

private:
  struct Entry {
    std::type_index type;
    void* value;
    std::unique_ptr<AnyResource> owned;
  };
  static void checkType(std::string_view name, std::type_index stored, std::type_index asked);
  [[noreturn]] static void throwMissing(std::string_view name);
  std::map<std::string, Entry, std::less<>> entries_;
};

}  // namespace lpvlab

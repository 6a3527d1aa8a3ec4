#include "framework/pipeline/named_resources.h"

#include "framework/core/error.h"

namespace lpvlab {

void ResourceTable::adopt(const std::string& name, std::unique_ptr<AnyResource> resource) {
  const std::type_index type = resource->type();
  void* value = resource->get();
  entries_.insert_or_assign(name, Entry{type, value, std::move(resource)});
}

void ResourceTable::clear() {
  for (auto& [name, entry] : entries_)
    if (entry.owned) entry.owned->clear();
}

void ResourceTable::place(const GridGeometry& lightGrid) {
  for (auto& [name, entry] : entries_)
    if (entry.owned) entry.owned->place(lightGrid);
}

std::map<std::string, std::size_t> ResourceTable::memoryBytes() const {
  std::map<std::string, std::size_t> bytes;
  for (const auto& [name, entry] : entries_)
    if (entry.owned) bytes[name] = entry.owned->memoryBytes();
  return bytes;
}

void ResourceTable::checkType(std::string_view name, std::type_index stored, std::type_index asked) {
  if (stored != asked)
    throw Error("resource '" + std::string(name) + "' is stored as " + stored.name() +
                " but was asked for as " + asked.name() + ": two keys share the name");
}

void ResourceTable::throwMissing(std::string_view name) {
  throw Error("resource '" + std::string(name) +
              "' was consumed, but the frame has none: no strategy of the composition produced it");
}

}  // namespace lpvlab

#pragma once
// Every registered strategy of every stage with what it declares (named_resources.h) with its
// default parameters: what `lpvlab list` prints, and where the composition check looks for the
// strategies that would produce a resource nobody in a composition produces.

#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/pipeline/named_resources.h"

namespace lpvlab {

struct CatalogueEntry {
  std::string stage;  // "injection", "occlusion", "propagation", "rendering"
  std::string name;   // the registered name ([<stage>] type = "<name>")
  std::string description;
  ResourceUses uses;  // with the default parameters (a parameter may change them)
  std::string cpuRefusal;  // why it has no CPU kernel with its defaults alone, or "" if it has one
  std::string drawsWithGl;  // what it draws with GL whatever the backend (no run without GL), or ""
  std::string parameters;  // "key = value, ..." as the strategy reads them by default
  nlohmann::json defaults;  // the same as an object: key -> default value
};

// In pipeline order, each stage's strategies by name.
std::vector<CatalogueEntry> strategyCatalogue();

// Every registered indirect method, LPV among them ([indirect] method, indirect_method.h), with
// what it declares with its parameters' defaults (LPV: the default composition).
struct MethodCatalogueEntry {
  std::string name;
  std::string description;
  std::string parameters;  // "key = value, ..." as the method reads them by default
  nlohmann::json defaults;  // the same as an object: key -> default value
  std::vector<std::string> stages;  // its timed stages, in the order it runs them
  std::set<std::string> consumes;   // the raster inputs it reads (raster_inputs.h)
  std::vector<std::string> summaryKeys;  // its configuration keys a sweep's summary shows
};
std::vector<MethodCatalogueEntry> methodCatalogue();

// `[<stage>] type = "<name>"` of every registered strategy that produces `resource` with its
// default parameters.
std::vector<std::string> producersOf(const std::string& resource);

}  // namespace lpvlab

#pragma once
// Every registered strategy of every stage with what it declares (named_resources.h) with its
// default parameters: what `lpvlab list` prints, and where the composition check looks for the
// strategies that would produce a resource nobody in a composition produces.

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
  std::string parameters;  // "key = value, ..." as the strategy reads them by default
  nlohmann::json defaults;  // the same as an object: key -> default value
};

// In pipeline order, each stage's strategies by name.
std::vector<CatalogueEntry> strategyCatalogue();

// Every registered indirect method other than LPV ([indirect] method, indirect_method.h) with its
// parameters' defaults (a JSON object of key -> value).
struct MethodCatalogueEntry {
  std::string name;
  std::string description;
  std::string parameters;  // "key = value, ..." as the method reads them by default
  nlohmann::json defaults;  // the same as an object: key -> default value
  std::vector<std::string> stages;  // its timed stages, in the order it runs them
};
std::vector<MethodCatalogueEntry> methodCatalogue();

// `[<stage>] type = "<name>"` of every registered strategy that produces `resource` with its
// default parameters.
std::vector<std::string> producersOf(const std::string& resource);

}  // namespace lpvlab

#pragma once
// Where a result came from: the source revision, the libraries it was built with, the machine
// and the time. Written into every run's manifest so a figure can be traced to what made it.

#include <nlohmann/json.hpp>
#include <string>

namespace lpvlab {

// "<sha>" of the checkout containing `sourceDir`, "<sha>-dirty" when it has uncommitted or
// untracked changes (variants are globbed, so an untracked file changes the build), "unknown"
// when it isn't a git checkout or git is missing.
std::string gitRevision(const std::string& sourceDir);

// This lpvlab's revision: gitRevision of its source tree when it runs from its build tree, else
// the REVISION file of its data folder (install_layout.h), which scripts/bundle.sh and
// `cmake --install` write from the source tree; "unknown" without either.
std::string lpvlabRevision();

// Versions of the libraries available to this module and of the compiler, e.g.
// {"openimageio": "2.4.7", "glm": "0.9.9.8", "compiler": "GCC 12.2.0", ...}. Modules with
// more dependencies add theirs.
nlohmann::json libraryVersions();

// {"cpu": model name, "logical_cores": n, "os": PRETTY_NAME, "kernel": release, "hostname": h}.
nlohmann::json hostInfo();

// The current time in UTC, ISO 8601 to the second: "2024-05-01T12:34:56Z".
std::string utcTimestamp();

}  // namespace lpvlab

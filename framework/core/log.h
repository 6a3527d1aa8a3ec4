#pragma once
// lpvlab's messages on stderr, by level (spdlog): `-q` keeps warnings and errors, the default adds
// notes and progress (info), `-v` adds how a run was set up (debug: resolved paths, the raster
// plan, cache decisions). What a command prints on stdout (its tables, its results) is output,
// not a message, and no level hides it.
//
// The level comes from -q/-v, else from LPVLAB_LOG_LEVEL ("quiet", "normal", "verbose"), which
// the command line sets in turn, so the processes a sweep starts inherit it.

#include <string>
#include <string_view>

namespace lpvlab::log {

enum class Level { Debug, Info, Warning, Error };

void setLevel(Level level);
bool shows(Level level);  // whether messages of this level are printed

// "quiet" -> Warning, "normal" -> Info, "verbose" -> Debug; anything else: nothing.
bool levelFromName(std::string_view name, Level& out);
const char* levelName(Level level);

// Each prints one line: "lpvlab: <message>" (debug and info), "lpvlab: warning: <message>",
// "lpvlab: error: <message>".
void debug(std::string_view message);
void info(std::string_view message);
void warning(std::string_view message);
void error(std::string_view message);

}  // namespace lpvlab::log

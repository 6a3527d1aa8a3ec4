#include "framework/core/log.h"

#include <memory>

#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

namespace lpvlab::log {

namespace {

// One logger to stderr, messages as given (the prefix is ours: every error line of lpvlab starts
// "lpvlab: error: ", which tests and scripts match), flushed at once so lines interleave with
// progress in order.
spdlog::logger& logger() {
  static const std::shared_ptr<spdlog::logger> instance = [] {
    auto made = std::make_shared<spdlog::logger>("lpvlab", std::make_shared<spdlog::sinks::stderr_sink_mt>());
    made->set_pattern("%v");
    made->set_level(spdlog::level::info);
    made->flush_on(spdlog::level::trace);
    return made;
  }();
  return *instance;
}

spdlog::level::level_enum toSpdlog(Level level) {
  switch (level) {
    case Level::Debug: return spdlog::level::debug;
    case Level::Info: return spdlog::level::info;
    case Level::Warning: return spdlog::level::warn;
    case Level::Error: return spdlog::level::err;
  }
  return spdlog::level::info;
}

}  // namespace

void setLevel(Level level) { logger().set_level(toSpdlog(level)); }

bool shows(Level level) { return logger().should_log(toSpdlog(level)); }

bool levelFromName(std::string_view name, Level& out) {
  if (name == "quiet") out = Level::Warning;
  else if (name == "normal") out = Level::Info;
  else if (name == "verbose") out = Level::Debug;
  else return false;
  return true;
}

const char* levelName(Level level) {
  return level == Level::Debug ? "verbose" : level >= Level::Warning ? "quiet" : "normal";
}

void debug(std::string_view message) { logger().debug("lpvlab: {}", message); }
void info(std::string_view message) { logger().info("lpvlab: {}", message); }
void warning(std::string_view message) { logger().warn("lpvlab: warning: {}", message); }
void error(std::string_view message) { logger().error("lpvlab: error: {}", message); }

}  // namespace lpvlab::log

#include "framework/core/progress.h"

#include "framework/core/log.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace lpvlab {

namespace {
double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)),
      start_(std::chrono::steady_clock::now()),
      lastPrint_(start_),
      terminal_(isatty(fileno(stderr)) != 0) {}

std::string ProgressBar::formatSeconds(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  std::ostringstream out;
  if (s >= 3600) out << s / 3600 << "h" << (s % 3600) / 60 << "m";
  else if (s >= 60) out << s / 60 << "m" << (s % 60 < 10 ? "0" : "") << s % 60 << "s";
  else out << s << "s";
  return out.str();
}

void ProgressBar::update(double fraction, const std::string& detail,
                         std::optional<double> etaSeconds) {
  if (!log::shows(log::Level::Info)) return;  // -q: no progress
  fraction = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0);
  const double elapsed = secondsSince(start_);
  if (!terminal_ && secondsSince(lastPrint_) < 10.0) return;
  lastPrint_ = std::chrono::steady_clock::now();
  // The rate so far predicts the rest; nothing is predicted before the first measurable progress.
  const double eta = etaSeconds       ? *etaSeconds
                     : fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction
                                      : -1.0;
  const int width = 30, filled = int(std::lround(fraction * width));
  std::ostringstream line;
  line << label_ << " [" << std::string(filled, '#') << std::string(width - filled, '.') << "] "
       << int(std::lround(fraction * 100)) << "% " << detail << ", elapsed "
       << formatSeconds(elapsed) << ", ETA " << formatSeconds(eta);
  if (terminal_) std::cerr << "\r" << line.str() << "\033[K" << std::flush;
  else std::cerr << line.str() << "\n";
}

void ProgressBar::finish(const std::string& detail) {
  if (!log::shows(log::Level::Info)) return;
  std::cerr << (terminal_ ? "\r" : "") << label_ << " done: " << detail << " in "
            << formatSeconds(secondsSince(start_)) << (terminal_ ? "\033[K\n" : "\n");
}

}  // namespace lpvlab

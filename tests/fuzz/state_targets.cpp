// Fuzz targets of what lpvlab writes and reads back: a reference's state.bin, a fit's progress,
// a sweep's sweep.json and manifests. A damaged file must be an Error naming it.

#include <filesystem>
#include <string>

#include "framework/core/error.h"
#include "framework/experiment/sweep_summary.h"
#include "framework/fit/fit_checkpoint.h"
#include "framework/reference/reference_cache.h"
#include "fuzz/fuzz_targets.h"
#include "fuzz/fuzz_workspace.h"

namespace lpvlab::fuzz {

void referenceState(Bytes data, std::size_t size) {
  const std::string path = FuzzWorkspace::instance().write("state.bin", data, size);
  try {
    double seconds = 0.0;
    const Accumulator acc = loadAccumulator(path, &seconds);
    acc.images();
    acc.meanRelativeError();
  } catch (const Error&) {
  }
}

void fitProgress(Bytes data, std::size_t size) {
  // The seeds' key: "fuzz" (readFitProgress reads another fit's progress as none).
  const std::string path = FuzzWorkspace::instance().write("fit.progress.json", data, size);
  try {
    readFitProgress(path, "fuzz");
  } catch (const Error&) {
  }
}

void sweepManifests(Bytes data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string separator = "\n====\n";
  const std::size_t split = text.find(separator);
  const std::filesystem::path dir = FuzzWorkspace::instance().dir() / "sweep";
  std::filesystem::remove_all(dir);
  FuzzWorkspace::instance().write("sweep/sweep.json", text.substr(0, split));
  if (split != std::string::npos)
    FuzzWorkspace::instance().write("sweep/0123456789/manifest.json",
                                    text.substr(split + separator.size()));
  try {
    writeSweepSummary(dir.string());
  } catch (const Error&) {
  }
}

}  // namespace lpvlab::fuzz

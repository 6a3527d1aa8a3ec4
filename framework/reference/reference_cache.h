#pragma once
// Rendering references progressively and keeping them. A reference is keyed by a hash of
// everything that determines its pixels (scene content and lights, camera, resolution, tracer
// settings and seed), never by when to stop: a cached reference with enough samples is reused, one
// with too few is continued from its saved sums (deterministically: the result is the same as
// rendering all samples at once), and an interrupted rendering resumes from its last checkpoint.
//
// Layout of a cache entry, <cache>/<key>/:
//   state.bin      the Accumulator (sums and sums of squares): what resuming needs
//   images.exr     means and variances as AOVs (path_tracer.h), for metrics and for looking
//   manifest.json  key inputs, samples, seconds, relative error, paths/s, rays/s
//   lock           flock(2)ed while a process reads or renders the entry: concurrent requests
//                  for one reference (parallel sweeps, Slurm tasks) render it once
// Each is written to a temporary name and renamed, state.bin at every checkpoint.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "framework/reference/path_tracer.h"

namespace lpvlab {

// When a reference is good enough: any criterion that is set (> 0) and met stops rendering.
struct ReferenceTarget {
  std::int64_t samples = 256;     // per pixel
  double seconds = 0.0;           // total rendering time spent on this reference
  double relativeError = 0.0;     // Accumulator::meanRelativeError of `combined`
  bool any() const { return samples > 0 || seconds > 0.0 || relativeError > 0.0; }
};

struct ReferenceRequest {
  int width = 256, height = 256;
  TracerSettings tracer;
  ReferenceTarget target;
  int threads = 0;                // 0: every core this process may run on (its affinity mask)
  std::string cacheDir;           // "" = defaultCacheDir()
  double checkpointSeconds = 30.0;
  bool showProgress = true;
};

struct Reference {
  std::string key;
  std::string directory;          // the cache entry
  std::vector<NamedImage> aovs;   // means and variances (path_tracer.h)
  std::int64_t samples = 0;
  double seconds = 0.0;           // rendering time spent in total, over all sessions
  double relativeError = 0.0;
  bool reused = false;            // nothing rendered this time
  nlohmann::json manifest;
};

// env LPVLAB_CACHE_DIR, else <source tree>/.cache/references.
std::string defaultCacheDir();

std::string referenceKey(const Scene& scene, const Camera& camera, const ReferenceRequest& request);

// Returns the cached reference when it meets the target, else renders (continuing any saved state)
// until it does. Throws an Error for a request without a target or for an unusable scene.
Reference ensureReference(const Scene& scene, const Camera& camera, const ReferenceRequest& request);

// The saved sums, for tests and tools; throws an Error naming the file when it is corrupt.
void saveAccumulator(const std::string& path, const Accumulator& acc, double seconds);
Accumulator loadAccumulator(const std::string& path, double* seconds = nullptr);

}  // namespace lpvlab

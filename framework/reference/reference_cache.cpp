#include "framework/core/log.h"
#include "framework/reference/reference_cache.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "framework/core/install_layout.h"
#include "framework/core/available_cores.h"
#include "framework/core/error.h"
#include "framework/core/hash.h"
#include "framework/core/progress.h"
#include "framework/core/atomic_file.h"
#include "framework/io/provenance.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {

namespace fs = std::filesystem;

namespace {

// An exclusive flock(2) on a cache entry's lock file for the lifetime of the object.
class EntryLock {
 public:
  EntryLock(const std::string& path, const std::string& key) {
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw Error(path + ": cannot open the reference's lock file: " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) return;
    if (errno != EWOULDBLOCK) fail(path);  // no locks here (e.g. Lustre without -o flock)
    log::info("reference " + key + ": another process is rendering it; waiting");
    while (::flock(fd_, LOCK_EX) != 0)
      if (errno != EINTR) fail(path);
  }
  ~EntryLock() { ::close(fd_); }
  EntryLock(const EntryLock&) = delete;
  EntryLock& operator=(const EntryLock&) = delete;

 private:
  [[noreturn]] void fail(const std::string& path) {
    const std::string why = std::strerror(errno);
    ::close(fd_);
    throw Error(path + ": cannot lock the reference: " + why +
                " (the cache needs flock(2) across the processes that share it; docs/experiments.md)");
  }
  int fd_ = -1;
};

// Bumped whenever the tracer's estimator changes, so old references are not reused.
constexpr int kTracerVersion = 1;
constexpr char kStateMagic[8] = {'L', 'P', 'V', 'A', 'C', 'C', '1', '\0'};

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

bool targetMet(const ReferenceTarget& t, std::int64_t samples, double seconds, double error) {
  return (t.samples > 0 && samples >= t.samples) || (t.seconds > 0.0 && seconds >= t.seconds) ||
         (t.relativeError > 0.0 && samples > 1 && error <= t.relativeError);
}

// The fraction of the work done, for the progress bar: the nearest criterion wins. Relative error
// falls as 1/sqrt(samples), so the samples it needs are samples * (error / target)^2.
double progressFraction(const ReferenceTarget& t, std::int64_t samples, double seconds, double error) {
  double f = 0.0;
  if (t.samples > 0) f = std::max(f, double(samples) / double(t.samples));
  if (t.seconds > 0.0) f = std::max(f, seconds / t.seconds);
  if (t.relativeError > 0.0 && samples > 1 && error > 0.0)
    f = std::max(f, std::min(1.0, (t.relativeError * t.relativeError) / (error * error)));
  return std::min(f, 1.0);
}

template <class T>
void writeRaw(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <class T>
void readRaw(std::istream& in, T& v) {
  in.read(reinterpret_cast<char*>(&v), sizeof(T));
}

void writeDoubles(std::ostream& out, const std::vector<double>& v) {
  const std::uint64_t n = v.size();
  writeRaw(out, n);
  out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(n * sizeof(double)));
}
void readDoubles(std::istream& in, std::vector<double>& v, std::size_t expected, const std::string& path) {
  std::uint64_t n = 0;
  readRaw(in, n);
  if (!in || n != expected) throw Error(path + ": corrupt reference state (array size)");
  v.resize(n);
  in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(double)));
}

}  // namespace

std::string defaultCacheDir() {
  if (const char* env = std::getenv("LPVLAB_CACHE_DIR")) return env;
  // A build tree keeps its references in the checkout; an installed or bundled lpvlab, whose
  // folder may be read-only or shared, in the user's cache.
  if (runsFromSourceTree()) return (fs::path(LPVLAB_SOURCE_DIR) / ".cache" / "references").string();
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return (fs::path(xdg) / "lpvlab" / "references").string();
  if (const char* home = std::getenv("HOME"); home && *home)
    return (fs::path(home) / ".cache" / "lpvlab" / "references").string();
  return (fs::temp_directory_path() / "lpvlab-references").string();
}

namespace {

// The key from the scene's hash (which reads every texel, so callers compute it once).
std::string keyFromSceneHash(const std::string& sceneContentHash, const Camera& camera,
                             const ReferenceRequest& r) {
  Hasher h;
  h.value(kTracerVersion).text(sceneContentHash);
  for (const glm::vec3& v : {camera.position, camera.forward, camera.up}) h.value(v.x).value(v.y).value(v.z);
  h.value(camera.verticalFov).value(r.width).value(r.height);
  h.value(r.tracer.seed).value(r.tracer.maxBounces).value(r.tracer.rouletteAfter);
  if (r.tracer.sampler == SampleSequence::Sobol) h.text("sampler=sobol");  // independent: as before
  if (r.tracer.glossy) h.text("brdf=phong");                                 // lambertian: as before
  h.value(r.tracer.skyRadiance.x).value(r.tracer.skyRadiance.y).value(r.tracer.skyRadiance.z);
  return h.hex();
}

}  // namespace

std::string referenceKey(const Scene& scene, const Camera& camera, const ReferenceRequest& r) {
  return keyFromSceneHash(sceneHash(scene), camera, r);
}

void saveAccumulator(const std::string& path, const Accumulator& acc, double seconds) {
  writeAtomically(path, [&](const std::string& temp) {
    std::ofstream out(temp, std::ios::binary);
    out.write(kStateMagic, sizeof kStateMagic);
    writeRaw(out, acc.width);
    writeRaw(out, acc.height);
    writeRaw(out, acc.samples);
    writeRaw(out, seconds);
    writeDoubles(out, acc.sum);
    writeDoubles(out, acc.sumSquares);
    writeDoubles(out, acc.firstHit);
    if (!out) throw Error(temp + ": cannot write the reference state");
  });
}

Accumulator loadAccumulator(const std::string& path, double* seconds) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open the reference state");
  char magic[sizeof kStateMagic];
  in.read(magic, sizeof magic);
  if (!in || std::memcmp(magic, kStateMagic, sizeof magic) != 0)
    throw Error(path + ": not an lpvlab reference state");
  int width = 0, height = 0;
  std::int64_t samples = 0;
  double spent = 0.0;
  readRaw(in, width);
  readRaw(in, height);
  readRaw(in, samples);
  readRaw(in, spent);
  if (!in || width < 1 || height < 1 || samples < 0 || !std::isfinite(spent) || spent < 0.0)
    throw Error(path + ": corrupt reference state (header)");
  // The header's size must match the file's before anything that size is allocated: a damaged
  // width must not ask for terabytes.
  const std::uintmax_t pixels = std::uintmax_t(width) * std::uintmax_t(height);
  const std::uintmax_t values =
      pixels * (2 * Accumulator::kRadianceValues + Accumulator::kFirstHitValues);
  const std::uintmax_t expected = sizeof kStateMagic + 2 * sizeof(int) + sizeof(std::int64_t) +
                                  sizeof(double) + 3 * sizeof(std::uint64_t) +
                                  values * sizeof(double);
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec || size != expected)
    throw Error(path + ": corrupt reference state (" + std::to_string(width) + "x" +
                std::to_string(height) + " needs " + std::to_string(expected) +
                " bytes, the file has " +
                (ec ? std::string("an unknown size") : std::to_string(size)) + ")");
  Accumulator acc(width, height);
  acc.samples = samples;
  readDoubles(in, acc.sum, acc.sum.size(), path);
  readDoubles(in, acc.sumSquares, acc.sumSquares.size(), path);
  readDoubles(in, acc.firstHit, acc.firstHit.size(), path);
  if (!in) throw Error(path + ": corrupt reference state (truncated)");
  for (const std::vector<double>* values : {&acc.sum, &acc.sumSquares, &acc.firstHit})
    for (double v : *values)
      if (!std::isfinite(v))
        throw Error(path + ": corrupt reference state (a sum is NaN or infinite)");
  for (double v : acc.sumSquares)
    if (v < 0.0) throw Error(path + ": corrupt reference state (a negative sum of squares)");
  if (seconds) *seconds = spent;
  return acc;
}

namespace {

// The cache entry's directory, created (with an error naming the cache when it cannot be).
fs::path entryDirectory(const ReferenceRequest& request, const std::string& key) {
  const fs::path dir = fs::path(request.cacheDir.empty() ? defaultCacheDir() : request.cacheDir) / key;
  std::error_code created;
  fs::create_directories(dir, created);
  if (created)
    throw Error("reference cache " + dir.parent_path().string() + ": cannot create " +
                dir.string() + ": " + created.message() +
                " (the cache is $LPVLAB_CACHE_DIR, --cache or .cache/references)");
  return dir;
}

// The saved accumulator of an entry (its samples so far and their seconds), or an empty one.
Accumulator savedAccumulator(const std::string& statePath, const ReferenceRequest& request,
                             double& spent) {
  Accumulator acc(request.width, request.height);
  if (!fs::exists(statePath)) return acc;
  acc = loadAccumulator(statePath, &spent);
  if (acc.width != request.width || acc.height != request.height)
    throw Error(statePath + ": corrupt reference state (" + std::to_string(acc.width) + "x" +
                std::to_string(acc.height) + " where the key says " +
                std::to_string(request.width) + "x" + std::to_string(request.height) + ")");
  return acc;
}

// What one session of tracing did: its paths, rays and seconds, and the tracer's engine.
struct TracingSession {
  std::int64_t paths = 0, rays = 0;
  double seconds = 0.0;
  nlohmann::json engine;
};

// Traces passes of about a second into `acc` until the request's target is met, checkpointing
// to `statePath` and showing progress; `spent` counts every session's seconds.
TracingSession traceUntilTarget(const Scene& scene, const Camera& camera, const ReferenceRequest& request,
                                const std::string& key, const std::string& statePath, Accumulator& acc,
                                double& spent) {
  TracingSession session;
  const PathTracer tracer(scene, camera, request.width, request.height, request.tracer);
  session.engine = {{"isa", tracer.isa()}, {"packet_width", tracer.packetWidth()}};
  ProgressBar progress("reference " + key);
  auto lastCheckpoint = std::chrono::steady_clock::now();
  double secondsPerSample = 0.0;
  while (!targetMet(request.target, acc.samples, spent, acc.meanRelativeError())) {
    // Passes of about a second keep the progress bar and checkpoints current.
    int count = secondsPerSample > 0.0 ? int(std::clamp(1.0 / secondsPerSample, 1.0, 1024.0)) : 1;
    if (request.target.samples > 0)
      count = int(std::min<std::int64_t>(count, std::max<std::int64_t>(1, request.target.samples - acc.samples)));
    const auto start = std::chrono::steady_clock::now();
    std::int64_t passRays = 0;
    session.paths += tracer.render(acc, count, request.threads, &passRays);
    session.rays += passRays;
    const double passSeconds = secondsSince(start);
    secondsPerSample = passSeconds / count;
    spent += passSeconds;
    session.seconds += passSeconds;
    const double error = acc.meanRelativeError();
    if (request.showProgress) {
      std::ostringstream detail;
      detail << acc.samples << " spp, rel. error " << error;
      progress.update(progressFraction(request.target, acc.samples, spent, error), detail.str());
    }
    if (secondsSince(lastCheckpoint) >= request.checkpointSeconds) {
      saveAccumulator(statePath, acc, spent);
      lastCheckpoint = std::chrono::steady_clock::now();
    }
  }
  saveAccumulator(statePath, acc, spent);
  if (request.showProgress) progress.finish(std::to_string(acc.samples) + " spp");
  return session;
}

// A finished reference's manifest: what it shows (scene, camera, size), how it was traced, and
// what this session took.
nlohmann::json referenceManifest(const Reference& ref, const Scene& scene, const std::string& contentHash,
                                 const Camera& camera, const ReferenceRequest& request,
                                 const TracingSession& session) {
  return {
      {"key", ref.key},
      {"scene",
       {{"source", scene.source}, {"hash", contentHash}, {"triangles", scene.triangleCount()}}},
      {"camera",
       {{"name", camera.name},
        {"position", {camera.position.x, camera.position.y, camera.position.z}},
        {"forward", {camera.forward.x, camera.forward.y, camera.forward.z}},
        {"vertical_fov_rad", camera.verticalFov}}},
      {"width", request.width},
      {"height", request.height},
      {"tracer",
       {{"version", kTracerVersion},
        {"seed", request.tracer.seed},
        {"sampler", samplerName(request.tracer.sampler)},
        {"brdf", request.tracer.glossy ? "phong" : "lambertian"},
        {"max_bounces", request.tracer.maxBounces},
        {"roulette_after", request.tracer.rouletteAfter},
        {"sky_radiance",
         {request.tracer.skyRadiance.x, request.tracer.skyRadiance.y,
          request.tracer.skyRadiance.z}}}},
      {"samples_per_pixel", ref.samples},
      {"seconds_total", ref.seconds},
      {"relative_error", ref.relativeError},
      {"relative_error_estimate",
       request.tracer.sampler == SampleSequence::Sobol
           ? "per-pixel sample variance / samples, as for independent samples: usually an "
             "overestimate with scrambled Sobol samples, which are not independent (their variance "
             "is at most e = 2.72 times the independent one's, Owen 1997, and far below it on smooth "
             "light)"
           : "per-pixel sample variance / samples (independent samples)"},
      {"last_session",
       {{"seconds", session.seconds},
        {"paths", session.paths},
        {"rays", session.rays},
        {"paths_per_second", session.seconds > 0 ? session.paths / session.seconds : 0.0},
        {"rays_per_second", session.seconds > 0 ? session.rays / session.seconds : 0.0},
        {"threads", request.threads > 0 ? request.threads : availableCores()},
        {"engine", session.engine}}},
      {"created_utc", utcTimestamp()},
      {"git_revision", lpvlabRevision()},
      {"host", hostInfo()}};
}

}  // namespace

Reference ensureReference(const Scene& scene, const Camera& camera, const ReferenceRequest& request) {
  if (!request.target.any())
    throw Error("reference: no sample budget: set samples, seconds or relative_error above 0");
  Reference ref;
  const std::string contentHash = sceneHash(scene);
  ref.key = keyFromSceneHash(contentHash, camera, request);
  const fs::path dir = entryDirectory(request, ref.key);
  ref.directory = dir.string();
  // One process at a time renders a reference: another (a parallel sweep's child, a Slurm task)
  // waits here and then finds it complete. The lock dies with its process, also on SIGKILL.
  const EntryLock lock((dir / "lock").string(), ref.key);
  // A process killed while writing leaves its temporary (atomic_file.h) behind; under the lock no
  // one else is writing, so every temporary here is such a leftover.
  removeLeftoverTemporaries(dir.string());
  const std::string statePath = (dir / "state.bin").string();

  double spent = 0.0;
  Accumulator acc = savedAccumulator(statePath, request, spent);
  const bool complete = fs::exists(dir / "images.exr") && fs::exists(dir / "manifest.json");
  ref.reused = complete && targetMet(request.target, acc.samples, spent, acc.meanRelativeError());
  log::debug("reference " + ref.key + " in " + ref.directory + ": " +
             (ref.reused ? "reused (" + std::to_string(acc.samples) + " spp meet the budget)"
                         : "rendering (" + std::to_string(acc.samples) + " spp saved), sampler " +
                               samplerName(request.tracer.sampler)));
  if (!ref.reused && acc.samples > 0 && request.showProgress)
    log::info("reference " + ref.key + ": continuing from " + std::to_string(acc.samples) +
              " saved samples per pixel");
  TracingSession session;  // what this session's samples were traced with
  if (!ref.reused) session = traceUntilTarget(scene, camera, request, ref.key, statePath, acc, spent);

  ref.aovs = acc.images();
  ref.samples = acc.samples;
  ref.seconds = spent;
  ref.relativeError = acc.meanRelativeError();
  if (ref.reused) {
    std::ifstream in(dir / "manifest.json");
    ref.manifest = nlohmann::json::parse(in, nullptr, false);
    if (ref.manifest.is_discarded()) throw Error((dir / "manifest.json").string() + ": not valid JSON");
    return ref;
  }
  ref.manifest = referenceManifest(ref, scene, contentHash, camera, request, session);
  writeExr((dir / "images.exr").string(), ref.aovs, {{"lpvlab:reference_key", ref.key}});
  writeTextAtomically((dir / "manifest.json").string(), ref.manifest.dump(2) + "\n");
  return ref;
}

}  // namespace lpvlab

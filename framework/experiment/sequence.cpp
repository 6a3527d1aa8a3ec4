#include "framework/core/log.h"
#include "framework/experiment/sequence.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include "framework/core/error.h"
#include "framework/core/hash.h"
#include "framework/core/progress.h"
#include "framework/experiment/json_path.h"
#include "framework/experiment/experiment_renderer.h"
#include "framework/experiment/timing.h"
#include "framework/experiment/run_outputs.h"
#include "framework/experiment/sequence_temporal.h"
#include "framework/core/atomic_file.h"
#include "framework/io/child_process.h"
#include "framework/particles/particle_billboards.h"
#include "framework/scene/scene_loader.h"

namespace lpvlab {

namespace fs = std::filesystem;

namespace {

nlohmann::json vec3Json(const glm::vec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json readFrameRecord(const fs::path& path) {
  std::ifstream in(path);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw Error(path.string() + ": damaged frame record (" + e.what() +
                "); delete it to render "
                "that frame again");
  }
}

FrameTimes frameTimesOf(const nlohmann::json& record) {
  FrameTimes times;
  // "gpu_ms": records written before stage times were labelled by their clock (2026-11) named
  // them so, whatever the clock; they have no stage_clock.
  const nlohmann::json& stageMs = record.contains("stage_ms") ? record.at("stage_ms") : record.at("gpu_ms");
  for (const auto& [stage, ms] : stageMs.items()) times.stageMs[stage] = ms.get<double>();
  if (const auto* clock = findPath(record, "stage_clock"); clock && clock->is_object())
    for (const auto& [stage, name] : clock->items()) times.clock[stage] = name.get<std::string>();
  if (const auto* order = findPath(record, "stage_order"); order && order->is_array())
    for (const auto& stage : *order) times.order.push_back(stage.get<std::string>());
  for (const auto& [stage, ms] : record.at("wall_ms").items())
    times.wallMs[stage] = ms.get<double>();
  // Records written before they named the method's stages (2026-11) have no method_stages.
  if (const auto* method = findPath(record, "method_stages"); method && method->is_array())
    for (const auto& stage : *method) times.methodStages.insert(stage.get<std::string>());
  return times;
}

// Every metric of every pair averaged over the frames that have it: the sequence's figures in
// the summary (per-frame ones stay in the frame records and the manifest's sequence block).
nlohmann::json meanComparison(const std::vector<nlohmann::json>& records) {
  std::map<std::string, std::map<std::string, std::pair<double, int>>> sums;
  // Records are read back from files: only what is shaped as written counts.
  for (const nlohmann::json& record : records) {
    const nlohmann::json* comparison = findPath(record, "reference.comparison");
    if (!comparison || !comparison->is_object()) continue;
    for (const auto& [pair, value] : comparison->items()) {
      const nlohmann::json* metrics = findPath(value, "metrics");
      if (!metrics || !metrics->is_object()) continue;
      for (const auto& [metric, v] : metrics->items())
        if (v.is_number()) {
          auto& [sum, count] = sums[pair][metric];
          sum += v.get<double>();
          ++count;
        }
    }
  }
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [pair, metrics] : sums)
    for (const auto& [metric, sumCount] : metrics)
      out[pair]["metrics"][metric] = sumCount.first / sumCount.second;
  return out;
}

int frameDigits(int frames) {
  return std::max(4, int(std::to_string(std::max(0, frames - 1)).size()));
}

// frames/frame_%04d.png as H.264 (yuv420p needs even sizes: odd ones are padded by a pixel).
void writeVideo(const fs::path& dir, int frames, double fps) {
  const std::string pattern =
      (dir / "frames" / ("frame_%0" + std::to_string(frameDigits(frames)) + "d.png")).string();
  // Named as atomic_file.h names its temporaries, so a resumed run removes one a kill left.
  const fs::path temporary = dir / ("video.tmp-" + std::to_string(::getpid()) + ".mp4");
  const int status =
      runProgram({"ffmpeg", "-y", "-loglevel", "error", "-framerate", std::to_string(fps), "-i",
                  pattern, "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18", "-vf",
                  "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-f", "mp4", temporary.string()});
  if (status != 0) {
    fs::remove(temporary);
    throw Error((dir / "video.mp4").string() + ": ffmpeg failed (exit " + std::to_string(status) +
                "); the frames are in " + (dir / "frames").string());
  }
  fs::rename(temporary, dir / "video.mp4");
}

// "0-3, 7, 9-10": frame numbers (ascending) as ranges.
std::string frameRanges(const std::vector<int>& frames) {
  std::string text;
  for (std::size_t i = 0; i < frames.size();) {
    std::size_t j = i;
    while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
    text += (text.empty() ? "" : ", ") + std::to_string(frames[i]) +
            (j > i ? "-" + std::to_string(frames[j]) : "");
    i = j + 1;
  }
  return text;
}

// The frames' warnings for the manifest: each distinct one once, with the frames it holds for
// ("every frame: ..." or "frames 0-3, 7: ..."), in the order they first appear.
std::vector<std::string> sequenceWarnings(const std::vector<nlohmann::json>& records) {
  std::vector<std::pair<std::string, std::vector<int>>> byWarning;
  for (std::size_t frame = 0; frame < records.size(); ++frame) {
    const auto* warnings = findPath(records[frame], "warnings");
    if (!warnings || !warnings->is_array()) continue;
    for (const auto& w : *warnings) {
      if (!w.is_string()) continue;
      auto it = std::find_if(byWarning.begin(), byWarning.end(),
                             [&](const auto& entry) { return entry.first == w.get<std::string>(); });
      if (it == byWarning.end()) it = byWarning.insert(byWarning.end(), {w.get<std::string>(), {}});
      it->second.push_back(int(frame));
    }
  }
  std::vector<std::string> out;
  for (const auto& [warning, frames] : byWarning)
    out.push_back((frames.size() == records.size() ? std::string("every frame: ")
                   : frames.size() == 1           ? "frame " + frameRanges(frames) + ": "
                                                  : "frames " + frameRanges(frames) + ": ") +
                  warning);
  return out;
}

// The first frame without a record in `dir`: a resumed sequence goes on there. Records of another
// configuration (a changed file with the same --out) are an error: two sequences would mix.
int firstMissingFrame(const Experiment& experiment, const fs::path& dir,
                      const std::string& configuration) {
  const Animation& animation = experiment.animation;
  int first = 0;
  for (;; ++first) {
    const fs::path record = dir / (frameStem(first, animation.frames) + ".json");
    if (first >= animation.frames || !fs::exists(record)) return first;
    if (readFrameRecord(record).value("configuration_hash", "") != configuration)
      throw Error(record.string() + ": a frame of another configuration of " + experiment.name +
                  "; give another --out, or delete " + dir.string() + " to start again");
  }
}

// Whether what a frame computes depends on the frames before it (a GV history, incremental
// instant radiosity): a resumed sequence then renders the frames before its first again.
bool keepsStateBetweenFrames(const Experiment& experiment) {
  return experiment.method->keepsStateBetweenFrames();
}

// A rendered frame's record (frames/<stem>.json): where the camera was, its times by stage, the
// particles alive, another method's figures, and the warnings a static run would get.
nlohmann::json frameRecord(const Experiment& experiment, Pipeline& pipeline, int frame,
                           const std::string& hash, const std::string& configuration,
                           const FrameTimes& times, const std::vector<std::size_t>& aliveParticles,
                           const std::vector<NamedImage>& aovs, float exposure) {
  const double seconds = experiment.animation.frameTime(frame);
  nlohmann::json record = {{"frame", frame},
                           {"time_s", seconds},
                           {"camera",
                            {{"position", vec3Json(experiment.camera.position)},
                             {"forward", vec3Json(experiment.camera.forward)},
                             {"vertical_fov_deg", glm::degrees(experiment.camera.verticalFov)}}},
                           {"scene_hash", hash},
                           {"configuration_hash", configuration},
                           {"stage_ms", times.stageMs},
                           {"stage_clock", times.clock},
                           {"stage_order", times.order},
                           {"method_stages", times.methodStages},
                           {"wall_ms", times.wallMs},
                           {"png_exposure_stops", exposure}};
  for (std::size_t s = 0; s < aliveParticles.size(); ++s)
    record["particles_alive"][experiment.particles[s].system().name] = aliveParticles[s];
  // The method's figures of this frame (incremental instant radiosity's removals and insertions
  // differ from frame to frame), where it has any.
  if (nlohmann::json statistics = pipeline.method().statistics(); !statistics.empty())
    record["indirect_method"] = std::move(statistics);
  // A frame that is black, or whose solve stopped short, is flagged as a static run is
  // (resultWarnings reads the figures a static manifest has where it finds them).
  nlohmann::json figures = nlohmann::json::object();
  if (record.contains("indirect_method"))
    figures["indirect_method"]["statistics"] = record["indirect_method"];
  if (const std::vector<std::string> warnings = resultWarnings(aovs, figures); !warnings.empty())
    record["warnings"] = warnings;
  return record;
}

// The sequence's manifest from every frame's record, in order.
nlohmann::json sequenceManifest(Experiment& experiment, const GlContext& context, Pipeline& pipeline,
                                const std::vector<nlohmann::json>& records, int first, bool video) {
  const Animation& animation = experiment.animation;
  std::vector<FrameTimes> times;
  for (const nlohmann::json& record : records) times.push_back(frameTimesOf(record));
  const TimingReport timing = timingReport(times, experiment.warmupFrames);
  nlohmann::json manifest =
      describeRun(experiment, context, pipeline, records.front().at("scene_hash"),
                  medianStageMs(timing));
  manifest["timing"] = timing.toJson();
  manifest["timing"]["per"] = "frame: each frame of the sequence rendered once, in order";
  manifest["sequence"] = {{"frames", animation.frames},
                          {"fps", animation.fps},
                          {"moves",
                           {{"camera", animation.movesCamera()},
                            {"lights", animation.movesLights()},
                            {"geometry", movesGeometry(experiment)}}},
                          {"resumed_at_frame", first},
                          {"temporal", temporalSummary(records)},
                          {"frame_records", records}};
  if (experiment.compareWithReference)
    manifest["reference"] = {
        {"per_frame", true},
        {"comparison", meanComparison(records)},
        {"note", "metrics averaged over the frames; per frame under sequence.frame_records"}};
  manifest["outputs"] = {
      {"frames", frameStem(0, animation.frames) + ".{exr,png,json} and on"},
      {"aovs", {"direct", "indirect", "combined", "albedo", "normal", "depth"}},
      {"units", "radiance W/(m^2 sr); depth: view depth in metres, 0 = no surface"},
      {"png_exposure_stops", records.front().at("png_exposure_stops")}};
  if (video) manifest["outputs"]["video"] = "video.mp4";
  if (const std::vector<std::string> warnings = sequenceWarnings(records); !warnings.empty())
    manifest["warnings"] = warnings;
  return manifest;
}

// Each frame's reference has a seed of its own, so consecutive references have independent
// noise, which the temporal error's noise correction assumes (sequence_temporal.h). Frame 0 keeps
// the experiment's seed: a one-frame sequence is the static run.
Reference frameReference(const Experiment& experiment, int frame) {
  ReferenceRequest request = experiment.reference;
  request.tracer.seed += std::uint64_t(frame);
  return ensureReference(experiment.scene, experiment.camera, request);
}

// The written frame before `first` (the first to render), which its temporal figures compare
// with; none when the sequence starts at frame 0. Moves the scene to that frame.
std::optional<FrameState> frameBefore(Experiment& experiment, const fs::path& dir, int first) {
  if (first == 0) return std::nullopt;
  const Animation& animation = experiment.animation;
  const int frame = first - 1;
  setSceneTime(experiment, animation.frameTime(frame));
  const std::string stem = (dir / frameStem(frame, animation.frames)).string();
  FrameState state{experiment.camera,
                   readFrameRecord(stem + ".json").at("scene_hash").get<std::string>(),
                   readExr(stem + ".exr"),
                   {}};
  if (experiment.compareWithReference) state.reference = frameReference(experiment, frame);
  state.keepOnlyCompared(experiment.comparison);
  return state;
}

// Places the camera, lights, meshes and particles of a frame in the pipeline.
class SceneMover {
public:
  SceneMover(Experiment& experiment, ExperimentRenderer& renderer)
      : experiment_(experiment), renderer_(renderer), geometryMoves_(movesGeometry(experiment)) {}

  void moveTo(int frame) {
    const Animation& animation = experiment_.animation;
    try {
      alive_ = setSceneTime(experiment_, animation.frameTime(frame));
      renderer_.billboards().place(animation.frameTime(frame));
    } catch (const Error& error) {
      throw Error(experiment_.file + ": frame " + std::to_string(frame) + ": " + error.what());
    }
    if (animation.movesCamera()) renderer_.pipeline().setCamera(experiment_.camera);
    if (animation.movesLights() || geometryMoves_)
      renderer_.pipeline().moveScene(experiment_.scene, animation.movesLights(), geometryMoves_);
  }
  // Per particle system, the particles alive in the frame moved to last.
  const std::vector<std::size_t>& aliveParticles() const { return alive_; }

private:
  Experiment& experiment_;
  ExperimentRenderer& renderer_;
  bool geometryMoves_;
  std::vector<std::size_t> alive_;
};

// What writing a frame needs besides the frame: where, the configuration's hash, and the one
// exposure of every PNG of the sequence (frame 0's; set by the first frame written).
struct FrameWriter {
  fs::path dir;
  std::string configuration;
  std::optional<float> exposure;
};

// Renders `frame` (the scene moved to it), compares it with its reference and with the frame
// before, and writes its EXR, PNG and record; returns its state for the next frame.
FrameState renderAndWriteFrame(Experiment& experiment, Pipeline& pipeline, const SceneMover& mover,
                               int frame, FrameWriter& writer, const std::optional<FrameState>& previous) {
  const FrameTimes times = pipeline.renderFrame();
  const std::vector<NamedImage> aovs = pipeline.readOutputs();
  try {
    requireFiniteImages(aovs);
  } catch (const Error& error) {
    throw Error("frame " + std::to_string(frame) + ": " + error.what());
  }
  if (!writer.exposure)
    writer.exposure = experiment.exposureStops +
                      (experiment.autoExposure ? middleGreyExposure(findAov(aovs, "combined")) : 0.0f);
  const std::string hash = sceneHash(experiment.scene);
  nlohmann::json record = frameRecord(experiment, pipeline, frame, hash, writer.configuration, times,
                                      mover.aliveParticles(), aovs, *writer.exposure);
  FrameState state{experiment.camera, hash, aovs, {}};
  if (experiment.compareWithReference) {
    state.reference = frameReference(experiment, frame);
    try {
      record["reference"] = compareWithReference(
          aovs, *state.reference, coverageMask(findAov(aovs, "depth")), experiment.comparison);
    } catch (const Error& error) {  // e.g. a camera inside a mesh, whose reference is black
      throw Error(experiment.file + ": frame " + std::to_string(frame) + ": " + error.what());
    }
  }
  state.keepOnlyCompared(experiment.comparison);
  if (previous) record["temporal"] = temporalRecord(state, *previous, experiment.comparison);
  const std::string stem = (writer.dir / frameStem(frame, experiment.animation.frames)).string();
  writeExr(stem + ".exr", aovs,
           {{"lpvlab:experiment", experiment.name},
            {"lpvlab:scene_hash", hash},
            {"lpvlab:frame", std::to_string(frame)}});
  writePng(stem + ".png", findAov(aovs, "combined"), *writer.exposure, experiment.toneCurve,
           experiment.whiteStops);
  writeTextAtomically(stem + ".json", record.dump(2) + "\n");
  return state;
}

// The first frame to render in `dir`: frames already there must be this configuration's (a
// changed file with the same --out would otherwise mix two sequences). A run killed while
// writing a frame's files (or the video) left temporaries: that frame has no record, so it is
// rendered again.
int resumeAt(const Experiment& experiment, const fs::path& dir, const std::string& configuration) {
  const int first = firstMissingFrame(experiment, dir, configuration);
  removeLeftoverTemporaries((dir / "frames").string());
  removeLeftoverTemporaries(dir.string());
  if (first > 0)
    log::info(experiment.name + ": frames 0-" + std::to_string(first - 1) +
              " are done; continuing at frame " + std::to_string(first));
  return first;
}

}  // namespace

std::string frameStem(int frame, int frames) {
  std::ostringstream s;
  s << "frames/frame_" << std::setfill('0') << std::setw(frameDigits(frames)) << frame;
  return s.str();
}

nlohmann::json runSequence(Experiment& experiment, const GlContext& context,
                           const std::string& outDir) {
  const Animation& animation = experiment.animation;
  const bool video = animation.video && animation.frames > 1;
  if (video && findProgram("ffmpeg").empty())
    throw Error(
        experiment.file +
        ": key 'animation.video': the ffmpeg program is not installed "
        "(Debian package ffmpeg; scripts/install-deps.sh installs it), or set video = false");
  const fs::path dir(outDir);
  fs::create_directories(dir / "frames");
  FrameWriter writer{dir, Hasher().text(experiment.configuration.dump()).hex(), std::nullopt};
  const int first = resumeAt(experiment, dir, writer.configuration);
  std::optional<FrameState> previous = frameBefore(experiment, dir, first);

  // A composition whose frames depend on the frames before (a GV history) renders the frames
  // before `first` again, unwritten, so a resumed sequence matches an uninterrupted one.
  const bool replay = first > 0 && keepsStateBetweenFrames(experiment);
  const int start = replay ? 0 : first;
  if (replay)
    log::info(experiment.name + ": rendering frames 0-" + std::to_string(first - 1) +
              " again (not written): the composition keeps state between frames");
  ShaderCompiler shaders;
  setSceneTime(experiment, animation.frameTime(start));
  ExperimentRenderer renderer(experiment, animation.frameTime(start), shaders);
  Pipeline& pipeline = renderer.pipeline();
  for (int i = 0; i < experiment.warmupFrames; ++i) pipeline.renderFrame();
  SceneMover mover(experiment, renderer);
  for (int frame = start; frame < first; ++frame) {
    mover.moveTo(frame);
    pipeline.renderFrame();
  }

  if (first > 0)
    writer.exposure = readFrameRecord(dir / (frameStem(0, animation.frames) + ".json"))
                          .at("png_exposure_stops")
                          .get<float>();
  ProgressBar progress(experiment.name + " frames");
  const auto started = std::chrono::steady_clock::now();
  for (int frame = first; frame < animation.frames; ++frame) {
    mover.moveTo(frame);
    previous = renderAndWriteFrame(experiment, pipeline, mover, frame, writer, previous);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const int done = frame - first + 1, left = animation.frames - frame - 1;
    // The ETA from this run's frames alone: a resumed sequence's bar starts part full.
    progress.update(double(frame + 1) / animation.frames,
                    "frame " + std::to_string(frame + 1) + "/" + std::to_string(animation.frames),
                    elapsed / done * left);
  }
  progress.finish(std::to_string(animation.frames) + " frames");
  if (video) writeVideo(dir, animation.frames, animation.fps);

  // The manifest, from every frame's record (also those of an earlier, interrupted run).
  std::vector<nlohmann::json> records;
  for (int frame = 0; frame < animation.frames; ++frame)
    records.push_back(readFrameRecord(dir / (frameStem(frame, animation.frames) + ".json")));
  const nlohmann::json manifest = sequenceManifest(experiment, context, pipeline, records, first, video);
  writeTextAtomically((dir / "manifest.json").string(), manifest.dump(2) + "\n");
  return manifest;
}

}  // namespace lpvlab

#include "framework/experiment/sequence_temporal.h"

#include <algorithm>
#include <map>
#include <set>

#include "framework/experiment/json_path.h"
#include "framework/experiment/run_outputs.h"
#include "framework/metrics/temporal.h"
#include "framework/reference/reprojection.h"

namespace lpvlab {

namespace {

std::string varianceName(const std::string& aov) { return aov + "_variance"; }

std::vector<NamedImage> keepNamed(std::vector<NamedImage> aovs,
                                  const std::set<std::string>& names) {
  std::erase_if(aovs, [&](const NamedImage& a) { return !names.count(a.name); });
  return aovs;
}

}  // namespace

void FrameState::keepOnlyCompared(const ComparisonSettings& comparison) {
  std::set<std::string> mine = {"depth", "normal"}, theirs;
  for (const auto& [run, reference] : comparison.pairs) {
    mine.insert(run);
    theirs.insert(reference);
    theirs.insert(varianceName(reference));
  }
  aovs = keepNamed(std::move(aovs), mine);
  if (reference) reference->aovs = keepNamed(std::move(reference->aovs), theirs);
}

nlohmann::json temporalRecord(const FrameState& now, const FrameState& before,
                              const ComparisonSettings& comparison) {
  const Image& depth = findAov(now.aovs, "depth");
  const Reprojection reprojection = reprojectThroughDepth(
      {now.camera, depth, findAov(now.aovs, "normal")},
      {before.camera, findAov(before.aovs, "depth"), findAov(before.aovs, "normal")});
  const Image mask = coverageMask(depth);
  nlohmann::json out = {{"at_rest", now.sceneHash == before.sceneHash}};
  std::int64_t seen = 0, matched = 0;
  for (std::size_t p = 0; p < reprojection.taps.size(); ++p)
    if (mask.pixels[p] != 0.0f) {
      ++seen;
      matched += reprojection.taps[p].count > 0;
    }
  out["reprojected_fraction"] = seen > 0 ? double(matched) / double(seen) : 0.0;
  if (matched == 0) return out;  // a cut, or nothing on screen: no point to follow

  for (const auto& [run, referenceName] : comparison.pairs) {
    const Image& current = findAov(now.aovs, run);
    const Image& previous = findAov(before.aovs, run);
    if (!out["change"].contains(run))
      out["change"][run] = frameToFrameChange(current, previous, reprojection, &mask).toJson();
    if (!now.reference || !before.reference) continue;
    // One cache entry for both frames (nothing changed that the path tracer sees) has the same
    // noise in both: it cancels, and subtracting its variance would be wrong.
    const bool independent = now.reference->key != before.reference->key;
    const ReferencePair references{
        findAov(now.reference->aovs, referenceName), findAov(before.reference->aovs, referenceName),
        independent ? &findAov(now.reference->aovs, varianceName(referenceName)) : nullptr,
        independent ? &findAov(before.reference->aovs, varianceName(referenceName)) : nullptr};
    out["error"][run + "_vs_" + referenceName] =
        temporalError(current, previous, references, reprojection, &mask).toJson();
  }
  return out;
}

nlohmann::json temporalSummary(const std::vector<nlohmann::json>& records) {
  // (group, name) -> relative values over the frames that have one.
  std::map<std::pair<std::string, std::string>, std::vector<double>> values;
  int frames = 0, atRest = 0;
  for (const nlohmann::json& record : records) {
    // Records are read back from files a user may have edited: anything not shaped as written
    // is skipped, never indexed blindly.
    const nlohmann::json* t = findPath(record, "temporal");
    if (!t || !t->is_object()) continue;
    ++frames;
    const nlohmann::json* restFlag = findPath(*t, "at_rest");
    const bool rest = restFlag && restFlag->is_boolean() && restFlag->get<bool>();
    atRest += rest;
    for (const char* group : {"change", "error"}) {
      const nlohmann::json* figuresByName = findPath(*t, group);
      if (!figuresByName || !figuresByName->is_object()) continue;
      for (const auto& [name, figures] : figuresByName->items()) {
        const nlohmann::json* relative = findPath(figures, "relative");
        if (!relative || !relative->is_number()) continue;
        const double v = relative->get<double>();
        values[{group, name}].push_back(v);
        if (rest && std::string(group) == "change") values[{"flicker_at_rest", name}].push_back(v);
      }
    }
  }
  nlohmann::json out = {{"frames_compared", frames}, {"frames_at_rest", atRest}};
  for (const auto& [key, v] : values) {
    double sum = 0.0;
    for (double x : v) sum += x;
    out[key.first][key.second] = {{"mean_relative", sum / double(v.size())},
                                  {"max_relative", *std::max_element(v.begin(), v.end())},
                                  {"frames", v.size()}};
  }
  return out;
}

}  // namespace lpvlab

#include "framework/experiment/sequence_temporal.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "framework/experiment/json_path.h"
#include "framework/experiment/run_outputs.h"
#include "framework/metrics/temporal.h"
#include "framework/reference/reprojection.h"

namespace lpvlab {

namespace {

std::string varianceName(const std::string& aov) { return aov + "_variance"; }

// The lighting figures (temporal.h's demodulate) leave out pixels of an albedo below this in any
// channel: a 2 % albedo reflects too little for its lighting to be told from rounding.
constexpr float kMinimumAlbedo = 0.02f;
const char* const kLightingSuffix = "_lighting";

// Both frames' lighting (an output over its albedo AOV): the images, the current pixels it
// leaves in and the reprojection without taps onto previous pixels it leaves out.
struct Lighting {
  Image nowValid, beforeValid;  // declared first: the images' initialisers fill them
  Image now, before;
  Lighting(const Image& outputNow, const Image& albedoNow, const Image& outputBefore,
           const Image& albedoBefore, bool squared = false)
      : now(demodulate(outputNow, albedoNow, kMinimumAlbedo, &nowValid, squared)),
        before(demodulate(outputBefore, albedoBefore, kMinimumAlbedo, &beforeValid, squared)) {}
};

// Whether some pixel of `mask` has taps (the temporal figures refuse an empty set).
bool anyCovered(const Reprojection& reprojection, const Image& mask) {
  for (std::size_t p = 0; p < reprojection.taps.size(); ++p)
    if (mask.pixels[p] != 0.0f && reprojection.taps[p].count > 0) return true;
  return false;
}

Image product(const Image& a, const Image& b) {
  Image out = a;
  for (std::size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] *= b.pixels[i];
  return out;
}

std::vector<NamedImage> keepNamed(std::vector<NamedImage> aovs,
                                  const std::set<std::string>& names) {
  std::erase_if(aovs, [&](const NamedImage& a) { return !names.count(a.name); });
  return aovs;
}

}  // namespace

void FrameState::keepOnlyCompared(const ComparisonSettings& comparison) {
  std::set<std::string> mine = {"depth", "normal", "albedo"}, theirs = {"albedo"};
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

  const Image& albedoNow = findAov(now.aovs, "albedo");
  const Image& albedoBefore = findAov(before.aovs, "albedo");
  for (const auto& [run, referenceName] : comparison.pairs) {
    const Image& current = findAov(now.aovs, run);
    const Image& previous = findAov(before.aovs, run);
    const Lighting lighting(current, albedoNow, previous, albedoBefore);
    const Reprojection lightingReprojection = withoutTapsOnto(reprojection, lighting.beforeValid);
    const Image lightingMask = product(mask, lighting.nowValid);
    if (!out["change"].contains(run)) {
      out["change"][run] = frameToFrameChange(current, previous, reprojection, &mask).toJson();
      if (anyCovered(lightingReprojection, lightingMask))
        out["change"][run + kLightingSuffix] =
            frameToFrameChange(lighting.now, lighting.before, lightingReprojection, &lightingMask)
                .toJson();
    }
    if (!now.reference || !before.reference) continue;
    // One cache entry for both frames (nothing changed that the path tracer sees) has the same
    // noise in both: it cancels, and subtracting its variance would be wrong.
    const bool independent = now.reference->key != before.reference->key;
    const std::vector<NamedImage>& refNow = now.reference->aovs;
    const std::vector<NamedImage>& refBefore = before.reference->aovs;
    const ReferencePair references{
        findAov(refNow, referenceName), findAov(refBefore, referenceName),
        independent ? &findAov(refNow, varianceName(referenceName)) : nullptr,
        independent ? &findAov(refBefore, varianceName(referenceName)) : nullptr};
    const std::string pair = run + "_vs_" + referenceName;
    out["error"][pair] = temporalError(current, previous, references, reprojection, &mask).toJson();

    // The lighting's error: each side over its own albedo (the path tracer's first-hit albedo),
    // the references' variances over its square; pixels either side leaves out are left out.
    const Image* refAlbedoNow = findAovOrNull(refNow, "albedo");
    const Image* refAlbedoBefore = findAovOrNull(refBefore, "albedo");
    if (!refAlbedoNow || !refAlbedoBefore) continue;
    const Lighting refLighting(references.now, *refAlbedoNow, references.before, *refAlbedoBefore);
    std::optional<Lighting> refVariance;
    if (independent)
      refVariance.emplace(*references.nowVariance, *refAlbedoNow, *references.beforeVariance,
                          *refAlbedoBefore, true);
    const Reprojection both = withoutTapsOnto(lightingReprojection, refLighting.beforeValid);
    const Image bothMask = product(lightingMask, refLighting.nowValid);
    if (!anyCovered(both, bothMask)) continue;
    const ReferencePair lightingReferences{refLighting.now, refLighting.before,
                                           refVariance ? &refVariance->now : nullptr,
                                           refVariance ? &refVariance->before : nullptr};
    out["error"][pair + kLightingSuffix] =
        temporalError(lighting.now, lighting.before, lightingReferences, both, &bothMask).toJson();
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

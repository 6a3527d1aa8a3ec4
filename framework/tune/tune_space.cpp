#include "framework/tune/tune_space.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

#include "framework/core/hash.h"
#include "framework/reference/random.h"

namespace lpvlab {

namespace {

// Configurations in a space of choices only (1 for a space with a range: it has no end).
double spaceSize(const TuneSpec& spec) {
  double size = 1.0;
  for (const TuneDimension& d : spec.space) size *= d.choices.empty() ? 1e300 : double(d.choices.size());
  return size;
}

TuneCandidate candidateOf(std::vector<std::string> overrides) {
  TuneCandidate c;
  c.overrides = std::move(overrides);
  std::string joined;
  for (const std::string& o : c.overrides) joined += o + "\n";
  c.id = c.overrides.empty() ? "baseline" : Hasher().text(joined).hex().substr(0, 10);
  return c;
}

// The index-th configuration of a space of choices only (mixed radix, the first key fastest).
std::vector<std::string> enumerated(const TuneSpec& spec, std::size_t index) {
  std::vector<std::string> out;
  for (const TuneDimension& d : spec.space) {
    out.push_back(d.key + "=" + d.choices[index % d.choices.size()]);
    index /= d.choices.size();
  }
  return out;
}

}  // namespace

std::string TuneCandidate::name() const {
  std::string out;
  for (const std::string& o : overrides) out += (out.empty() ? "" : ", ") + o;
  return out.empty() ? "baseline (the file as it is)" : out;
}

std::string rangeValue(const TuneDimension& d, double u) {
  double v = d.log ? d.min * std::pow(d.max / d.min, u) : d.min + u * (d.max - d.min);
  if (d.step > 0.0) v = d.min + std::round((v - d.min) / d.step) * d.step;
  if (d.integer) v = std::round(v);
  v = std::clamp(v, d.min, d.max);
  std::ostringstream s;
  if (d.integer) {
    s << std::int64_t(v);
    return s.str();
  }
  s << std::setprecision(6) << v;
  std::string text = s.str();
  if (text.find_first_of(".e") == std::string::npos) text += ".0";  // TOML reads "2" as an integer
  return text;
}

std::vector<TuneCandidate> drawCandidates(const TuneSpec& spec) {
  std::vector<TuneCandidate> out = {candidateOf({})};
  std::set<std::string> seen = {out.front().id};
  const double size = spaceSize(spec);
  if (size <= double(spec.candidates)) {
    for (std::size_t i = 0; i < std::size_t(size); ++i) {
      TuneCandidate c = candidateOf(enumerated(spec, i));
      if (seen.insert(c.id).second) out.push_back(std::move(c));
    }
    return out;
  }
  // Draws until `candidates` distinct ones (a bounded number of tries: a space with few distinct
  // values on its ranges' steps may hold fewer).
  for (std::uint64_t draw = 0; int(out.size()) <= spec.candidates && draw < 100u * spec.candidates; ++draw) {
    SampleRandom random(spec.seed, 0x7475'6e65ull, draw);  // "tune"
    std::vector<std::string> overrides;
    for (const TuneDimension& d : spec.space) {
      const double u = random.uniform();
      overrides.push_back(d.key + "=" + (d.choices.empty()
                                             ? rangeValue(d, u)
                                             : d.choices[std::min(d.choices.size() - 1, std::size_t(u * d.choices.size()))]));
    }
    TuneCandidate c = candidateOf(std::move(overrides));
    if (seen.insert(c.id).second) out.push_back(std::move(c));
  }
  return out;
}

}  // namespace lpvlab

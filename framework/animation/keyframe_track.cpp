#include "framework/animation/keyframe_track.h"

#include <algorithm>
#include <cmath>
#include <glm/gtx/quaternion.hpp>
#include <glm/gtx/spline.hpp>

#include "framework/core/error.h"

namespace lpvlab {

namespace {

bool finite(double v) { return std::isfinite(v); }
bool finite(const glm::dvec3& v) { return finite(v.x) && finite(v.y) && finite(v.z); }
bool finite(const glm::dquat& q) {
  return finite(q.w) && finite(q.x) && finite(q.y) && finite(q.z);
}

// GLM's Hermite basis (gtx/spline) on vectors; a double goes through as a one-component vector.
glm::dvec3 hermite(const glm::dvec3& v0, const glm::dvec3& m0, const glm::dvec3& v1,
                   const glm::dvec3& m1, double s) {
  return glm::hermite(v0, m0, v1, m1, s);
}
double hermite(double v0, double m0, double v1, double m1, double s) {
  return glm::hermite(glm::dvec1(v0), glm::dvec1(m0), glm::dvec1(v1), glm::dvec1(m1), s).x;
}

}  // namespace

const std::vector<std::string>& interpolationNames() {
  static const std::vector<std::string> names = {"step", "linear", "catmull_rom"};
  return names;
}

Interpolation interpolationNamed(const std::string& name) {
  if (name == "step") return Interpolation::Step;
  if (name == "linear") return Interpolation::Linear;
  if (name == "catmull_rom") return Interpolation::CatmullRom;
  throw Error("unknown interpolation '" + name + "' (step, linear, catmull_rom)");
}

std::string interpolationName(Interpolation interpolation) {
  return interpolationNames()[std::size_t(interpolation)];
}

template <class T>
KeyframeTrack<T>::KeyframeTrack(std::vector<double> times, std::vector<T> values,
                                Interpolation interpolation)
    : times_(std::move(times)), values_(std::move(values)), interpolation_(interpolation) {
  if (times_.empty() || times_.size() != values_.size())
    throw Error("needs at least one key, each with a time and a value");
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (!std::isfinite(times_[i])) throw Error("key " + std::to_string(i) + ": time is not finite");
    if (i > 0 && !(times_[i] > times_[i - 1]))
      throw Error("key " + std::to_string(i) + ": time " + std::to_string(times_[i]) +
                  " s does not come after the previous key's " + std::to_string(times_[i - 1]) +
                  " s (keys must be in increasing time)");
    if (!finite(values_[i])) throw Error("key " + std::to_string(i) + ": value is not finite");
  }
  const std::size_t n = times_.size();
  if constexpr (std::is_same_v<T, glm::dquat>) {
    for (std::size_t i = 0; i < n; ++i) {
      if (glm::length(values_[i]) < 1e-12)
        throw Error("key " + std::to_string(i) + ": zero rotation");
      values_[i] = glm::normalize(values_[i]);
      // q and -q are the same rotation: keep each key on the side of its predecessor, so the
      // interpolation takes the shorter arc.
      if (i > 0 && glm::dot(values_[i - 1], values_[i]) < 0.0) values_[i] = -values_[i];
    }
    if (interpolation_ == Interpolation::CatmullRom)
      for (std::size_t i = 0; i < n; ++i)
        tangents_.push_back(glm::intermediate(values_[i == 0 ? 0 : i - 1], values_[i],
                                              values_[std::min(i + 1, n - 1)]));
  } else if (interpolation_ == Interpolation::CatmullRom) {
    for (std::size_t i = 0; i < n; ++i) {
      if (n == 1) {
        tangents_.push_back(T(0.0));
        continue;
      }
      const std::size_t before = i == 0 ? 0 : i - 1, after = std::min(i + 1, n - 1);
      tangents_.push_back((values_[after] - values_[before]) / (times_[after] - times_[before]));
    }
  }
}

template <class T>
T KeyframeTrack<T>::sample(double seconds) const {
  if (seconds <= times_.front()) return values_.front();
  if (seconds >= times_.back()) return values_.back();
  // The segment [t_i, t_{i+1}) holding `seconds`.
  const std::size_t i =
      std::size_t(std::upper_bound(times_.begin(), times_.end(), seconds) - times_.begin()) - 1;
  const double span = times_[i + 1] - times_[i];
  const double s = std::clamp((seconds - times_[i]) / span, 0.0, 1.0);
  switch (interpolation_) {
    case Interpolation::Step:
      return values_[i];
    case Interpolation::Linear:
      if constexpr (std::is_same_v<T, glm::dquat>)
        return glm::slerp(values_[i], values_[i + 1], s);
      else
        return values_[i] + (values_[i + 1] - values_[i]) * s;
    case Interpolation::CatmullRom:
      if constexpr (std::is_same_v<T, glm::dquat>)
        return glm::normalize(
            glm::squad(values_[i], values_[i + 1], tangents_[i], tangents_[i + 1], s));
      else
        // Tangents are per second; the Hermite basis takes them per unit of s.
        return hermite(values_[i], tangents_[i] * span, values_[i + 1], tangents_[i + 1] * span, s);
  }
  return values_[i];
}

template class KeyframeTrack<double>;
template class KeyframeTrack<glm::dvec3>;
template class KeyframeTrack<glm::dquat>;

}  // namespace lpvlab

#pragma once
// A value keyed at times (seconds) and interpolated between them: what every animated quantity of
// an experiment is made of (camera paths, lights, moving meshes; framework/animation/animation.h).
//
// Interpolation between keys i and i+1, with s = (t - t_i) / (t_{i+1} - t_i) in [0, 1]:
//   Step        the value of key i (held until the next key)
//   Linear      (1 - s) v_i + s v_{i+1}; rotations by spherical linear interpolation (slerp)
//   CatmullRom  the cubic Hermite curve through v_i and v_{i+1} whose tangents (per second) are
//               the finite differences (v_{i+1} - v_{i-1}) / (t_{i+1} - t_{i-1}), one-sided at the
//               first and last key. It passes through every key and its first derivative in time
//               is continuous (C1) also where keys are unevenly spaced; with evenly spaced keys it
//               is the uniform Catmull-Rom spline of thesis 6.11, eq. 6.4 (glm::catmullRom).
//               Rotations: Shoemake's squad (glm::squad), which passes through every key and is
//               C1 with evenly spaced keys.
// Before the first key and after the last the value is held. Times are doubles (a sequence of
// hours at 1000 fps still resolves its frames), values double precision.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

namespace lpvlab {

enum class Interpolation { Step, Linear, CatmullRom };

// "step", "linear", "catmull_rom" (as experiment files name them), and back.
const std::vector<std::string>& interpolationNames();
Interpolation interpolationNamed(const std::string& name);
std::string interpolationName(Interpolation interpolation);

// T: double, glm::dvec3 or glm::dquat (explicitly instantiated in keyframe_track.cpp).
template <class T>
class KeyframeTrack {
 public:
  KeyframeTrack() = default;  // no keys: empty(), and sample() must not be called
  // Throws an Error (naming no file: the reader adds where) unless there is at least one key,
  // times are finite and strictly increasing, and values finite. Quaternions are normalised.
  KeyframeTrack(std::vector<double> times, std::vector<T> values, Interpolation interpolation);

  bool empty() const { return times_.empty(); }
  const std::vector<double>& times() const { return times_; }
  const std::vector<T>& values() const { return values_; }
  Interpolation interpolation() const { return interpolation_; }

  T sample(double seconds) const;

 private:
  std::vector<double> times_;
  std::vector<T> values_;
  std::vector<T> tangents_;  // CatmullRom: per key, per second (rotations: squad's intermediates)
  Interpolation interpolation_ = Interpolation::Linear;
};

}  // namespace lpvlab

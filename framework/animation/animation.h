#pragma once
// An experiment's animation ([animation] table; docs/animation.md): how many frames at what rate,
// and what moves. Every animated value is a KeyframeTrack sampled at the frame's time, and
// applyFrame() is the one place that turns a time into the scene and camera of that frame, so the
// LPV pipeline and the reference path tracer see the same motion by construction.
//
// Frame f is at time f / fps seconds (frame 0 at 0 s). Frame 0 of an animated experiment is what
// a static run of it renders: loadExperiment applies it.

#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/animation/keyframe_track.h"
#include "framework/scene/scene.h"

namespace lpvlab {

// The camera along a path: its position and the point it looks at, each a track (thesis 6.11 puts
// a Catmull-Rom spline through control points of position and rotation; a look-at point keeps
// the view's roll fixed by `up`, which rotations interpolated on their own do not). The vertical
// field of view may be keyed too.
struct CameraMotion {
  KeyframeTrack<glm::dvec3> position;
  KeyframeTrack<glm::dvec3> lookAt;
  KeyframeTrack<double> verticalFov;  // radians; empty: the camera's own
  glm::vec3 up{0, 1, 0};
};

// A light of the scene (or of [[lights]]) whose keyed quantities follow their tracks; an empty
// track leaves that quantity as loaded. Intensity and colour are interpolated linearly between
// keys whatever the light's interpolation (a cubic would overshoot below zero between keys).
struct LightMotion {
  int light = -1;                       // index into Scene::lights
  KeyframeTrack<glm::dvec3> position;   // metres
  KeyframeTrack<glm::dvec3> direction;  // normalised after interpolation
  KeyframeTrack<double> intensity;      // W/sr, or W/m^2 for a directional light (scene.h)
  KeyframeTrack<glm::dvec3> color;
};

// Meshes moving as one rigid body: each frame, a point p of them as loaded goes to
// pivot + R(t) (p - pivot) + translation(t), and normals to R(t) n.
struct MeshMotion {
  std::vector<int> meshes;                // indices into Scene::meshes
  glm::dvec3 pivot{0.0};                  // default: the centre of their bounds as loaded
  KeyframeTrack<glm::dvec3> translation;  // metres; empty: none
  KeyframeTrack<glm::dquat> rotation;     // empty: none
  // The meshes as loaded (world space), which every frame transforms afresh, so rounding never
  // accumulates over a long sequence.
  std::vector<std::vector<glm::vec3>> restPositions, restNormals;
};

struct Animation {
  int frames = 1;
  double fps = 30.0;
  bool video = true;  // a sequence of more than one frame also gets an H.264 video (ffmpeg)
  std::optional<CameraMotion> camera;
  std::vector<LightMotion> lights;
  std::vector<MeshMotion> meshes;

  double frameTime(int frame) const { return double(frame) / fps; }
  // What changes between frames, so a sequence recomputes only what depends on it (the RSM and
  // shadow maps do not depend on the camera, the geometry volume's GV-from-geometry part not on
  // the lights).
  bool movesCamera() const { return camera.has_value(); }
  bool movesLights() const { return !lights.empty(); }
  bool movesGeometry() const { return !meshes.empty(); }
  bool animated() const { return frames > 1 || movesCamera() || movesLights() || movesGeometry(); }
};

// Sets the animated lights, meshes and camera of `scene` and `camera` to their values at `seconds`
// (everything not animated is left as it is). Throws an Error naming the frame time when a
// sampled value is degenerate (a camera at its look-at point, a zero light direction).
void applyAnimation(const Animation& animation, double seconds, Scene& scene, Camera& camera);

// The camera alone at `seconds`, from `camera` as loaded (itself when no path moves it): what
// applyAnimation sets it to, without touching a scene.
Camera cameraAt(const Animation& animation, double seconds, Camera camera);

}  // namespace lpvlab

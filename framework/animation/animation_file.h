#pragma once
// Reads an experiment's [animation] table (docs/animation.md) against its scene: names of lights
// and meshes are looked up there, and every frame's camera and light values are checked when the
// file is read, so a path that runs the camera into its look-at point at frame 73 is an error
// naming the key, not a NaN image an hour into the sequence.

#include "framework/animation/animation.h"
#include "framework/core/parameters.h"
#include "framework/scene/scene.h"

namespace lpvlab {

// `p` is the [animation] table (absent: one frame, nothing moves). A camera path moves `camera`,
// the experiment's ([camera], or the scene's first) when `cameraGiven`: the path keeps its field
// of view and planes unless it gives its own, and its far plane is pushed out to cover the whole
// path. Without a given camera the path's defaults are 45 degrees and planes from the scene size.
Animation readAnimation(Params p, const Scene& scene, Camera& camera, bool cameraGiven);

}  // namespace lpvlab

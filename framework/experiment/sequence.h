#pragma once
// Running an animated experiment ([animation], framework/animation/animation.h): every frame
// rendered into the run directory, each with its own files, then a video and the manifest:
//   frames/frame_NNNN.exr    every AOV, as a static run's images.exr
//   frames/frame_NNNN.png    the combined image at the sequence's one exposure (frame 0's
//                            automatic exposure, so the tone mapping never flickers)
//   frames/frame_NNNN.json   the frame's time, camera, scene hash, stage timings, its temporal
//                            figures against the frame before (sequence_temporal.h) and, with
//                            [reference] compare, its comparison with its own reference (each
//                            frame's reference has the seed of [reference] plus the frame number)
//   video.mp4                the PNGs as H.264 at the animation's frame rate (ffmpeg)
//   manifest.json            the run (as a static run's), timings over the frames in order, the
//                            sequence's per-frame records, metrics averaged over frames
// A frame's JSON is written last, so an interrupted sequence resumes at the first frame without
// one, reading the frame before it back for the temporal figures. Each LPV frame is computed from
// its scene alone: nothing of the light is carried from frame to frame.

#include <nlohmann/json.hpp>
#include <string>

#include "framework/experiment/experiment.h"
#include "framework/gl/context.h"

namespace lpvlab {

nlohmann::json runSequence(Experiment& experiment, const GlContext& context,
                           const std::string& outDir);

// The name of frame `frame`'s files without extension, "frames/frame_0007" (at least four
// digits, more where the sequence has more frames).
std::string frameStem(int frame, int frames);

}  // namespace lpvlab

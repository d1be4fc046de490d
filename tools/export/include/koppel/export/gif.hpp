// The animated GIF of a cycle (koppel animate): each frame of an AnimationScene drawn with cairo
// (the parts as plates with their holes and slots, the frame's pivots with the ground symbol,
// the traced curves as far as they have grown, the input as caption), to scale and the same
// view in every frame, quantised to 256 colours per frame and encoded by giflib: GIF89a, one
// local colour table per frame, looping forever.
#pragma once

#include "koppel/plot/animation.hpp"

#include <string>

namespace koppel::plot {

struct GifOptions {
  int width = 640, height = 480;  // px, each 16 .. kMaxAnimationSide
  double fps = 24;                // frames per second, 0.1 .. 50
  // Empty *why and true when the sides and fps are in range and frames x width x height is at
  // most kMaxAnimationPixels.
  bool IsValid(int frames, std::string* why) const;
  // A GIF's delay between frames is in 1/100 s: round(100 / fps), so 24 fps plays at 25.
  int DelayCentiseconds() const;
};

// The GIF file's bytes. Preconditions: options.IsValid(frames) and scene.frames not empty
// (std::invalid_argument otherwise); std::runtime_error when cairo or giflib fail (out of memory).
std::string RenderGif(const AnimationScene& scene, const GifOptions& options);

}  // namespace koppel::plot

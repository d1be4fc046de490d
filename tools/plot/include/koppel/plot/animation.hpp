// The frames of an animation of one cycle (koppel animate): the parts (parts.hpp) at the inputs
// of CycleInputs — a full turn, or a limited range there and back — and the traced curves, each
// drawn up to the frame's input on the way there and whole on the way back.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/plot/cycle.hpp"
#include "koppel/plot/parts.hpp"
#include "koppel/plot/plots.hpp"

#include <string>
#include <vector>

namespace koppel::plot {

struct AnimationOptions {
  CycleOptions cycle;
  int frames = 72;  // 1 .. kMaxAnimationFrames
  bool IsValid(std::string* why) const;
};

struct AnimationFrame {
  double input = 0;         // [rad | length]
  double traced_up_to = 0;  // the curves are drawn up to this input (TracedCurve::UpTo)
  std::string caption;      // "mzc-crank-rocker   φ = 30.0°"
  std::vector<Part> parts;  // the frame first
};

struct AnimationScene {
  PlotStatus status = PlotStatus::kComplete;  // kPartial: a frame's pose or a stretch of a curve is missing; kFailed: nothing to show
  std::string message;
  CycleRange range;
  std::vector<AnimationFrame> frames;  // options.frames of them unless a pose could not be reached
  std::vector<TracedCurve> curves;
};

// Throws std::invalid_argument when the options are not valid.
AnimationScene AnimateCycle(const Mechanism& mechanism, const AnimationOptions& options);

}  // namespace koppel::plot

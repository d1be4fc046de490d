// The limits koppel holds every input to, so that a hostile file or command line ends with a
// clear message (exit 2) instead of an unbounded allocation, a hang or a crash. Each is checked
// before the work or the memory it bounds is spent; README.md "Limits" lists them for users.
#pragma once

#include <cstddef>

namespace koppel {

// Samples of one sweep (analyze, deadcentres, curve, proportional): a step of 0.00036 deg over a
// full turn; every sample keeps its pose and outputs, so more is gigabytes nobody reads.
inline constexpr long kMaxSweepSamples = 1'000'000;

// Samples of the straight-line search (curve --straight): the search tries every pair of end
// points, so its work grows with the square; 40 000 is 0.009 deg over +-180 deg, about a second.
inline constexpr long kMaxStraightSearchSamples = 40'000;

// Cells of one design chart (synth chart): each cell is a small optimisation (~0.2 ms), so this
// is at most a minute of work; the default chart has 1 271.
inline constexpr long kMaxChartCells = 250'000;

// Bytes of one input file: hand-written mechanisms are a few kilobytes and a generated one with
// the most parameters allowed fits; beyond it the reader would hold a runaway file (/dev/zero).
inline constexpr std::size_t kMaxInputBytes = 4 * 1024 * 1024;

// Parameters of one file: far above any mechanism's dozens, low enough that reading them stays
// well under a second.
inline constexpr std::size_t kMaxParameters = 100'000;

// Nesting depth of a YAML file: a mechanism file nests four levels; the YAML parser recurses per
// level, so a deep file would otherwise spend the stack.
inline constexpr int kMaxYamlDepth = 64;

// Characters of one formula (a parameter, a number in the file or on the command line): a
// formula is a line a person reads.
inline constexpr std::size_t kMaxFormulaLength = 1000;

// Frames of one animation (koppel animate --frames): 3 600 is ten frames per degree of a turn,
// far more than any eye needs; each frame is drawn and encoded anew.
inline constexpr int kMaxAnimationFrames = 3'600;

// Pixels along either side of an animation (koppel animate --size): a 4K screen's width; a frame
// takes about 22 bytes a pixel while it is drawn and encoded (350 MB at 4096 x 4096).
inline constexpr int kMaxAnimationSide = 4'096;

// Pixels of one animation, frames x width x height: every pixel is drawn, quantised and encoded,
// about 40 ns each (measured: 360 frames of 1024 x 768 in 10.6 s), so this is under a minute of
// work and a GIF of some 25 MB.
inline constexpr long kMaxAnimationPixels = 1'000'000'000;

}  // namespace koppel

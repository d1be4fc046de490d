// The limits koppel holds every input to, so that a hostile file or command line ends with a
// clear message (exit 2) instead of an unbounded allocation, a hang or a crash. Each is checked
// before the work or the memory it bounds is spent; README.md "Limits" lists them for users.
#pragma once

#include <cstddef>

namespace koppel {

// A CSV reader (points, motor curves) lists this many problems of a file, then stops reading it.
inline constexpr std::size_t kMaxReportedProblems = 20;

// Samples of one sweep (analyze, deadcentres, curve, proportional): a step of 0.00036 deg over a
// full turn; every sample keeps its pose and outputs, so more is gigabytes nobody reads.
inline constexpr long kMaxSweepSamples = 1'000'000;

// The random starts of synth path's global search (--starts): one or two milliseconds each, so
// the limit is half an hour on two cores; more is a typing error.
inline constexpr int kMaxTimedStarts = 1'000'000;

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

// Bytes of one name in a file (a link, point, joint, output, load, the drive's input, a
// parameter): a name labels a drawing and heads a column; 128 bytes is 32 to 128 characters.
inline constexpr std::size_t kMaxNameBytes = 128;

// Four-bars of one motion synthesis (synth motion: every ordered pair of dyads is a four-bar,
// re-analysed through every pose at about 2.5 ms each, measured): 12 000 is half a minute on one
// core. --grid 20 made 160 000 (7 min), --samples 1000 with four poses millions.
inline constexpr long kMaxMotionFourBars = 12'000;

// Point fits of one path synthesis (synth path: --top linkages polished by a least-squares fit
// over every point, plus the repeats of a better design dropped on the way): about 9 ms a point
// fit (measured: --top 10 on 24 points, 70 polishes, in 2.2 s), so 3 000 is half a minute on one
// core. --top 1000 on 24 points asked for 24 000.
inline constexpr long kMaxPathPointFits = 3'000;

// Rows of one simulation (simulate --t/--dt): each row is a solved pose and a line of output;
// --t 0:1e6 --dt 1 asked for a million.
inline constexpr long kMaxSimulationRows = 100'000;

// Monte Carlo samples of one tolerance analysis (tolerance --samples): each sample evaluates the
// file anew with its drawn parameters and solves every input, about 0.4 ms of one core a sample
// (measured: 200 000 samples of the offset slider-crank at one input in 38 s on two cores), so a
// million is some three minutes on two cores; 100 000 already put 100 samples beyond the 0.001
// quantile. --samples 10000000 asked for half an hour.
inline constexpr long kMaxToleranceSamples = 1'000'000;

// Samples x inputs of one tolerance analysis: every value is held until its input's quantiles are
// taken (8 bytes each, 800 MB at the limit; the run also checks it against the memory the process
// may have). --samples 5000000 over a turn asked for 1.8 billion.
inline constexpr long kMaxToleranceValues = 100'000'000;

// The largest coordinate of a point of a mechanism file [its length unit]: a billion. The solver
// works in double precision relative to the mechanism's size, and a squared length of 1e300
// overflows; `--set l1=1e300` made a mechanism whose every derived size was infinite.
inline constexpr double kMaxCoordinate = 1e9;

// Metres per length unit of a file (units: {length: ...}): a nanometre to a thousand kilometres.
// Forces, energies and moments of inertia scale with up to the fifth power of the unit (a mass's
// inertia in kg m^2 times speeds squared), so a unit of 1e308 m makes every force overflow.
inline constexpr double kMinLengthUnit = 1e-9;
inline constexpr double kMaxLengthUnit = 1e6;

// Threads of one command (--threads, a spec's threads): far above the cores of any machine koppel
// runs on; each thread reserves a stack (8 MB of address space), so --threads 600 under
// `ulimit -v` could not be had. Threads that cannot be created are done without (fewer run).
inline constexpr int kMaxThreads = 256;

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

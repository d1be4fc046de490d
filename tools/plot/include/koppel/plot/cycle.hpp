// One cycle of the drive, for the pictures that show a mechanism moving (koppel animate) or its
// coupler curves whole (koppel export --dxf): the drivable interval of the assembly branch,
// sampled, with the traced points' curves, and the inputs of the frames of an animation.
//
// Inputs in radians for an R drive, in the length unit for a P drive.
#pragma once

#include "koppel/core/expected.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/plot/parts.hpp"
#include "koppel/plot/sampled_run.hpp"
#include "koppel/solver/sweep.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {
class Model;
}  // namespace koppel

namespace koppel::plot {

struct CycleRange {
  double from = 0, to = 0;  // from < to
  bool full_turn = false;   // the pose at `to` is the pose at `from` (one period of a turning drive)
  std::string note;         // an end that is not the branch's own (the file's sweep), said for the user
};

// The drivable interval of the branch the assembly hint chooses (analysis DrivableRanges,
// branch 0): 0 .. period for a drive that turns fully, limit to limit for a rocking one. An end
// where the search bound stopped (a drive that meets no limit, such as a slider driven along an
// endless guide) is the end of `sweep` (the file's sweep; from and to in either order) instead,
// and the note says so. An error when the mechanism does not assemble at its hint.
Expected<CycleRange> CycleRangeOf(const Mechanism& mechanism, const SweepOptions& sweep);

// The inputs of `frames` frames (>= 1) of one cycle: a full turn in equal steps from `from`, the
// last one step before `from` comes round again; a limited range there and back, frame 0 at
// `from`, frame frames/2 at `to` (an even count), back towards `from` after it.
std::vector<double> CycleInputs(const CycleRange& range, int frames);

// The input up to which the curves are drawn at frame `frame` of CycleInputs: its own input on
// the way there, `to` on the way back (the curve is whole then).
double TracedUpTo(const CycleRange& range, int frames, int frame);

// Intervals into which a cycle's curves are cut: 1 degree of a full turn, 1/360 of a rocker's
// swing; enough that the polyline of a coupler curve lies within a hair of the curve.
inline constexpr int kCycleSegments = 360;

// A traced point's curve over the cycle: one run per stretch of the sweep (no line across a gap).
struct TracedCurve {
  std::string name;                               // as the user named the point
  std::vector<std::vector<double>> inputs;        // per run, increasing
  std::vector<std::vector<Eigen::Vector2d>> runs; // global points, the same shape
  bool closed = false;  // a full turn swept without a gap: the last point is the first again (left out)
  // The runs cut at `input`: every point with an input at most `input`.
  std::vector<std::vector<Eigen::Vector2d>> UpTo(double input) const;
};

// A point to trace: where it is and what to call it.
struct TracedPoint {
  PointRef point;
  std::string name;
};

struct CycleSamples {
  CycleRange range;
  SampledRun run;                    // kCycleSegments intervals over the range, order 0
  std::vector<TracedCurve> curves;   // one per traced point
  // per joint, a prismatic joint's least and greatest displacement over the range, refined to
  // the extremes (koppel/api/guide_travel.hpp), not the samples'; 0, 0 for other joints
  std::vector<std::pair<double, double>> travel;
};

// Sweeps `range` (kCycleSegments intervals) with the traced points as the only outputs, and
// finds each guide's travel over it (FindGuideTravels at the same resolution). The run may be
// partial (run.complete, run.message); an error when nothing could be computed or a guide's
// travel could not be found (a slot cut from the samples would be short).
Expected<CycleSamples> SampleCycle(const Mechanism& mechanism, const CycleRange& range, const std::vector<TracedPoint>& traced,
                                   const ContinuationOptions& continuation = {});

// What a picture of the cycle is made of: the points traced, the sizes of the parts, and the
// file's sweep (the range where the drive meets no limit, see CycleRangeOf; its continuation
// options are used for every walk).
struct CycleOptions {
  std::vector<TracedPoint> traced;
  PartSizes sizes;
  SweepOptions sweep;
  bool IsValid(std::string* why) const;  // sizes valid, sweep ends finite
};

// The options of a model's pictures unless the user says otherwise: its point outputs traced,
// DefaultPartSizes, and the file's sweep (koppel/api/model.hpp: sweep_from, sweep_to).
CycleOptions CycleOptionsOf(const Model& model);

// The cycle of CycleRangeOf(options.sweep) sampled with the options' points (SampleCycle above);
// an error when the range or the samples cannot be had. samples.range.note says where the
// range is not the branch's own.
Expected<CycleSamples> SampleCycle(const Mechanism& mechanism, const CycleOptions& options);

// The pose at `input` on the cycle's branch: the run's own pose where a sample lies at the input
// (so a frame at a branch point, where the sweep passed but a walk cannot stop, still has its
// pose), else continued from the nearest sample (PoseAt).
Expected<Eigen::VectorXd> PoseOnCycle(const Mechanism& mechanism, const CycleSamples& samples, double input);

// The mechanism's point outputs, in file order: what is traced unless the user names points.
std::vector<TracedPoint> PointOutputs(const Mechanism& mechanism);

}  // namespace koppel::plot

// Motion generation (Burmester) as `koppel synth motion` runs it: the poses file, the circle-point
// grid of three poses, the four poses' Burmester curves, and a report of the whole search (how
// many dyads, which four-bars failed) beside its designs. SynthesiseMotion (synthesis.hpp) is the
// short form. Units as synthesis.hpp: lengths in any one unit, angles in degrees.
#pragma once

#include "koppel/api/synthesis.hpp"

#include <string>
#include <utility>
#include <vector>

namespace koppel {

// The poses of a motion file (`poses: [[x, y, angle_deg], ...]`, README "synth motion").
// InputError naming the file, line and field.
std::vector<MotionPose> ReadMotionPoses(const std::string& path);

// Circle points on an n x n grid (cell centres) over the poses' box, enlarged by the poses' size
// (PoseScale) each way: MotionSpec::grid. InputError for n outside 1..100 or no pose.
std::vector<std::pair<double, double>> MotionGrid(const std::vector<MotionPose>& poses, int n);

// The centre-point and circle-point curves of four poses, one row per direction of a line through
// the base pole (360 directions): direction [deg], centre_x, centre_y, circle_x, circle_y.
// kNoDesign (message: why) when the poses have none; InputError unless there are four poses.
struct BurmesterCurveTable {
  DesignStatus status = DesignStatus::kNotRun;
  std::string message;
  DesignTable table;
};
BurmesterCurveTable MotionCurves(const std::vector<MotionPose>& poses);

// The whole search. status: kOk (a design without a branch or order defect is listed: the
// defect-free first, then by mu_min; four-bars that failed their re-analysis are counted and
// named in the notes), kNoDesign (message: no dyad, no four-bar, or only four-bars with a defect,
// which are still listed), kReanalysisFailed (nothing listed and failed > 0) or
// kInvalidRequest when the dyads make more four-bars than kMaxMotionFourBars (four_bars: how many;
// nothing was paired). paired: the dyads were paired into four-bars (false when the dyad choice
// found none for 2 to 4 poses: message says why). Each design as SynthesiseMotion's, its model and
// yaml named four-bar-<rank>; the yaml's comment names `source` (the poses file) and sweeps the
// drivable range (a full turn from the first pose for a crank). InputError as SynthesiseMotion.
struct MotionReport {
  DesignStatus status = DesignStatus::kNotRun;
  std::string message;
  std::vector<std::string> notes;  // what the dyad choice noted (e.g. the Ball–Burmester search)
  bool paired = false;
  int dyads = 0, rejected = 0, failed = 0;  // rejected: no crank, with require_crank
  int outside_space = 0;                     // four-bars outside MotionSpec::space, left out
  int defect_free = 0;                       // designs without a branch or order defect (listed first)
  double four_bars = 0;                      // the four-bars the dyads make, each re-analysed
  std::vector<std::string> failures;
  std::vector<Design> designs;  // the defect-free first, each part by mu_min, largest first
};
MotionReport SynthesiseMotionReport(const MotionSpec& spec, const std::string& source = "");

}  // namespace koppel

// Motion generation: four-bars from pairs of Burmester dyads (burmester.hpp), each re-analysed
// by the solver. The dyad driven at its centre point is the crank (input at A0), the other the
// rocker; the coupler is the moving plane.
//
// Re-analysis of one four-bar: the mechanism is assembled at every pose's crank angle from that
// pose's geometry and must put the plane's reference point and angle within 1e-9 of the
// mechanism's size (angles times that size) of the pose; then, reported and never hidden:
// - branch defect: the poses lie on different assembly branches (B on different sides of the line
//   A B0), or the crank, driven from the first pose, cannot reach them all on its branch;
// - order defect: driven in one sense from the first pose, the crank meets the poses out of order;
// - the Grashof type, the drivable range of the first pose's branch (a full turn or an interval)
//   and mu_min, the smallest transmission angle over the crank's travel from the first pose to
//   the last.
#pragma once

#include "koppel/analysis/classification.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/synthesis/burmester.hpp"
#include "koppel/synthesis/design_space.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace koppel {

struct MotionFourBar {
  Dyad crank, rocker;                  // A0 A (driven) and B0 B, circle points in the first pose
  Mechanism mechanism;                 // see four_bar_design.hpp; outputs P, theta, psi, mu
  bool passes = false;                 // every pose re-analysed within tolerance
  double pose_error = 0;               // largest position (or angle times size) error over the poses
  GrashofType grashof = GrashofType::kNotApplicable;
  bool branch_defect = false, order_defect = false;
  bool crank_turns_fully = false;      // the input at A0 turns fully on the first pose's branch
  double drive_from = 0, drive_to = 0; // drivable interval of that branch [rad]; full turn: the first pose's input + 0 .. 2 pi
  double mu_min = 0;                   // [rad], over the travel from the first pose to the last
  std::vector<double> pose_inputs;     // the crank angle at each pose [rad], in the sense of travel
  std::string message;                 // why it does not pass, or what the re-analysis noted
  bool DefectFree() const { return !branch_defect && !order_defect; }
};

// Re-analyses the four-bar of two dyads (the first driven). Degenerate links (shorter than 1e-9 of
// the poses' size) give passes = false with a message.
MotionFourBar AnalyseMotionFourBar(const std::vector<Pose>& poses, const Dyad& crank, const Dyad& rocker);

struct MotionOptions {
  bool require_crank = false;  // keep only four-bars whose input turns fully
  // four-bars outside it are left out (counted, the first one's broken constraint kept); K is the
  // plane's reference point, mu_min the four-bar's over the travel
  DesignSpace space;
  bool both_drives = true;     // each pair twice, driven at either centre point
  int threads = 0;             // 0: one per core
  bool IsValid(std::string* why) const;
};

struct MotionResult {
  std::vector<MotionFourBar> four_bars;  // passing ones: the defect-free first, each part by mu_min (largest first)
  int defect_free = 0;                   // of four_bars: without a branch or order defect
  int rejected = 0;                      // --require crank
  int outside_space = 0;                 // outside options.space
  std::string outside_reason;            // the constraint the first of them broke
  int failed = 0;                        // did not pass the re-analysis (a defect of the synthesis)
  std::vector<std::string> failures;     // their messages
};

// The four-bars FourBarsFromDyads makes of `dyads` dyads (the work: about 2.5 ms each), to be
// checked against kMaxMotionFourBars before the work starts.
std::uint64_t MotionFourBarCount(std::size_t dyads, const MotionOptions& options);

// A four-bar's sizes for the design space: pivots, links, the plane's reference point in the
// coupler's frame (in the first pose), its mu_min.
FourBarSizes MotionFourBarSizes(const std::vector<Pose>& poses, const MotionFourBar& f);

// Every pair of distinct dyads made a four-bar and re-analysed, on every core.
MotionResult FourBarsFromDyads(const std::vector<Pose>& poses, const std::vector<Dyad>& dyads, const MotionOptions& options);

}  // namespace koppel

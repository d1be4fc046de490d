// The table of figure quantities and their evaluators. Each evaluator recomputes one number with
// the generic solver (sweeps, stationary points, dead centres, straight-line and
// proportionality analysis, drivable ranges), never with a closed form of the mechanism.
#include "koppel/catalog/figure_quantities.hpp"

#include "figures.hpp"
#include "koppel/analysis/coupler_curve.hpp"
#include "koppel/analysis/extremes.hpp"
#include "koppel/analysis/proportionality.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/structure.hpp"
#include "koppel/solver/constraints.hpp"
#include "koppel/synthesis/cognates.hpp"

#include <algorithm>
#include <cmath>

namespace koppel {
namespace {

FigureValue Value(double v) { return {v, ""}; }
FigureValue NotComputed(std::string why) { return {std::nullopt, std::move(why)}; }

// min, max, argmin, argmax, stroke: the extremes of an output over the card's range (or from..to),
// refined (extremes.hpp: stationary points, a transmission angle's folds, the ends of a range that
// is not whole turns), so figures are exact, not sampled
FigureValue Extremes(FigureContext& c, const FigureCheck& f) {
  const int output = c.Output(f);
  const bool own_range = c.Has(f, "from") || c.Has(f, "to");
  OutputExtremes found;
  if (own_range) {
    SweepOptions range = c.CardRange();
    if (c.Has(f, "from")) range.from = c.Input(f, "from");
    if (c.Has(f, "to")) range.to = c.Input(f, "to");
    found = FindOutputExtremes(c.mechanism(), output, f.component, range);
  }
  const OutputExtremes& e = own_range ? found : c.DeadCentres(output, f.component).extremes;
  if (!e.sweep.complete()) return NotComputed(e.sweep.message);
  if (!Usable(e.status)) return NotComputed(e.message);
  switch (f.quantity) {
    case FigureQuantity::kMin: return Value(e.minimum.value);
    case FigureQuantity::kMax: return Value(e.maximum.value);
    case FigureQuantity::kArgMin: return Value(e.minimum.input);
    case FigureQuantity::kArgMax: return Value(e.maximum.input);
    default: return Value(e.maximum.value - e.minimum.value);
  }
}

// value and derivative: one sample at `at`, reached from the assembly along the branch
FigureValue AtInput(FigureContext& c, const FigureCheck& f) {
  const bool derivative = f.quantity == FigureQuantity::kDerivative;
  SweepOptions options;
  options.from = options.to = c.Input(f, "at");
  options.step = c.CardRange().step;
  options.order = derivative ? c.Order(f, "order") : 0;
  const SweepResult sweep = Sweep(c.mechanism(), options);
  if (!sweep.complete()) return NotComputed(sweep.message);
  if (!sweep.valid_order.empty() && sweep.valid_order[0] < options.order)
    return NotComputed("the pose at `at` is singular: order " + std::to_string(options.order) + " is not computable there");
  c.Output(f);
  return Value(sweep.outputs(0, OutputColumn(c.mechanism(), f.output, f.component, options.order, options.order)));
}

// the dead centres of the output (dead_centres.hpp): the crank angle from the folded to the
// extended dead centre counter-clockwise, either dead centre's input, the time ratio
FigureValue DeadCentreFigure(FigureContext& c, const FigureCheck& f) {
  const DeadCentreReport& r = c.DeadCentres(c.Output(f), f.component);
  // dead centres found over only the drivable part of the card's range are not the document's
  if (!r.sweep.complete()) return NotComputed(r.sweep.message);
  if (!r.has_stroke) return NotComputed(r.sweep.message.empty() ? "no two dead centres found" : r.sweep.message);
  // the extended and folded dead centre proper need the crank-coupler line-up; span and time ratio
  // are defined by the output's maximum and minimum as well (dead_centres.hpp)
  const bool positions = f.quantity == FigureQuantity::kDeadCentrePhiA || f.quantity == FigureQuantity::kDeadCentrePhiI;
  if (positions && !r.classified) return NotComputed("the dead centres are not crank-coupler line-ups (extended/folded)");
  const double turn = 2 * kPi;
  auto wrap = [turn](double a) { return std::fmod(std::fmod(a, turn) + turn, turn); };
  switch (f.quantity) {
    case FigureQuantity::kDeadCentreSpan: return Value(wrap(r.phi_a - r.phi_i));
    case FigureQuantity::kDeadCentrePhiA: return Value(wrap(r.phi_a));
    case FigureQuantity::kDeadCentrePhiI: return Value(wrap(r.phi_i));
    default:
      if (!c.mechanism().InputIsAngle()) return NotComputed("a time ratio needs a rotating drive");
      // phi_H / (360 deg - phi_H), phi_H from phi_a to phi_i counter-clockwise; the time ratio >= 1
      return Value(f.quantity == FigureQuantity::kTimeRatio ? r.TimeRatio() : r.phase_ratio);
  }
}

// seed 001's reading example: band about the flat-point tangent (proportionality.hpp)
FigureValue ProportionalityFigure(FigureContext& c, const FigureCheck& f) {
  const Mechanism& m = c.mechanism();
  const Proportionality p = ProportionalityDeviation(m, c.Output(f), c.Input(f, "from"), c.Input(f, "to"), CrankLength(m),
                                                     std::nullopt, std::abs(c.CardRange().step) / 20);
  if (!Usable(p.status)) return NotComputed(p.message);
  if (!p.sweep.complete()) return NotComputed(p.sweep.message);  // the whole range, not its drivable part
  return Value(f.quantity == FigureQuantity::kProportionalityDs ? p.delta_s : p.qp);
}

// seed 003's reading example: the longest stretch through K_I with Q_G <= qg (coupler_curve.hpp)
FigureValue StraightStretchFigure(FigureContext& c, const FigureCheck& f) {
  std::optional<double> at;
  if (c.Has(f, "at")) at = c.Input(f, "at");
  const StraightStretch& s = c.LongestStretch(c.Output(f), c.Number(f, "qg"), at);
  if (!s.ok()) return NotComputed(s.message);
  switch (f.quantity) {
    case FigureQuantity::kStraightlinePhiG: return Value(s.phi_g);
    case FigureQuantity::kStraightlinePhiA: return Value(s.phi_a);
    default: return Value(s.length);
  }
}

// the band width of the stretch from..to about the tangent at `at`
FigureValue StraightBand(FigureContext& c, const FigureCheck& f) {
  const Mechanism& m = c.mechanism();
  const StraightStretch s =
      StretchBand(m, m.outputs[c.Output(f)].p, c.Input(f, "at"), c.Input(f, "from"), c.Input(f, "to"), std::abs(c.CardRange().step) / 20);
  if (!s.ok()) return NotComputed(s.message);
  return Value(s.band);
}

FigureValue CognateFrame(FigureContext& c, const FigureCheck& f) {
  const Cognates cognates = RobertsCognates(c.mechanism(), c.mechanism().outputs[c.Output(f)].p);
  if (!cognates.ok()) return NotComputed(cognates.message);
  return Value(cognates.frame_first);
}

// The branch the assembly hint chooses, from the drivable ranges (ranges.hpp); nullptr and a
// reason when they could not be found.
const BranchRange* HintBranch(const RangeReport& report, std::string* why_not) {
  if (report.status != RangeStatus::kDone || report.branches.empty() || report.HasFailure()) {
    *why_not = report.message.empty() ? report.Brief() : report.message;
    return nullptr;
  }
  return &report.branches.front();
}

FigureValue InputLimit(FigureContext& c, const FigureCheck& f) {
  std::string why_not;
  const BranchRange* branch = HintBranch(c.Ranges(), &why_not);
  if (!branch) return NotComputed(why_not);
  const bool low = f.quantity == FigureQuantity::kInputLow;
  const RangeEnd end = low ? branch->from_kind : branch->to_kind;
  if (end != RangeEnd::kLimit && end != RangeEnd::kBranchPoint)
    return NotComputed(std::string("the drivable range ends in no limit position on this side: ") + ToString(end));
  return Value(low ? branch->from : branch->to);
}

// The mechanism driven at R joint `joint` instead, on the same assembly branch: the assembly
// hint is the original's assembled pose, point by point.
std::optional<Mechanism> DrivenAt(const Mechanism& m, int joint, std::string* why_not) {
  SweepOptions here;
  here.from = here.to = m.hint.input;
  here.order = 0;
  const SweepResult pose = Sweep(m, here);
  if (!pose.complete()) {
    *why_not = pose.message;
    return std::nullopt;
  }
  const Eigen::VectorXd q = pose.poses.row(0).transpose();
  const ConstraintSystem system(m);
  Mechanism driven = m;
  driven.drive.joint = joint;
  driven.drive.zero = 0;
  const Joint& j = m.joints[joint];
  driven.hint.input = system.LinkAngle(j.link_b, q.data()) - system.LinkAngle(j.link_a, q.data());
  driven.hint.points.clear();
  for (int l = 0; l < static_cast<int>(m.links.size()); ++l) {
    if (m.links[l].is_frame) continue;
    for (int p = 0; p < static_cast<int>(m.links[l].points.size()); ++p) {
      double xy[2];
      system.GlobalPoint({l, p}, q.data(), xy);
      driven.hint.points.push_back({{l, p}, Eigen::Vector2d(xy[0], xy[1])});
    }
  }
  return driven;
}

// 1 when the branch's drivable range is a full turn, 0 when it ends in limit positions both ways;
// anything else (the search bound) is not an answer
FigureValue TurnsFully(const BranchRange& branch) {
  if (branch.to_kind == RangeEnd::kFullTurn) return Value(1.0);
  const auto limited = [](RangeEnd end) { return end == RangeEnd::kLimit || end == RangeEnd::kBranchPoint; };
  if (limited(branch.from_kind) && limited(branch.to_kind)) return Value(0.0);
  return NotComputed(std::string("the drivable range ends in ") + ToString(branch.from_kind) + " and " + ToString(branch.to_kind));
}

// whether a joint (default: the drive) turns fully on the assembly's branch
FigureValue Revolves(FigureContext& c, const FigureCheck& f) {
  const Mechanism& m = c.mechanism();
  const int joint = c.Has(f, "joint") ? c.Joint(f, "joint") : m.drive.joint;
  std::string why_not;
  if (joint == m.drive.joint) {
    const BranchRange* branch = HintBranch(c.Ranges(), &why_not);
    return branch ? TurnsFully(*branch) : NotComputed(why_not);
  }
  const std::optional<Mechanism> driven = DrivenAt(m, joint, &why_not);
  if (!driven) return NotComputed(why_not);
  const RangeReport ranges = DrivableRanges(*driven);
  const BranchRange* branch = HintBranch(ranges, &why_not);
  return branch ? TurnsFully(*branch) : NotComputed(why_not);
}

// the input of the branch point (Verzweigungslage, e.g. a change point) nearest `near` that the
// sweep of the card's range crossed (sweep.hpp)
FigureValue BranchPointFigure(FigureContext& c, const FigureCheck& f) {
  const SweepResult& sweep = c.RangeSweep(f);
  if (!sweep.complete()) return NotComputed(sweep.message);
  const double near = c.Input(f, "near");
  std::optional<double> best;
  for (const SingularPoint& p : sweep.singular_points) {
    if (p.kind != SingularKind::kBranchPoint) continue;
    if (!best || std::abs(p.input - near) < std::abs(*best - near)) best = p.input;
  }
  if (!best) return NotComputed("the sweep met no branch point");
  return Value(*best);
}

// full turns of an angle output from the first to the last sample of the sweep (link angles
// are continuous along a sweep: a revolving output gains 2 pi per turn, a rocker returns)
FigureValue Turns(FigureContext& c, const FigureCheck& f) {
  const SweepResult& sweep = c.RangeSweep(f);
  if (!sweep.complete()) return NotComputed(sweep.message);
  const int column = OutputColumn(c.mechanism(), f.output, 0, 0, 0);
  const double change = sweep.outputs(sweep.outputs.rows() - 1, column) - sweep.outputs(0, column);
  return Value(change / (2 * kPi));
}

constexpr FigureArgument kFrom{"from", ArgumentKind::kInput, false};
constexpr FigureArgument kTo{"to", ArgumentKind::kInput, false};
constexpr FigureArgument kFromRequired{"from", ArgumentKind::kInput, true};
constexpr FigureArgument kToRequired{"to", ArgumentKind::kInput, true};
constexpr FigureArgument kAtRequired{"at", ArgumentKind::kInput, true};

std::vector<FigureQuantityInfo> MakeTable() {
  using Q = FigureQuantity;
  using U = ValueUnit;
  using O = OutputUse;
  using A = AngleKind;
  const FigureArgument qg{"qg", ArgumentKind::kNumber, true};
  const FigureArgument at{"at", ArgumentKind::kInput, false};
  return {
      {Q::kMin, "min", O::kAny, U::kOfOutput, A::kPosition, {kFrom, kTo}, "least value of the output over the sweep (or from..to)", Extremes},
      {Q::kMax, "max", O::kAny, U::kOfOutput, A::kPosition, {kFrom, kTo}, "greatest value of the output over the sweep (or from..to)", Extremes},
      {Q::kArgMin, "argmin", O::kAny, U::kOfInput, A::kPosition, {kFrom, kTo}, "input where the output is least", Extremes},
      {Q::kArgMax, "argmax", O::kAny, U::kOfInput, A::kPosition, {kFrom, kTo}, "input where the output is greatest", Extremes},
      {Q::kStroke, "stroke", O::kAny, U::kOfOutput, A::kSpan, {kFrom, kTo}, "max - min of the output (stroke, swing angle)", Extremes},
      {Q::kValue, "value", O::kAny, U::kOfOutput, A::kPosition, {kAtRequired}, "the output at input `at`", AtInput},
      {Q::kDerivative, "derivative", O::kAny, U::kPlain, A::kSpan, {kAtRequired, {"order", ArgumentKind::kOrder, true}},
       "transfer function of order `order` at input `at` (per radian of an R drive)", AtInput},
      {Q::kDeadCentreSpan, "deadcentre_span", O::kAny, U::kOfInput, A::kSpan, {},
       "crank angle from the folded to the extended dead centre (else: from the minimum to the maximum), counter-clockwise",
       DeadCentreFigure},
      {Q::kDeadCentrePhiA, "deadcentre_phi_a", O::kAny, U::kOfInput, A::kPosition, {}, "input of the extended dead centre (äußere Totlage)",
       DeadCentreFigure},
      {Q::kDeadCentrePhiI, "deadcentre_phi_i", O::kAny, U::kOfInput, A::kPosition, {}, "input of the folded dead centre (innere Totlage)",
       DeadCentreFigure},
      {Q::kPhaseRatio, "phase_ratio", O::kAny, U::kPlain, A::kSpan, {},
       "phase ratio phi_H / (360 deg - phi_H), phi_H from the extended to the folded dead centre (else: from the maximum to the minimum)",
       DeadCentreFigure},
      {Q::kTimeRatio, "time_ratio", O::kAny, U::kPlain, A::kSpan, {},
       "time ratio: the slow stroke's crank angle over the fast one's (the phase ratio or its reciprocal, >= 1)", DeadCentreFigure},
      {Q::kProportionalityDs, "proportionality_ds", O::kAny, U::kPlain, A::kSpan, {kFromRequired, kToRequired},
       "band width about the flat-point tangent over from..to (Dittrich, Proportionalgetriebe)", ProportionalityFigure},
      {Q::kProportionalityQp, "proportionality_qp", O::kAny, U::kPlain, A::kSpan, {kFromRequired, kToRequired},
       "Q_P = (Δs / l1) / phi_P over from..to (Dittrich, Proportionalgetriebe)", ProportionalityFigure},
      {Q::kStraightlinePhiG, "straightline_phi_g", O::kPoint, U::kOfInput, A::kSpan, {qg, at},
       "input span of the longest stretch with Q_G <= qg through `at` (Dittrich and Müller, Meyer zur Capellen linkage)", StraightStretchFigure},
      {Q::kStraightlinePhiA, "straightline_phi_a", O::kPoint, U::kOfInput, A::kPosition, {qg, at}, "input where that stretch begins",
       StraightStretchFigure},
      {Q::kStraightlineLength, "straightline_length", O::kPoint, U::kPlain, A::kSpan, {qg, at}, "length L of that stretch along its tangent",
       StraightStretchFigure},
      {Q::kStraightlineBand, "straightline_band", O::kPoint, U::kPlain, A::kSpan, {kFromRequired, kToRequired, kAtRequired},
       "width of the band parallel to the tangent at `at` that holds the path over from..to", StraightBand},
      {Q::kCognateFrame, "cognate_frame", O::kPoint, U::kPlain, A::kSpan, {}, "frame length of the first Roberts cognate", CognateFrame},
      {Q::kInputLow, "input_low", O::kNone, U::kOfInput, A::kPosition, {}, "lower limit position of the drive (drivable range)", InputLimit},
      {Q::kInputHigh, "input_high", O::kNone, U::kOfInput, A::kPosition, {}, "upper limit position of the drive (drivable range)", InputLimit},
      {Q::kRevolves, "revolves", O::kNone, U::kPlain, A::kSpan, {{"joint", ArgumentKind::kJoint, false}},
       "1 when the R joint (default: the drive) turns fully on this branch, 0 when it oscillates", Revolves},
      {Q::kTurns, "turns", O::kAngle, U::kPlain, A::kSpan, {kFrom, kTo}, "full turns of an angle output over the sweep", Turns},
      {Q::kBranchPoint, "branch_point", O::kNone, U::kOfInput, A::kPosition, {{"near", ArgumentKind::kInput, true}},
       "input of the branch point (change point) nearest `near` that the sweep crosses", BranchPointFigure},
      {Q::kRest, "rest", O::kAny, U::kOfOutput, A::kSpan, {kFromRequired, kToRequired},
       "a dwell (Rast): max - min of the output over from..to; expected 0, the tolerance is the band it rests in (declares the class dwell)",
       Extremes},
  };
}

}  // namespace

const std::vector<FigureQuantityInfo>& FigureQuantities() {
  static const std::vector<FigureQuantityInfo> table = MakeTable();
  return table;
}

const FigureQuantityInfo& QuantityInfo(FigureQuantity quantity) {
  return FigureQuantities().at(static_cast<size_t>(quantity));
}

const FigureQuantityInfo* FindFigureQuantity(const std::string& name) {
  for (const FigureQuantityInfo& info : FigureQuantities()) {
    if (name == info.name) return &info;
  }
  return nullptr;
}

}  // namespace koppel

// Motion generation (motion_synthesis.hpp, and SynthesiseMotion of synthesis.hpp): the dyads by
// the number of poses, paired into four-bars that the solver re-analyses through every pose.
#include "koppel/api/motion_synthesis.hpp"

#include "design_units.hpp"
#include "display.hpp"

#include "koppel/catalog/mechanism_writer.hpp"
#include "koppel/catalog/synthesis_spec.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/synthesis/motion_dyads.hpp"
#include "koppel/synthesis/motion_synthesis.hpp"

#include <fmt/core.h>

#include <cmath>

namespace koppel {

using api_detail::BadInput;

namespace {

void MotionRequire(bool valid, const std::string& field, const std::string& why) {
  if (!valid) BadInput("synthesis request", field, why);
}

std::vector<Pose> InternalPoses(const std::vector<MotionPose>& poses) {
  std::vector<Pose> out;
  for (const MotionPose& p : poses) {
    MotionRequire(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.angle), "poses", "a pose is not finite");
    out.push_back({Eigen::Vector2d(p.x, p.y), DegToRad(p.angle)});
  }
  return out;
}

std::string MotionComment(const MotionFourBar& f, int rank, const std::string& source) {
  std::string inputs;
  for (double v : f.pose_inputs) inputs += fmt::format("{}{:.6g}", inputs.empty() ? "" : ", ", RadToDeg(v));
  return fmt::format("Four-bar {} of koppel synth motion {} (Burmester). The coupler is the moving plane: its point P and\n"
                     "its angle theta pass through every pose (re-analysis error {:.3g}). Grashof type {}; branch defect {}; order\n"
                     "defect {}; the input phi (crank angle against +x) {}; mu_min over the poses' travel {:.6g} deg.\n"
                     "Crank angles of the poses: {} deg.",
                     rank, source, f.pose_error, ToString(f.grashof), f.branch_defect ? "yes" : "no", f.order_defect ? "yes" : "no",
                     f.crank_turns_fully ? "turns fully"
                                         : fmt::format("reaches {:.6g} .. {:.6g} deg on this branch", RadToDeg(f.drive_from), RadToDeg(f.drive_to)),
                     RadToDeg(f.mu_min), inputs);
}

// One four-bar as a Design named four-bar-<rank>: figures as synthesis.hpp lists them.
Design MotionDesign(const MotionFourBar& f, int rank, const std::string& source, const std::optional<Loads>& units) {
  std::vector<DesignFigure> figures;
  const auto point = [&](const std::string& name, const Eigen::Vector2d& p) {
    figures.push_back({ComponentName(name, 0), p.x(), "length"});
    figures.push_back({ComponentName(name, 1), p.y(), "length"});
  };
  point("A0", f.crank.centre);
  point("A", f.crank.circle);
  point("B", f.rocker.circle);
  point("B0", f.rocker.centre);
  figures.push_back({"mu_min", RadToDeg(f.mu_min), "deg"});
  figures.push_back({"branch_defect", f.branch_defect ? 1.0 : 0.0, "bool"});
  figures.push_back({"order_defect", f.order_defect ? 1.0 : 0.0, "bool"});
  figures.push_back({"crank_turns_fully", f.crank_turns_fully ? 1.0 : 0.0, "bool"});
  figures.push_back({"pose_error", f.pose_error, "length"});
  for (size_t i = 0; i < f.pose_inputs.size(); ++i) figures.push_back({fmt::format("pose{}_input", i + 1), RadToDeg(f.pose_inputs[i]), "deg"});
  Design d;
  d.status = DesignStatus::kOk;
  d.message = ToString(f.grashof);
  d.figures = std::move(figures);
  Mechanism m = f.mechanism;
  m.name = fmt::format("four-bar-{}", rank);
  d.model = Model::FromMechanism(m);
  // a crank: a full turn from the first pose; else its drivable interval on the first pose's branch
  const double from = RadToDeg(f.drive_from), to = RadToDeg(f.drive_to);
  const SweepDefaults sweep = f.crank_turns_fully ? SweepDefaults{from, from + 360, 1} : SweepDefaults{from, to, (to - from) / 360};
  d.yaml = WriteMechanismYaml(m, MotionComment(f, rank, source), sweep, {}, UnitsFor(units));
  LabelLengths(units, d.figures);
  return d;
}

DyadRequest Request(const MotionSpec& spec, const std::vector<Pose>& poses) {
  DyadRequest request;
  for (const auto& [x, y] : spec.circle_points) request.circle_points.emplace_back(x, y);
  if (spec.grid != 0) {
    MotionRequire(poses.size() == 3, "grid", "a grid of circle points is for three poses");
    for (const auto& [x, y] : MotionGrid(spec.poses, spec.grid)) request.circle_points.emplace_back(x, y);
    request.skip_unsolvable = true;
  }
  request.crank_turn = DegToRad(spec.crank_turn);
  request.curve_samples = spec.curve_samples;
  return request;
}

void Paired(const std::vector<Pose>& poses, const std::vector<Dyad>& dyads, const MotionOptions& options, const std::string& source,
            const std::optional<Loads>& units, MotionReport& out) {
  const MotionResult result = FourBarsFromDyads(poses, dyads, options);
  out.paired = true;
  out.rejected = result.rejected;
  out.outside_space = result.outside_space;
  out.failed = result.failed;
  out.failures = result.failures;
  for (size_t i = 0; i < result.four_bars.size(); ++i) out.designs.push_back(MotionDesign(result.four_bars[i], static_cast<int>(i + 1), source, units));
  out.defect_free = result.defect_free;
  const std::string failures = result.failed == 0 ? "" :
      fmt::format("{} four-bar(s) failed their re-analysis and are not listed{}", result.failed,
                  result.failures.empty() ? "" : " (the first: " + result.failures.front() + ")");
  if (result.defect_free > 0) {
    out.status = DesignStatus::kOk;
    if (!failures.empty()) out.notes.push_back(failures);
  } else if (!out.designs.empty()) {
    out.status = DesignStatus::kNoDesign;
    out.message = fmt::format("none of the {} four-bars carries the plane through the poses without a branch or order defect "
                              "(listed with their defects){}", out.designs.size(), failures.empty() ? "" : "; " + failures);
  } else if (result.outside_space > 0) {  // the space left nothing: say so, and what else failed
    out.status = DesignStatus::kNoDesign;
    out.message = fmt::format("none of the four-bars lies inside the design space ({} outside); the first broke {}", result.outside_space,
                              result.outside_reason);
    if (!failures.empty()) out.notes.push_back(failures);
  } else if (result.failed > 0) {
    out.status = DesignStatus::kReanalysisFailed;
    out.message = failures;
  } else {
    out.status = DesignStatus::kNoDesign;
    out.message = dyads.empty() ? "no dyad meets the poses" : "no four-bar meets the request";
  }
}

}  // namespace

std::vector<MotionPose> ReadMotionPoses(const std::string& path) {
  std::vector<MotionPose> poses;
  for (const Pose& p : ReadMotionSpec(path).poses) poses.push_back({p.point.x(), p.point.y(), RadToDeg(p.angle)});
  return poses;
}

std::vector<std::pair<double, double>> MotionGrid(const std::vector<MotionPose>& poses, int n) {
  MotionRequire(n >= 1 && n <= 100, "grid", "must be a whole number from 1 to 100");
  MotionRequire(!poses.empty(), "poses", "no pose");
  const std::vector<Pose> internal = InternalPoses(poses);
  Eigen::Vector2d lo = internal[0].point, hi = internal[0].point;
  for (const Pose& p : internal) {
    lo = lo.cwiseMin(p.point);
    hi = hi.cwiseMax(p.point);
  }
  const double margin = PoseScale(internal);
  lo.array() -= margin;
  hi.array() += margin;
  std::vector<std::pair<double, double>> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) points.emplace_back(lo.x() + (hi.x() - lo.x()) * (i + 0.5) / n, lo.y() + (hi.y() - lo.y()) * (j + 0.5) / n);
  return points;
}

BurmesterCurveTable MotionCurves(const std::vector<MotionPose>& poses) {
  MotionRequire(poses.size() == 4, "poses", "the Burmester curves are for four poses");
  const BurmesterCurves curves = CentrePointCurve(InternalPoses(poses), 360);
  BurmesterCurveTable out;
  out.status = curves.ok() ? DesignStatus::kOk : DesignStatus::kNoDesign;
  out.message = curves.message;
  if (!curves.ok()) return out;
  out.table.columns = {"direction", "centre_x", "centre_y", "circle_x", "circle_y"};
  for (const BurmesterCurveSample& s : curves.samples)
    out.table.rows.push_back({RadToDeg(s.direction), s.dyad.centre.x(), s.dyad.centre.y(), s.dyad.circle.x(), s.dyad.circle.y()});
  return out;
}

MotionReport SynthesiseMotionReport(const MotionSpec& spec, const std::string& source) {
  const std::optional<Loads> units = UnitsOf(spec.units);  // an unknown unit refused before the search
  MotionRequire(spec.threads >= 0 && spec.threads <= kMaxThreads, "threads", fmt::format("must be 0 (one per core) to {}", kMaxThreads));
  const std::vector<Pose> poses = InternalPoses(spec.poses);
  const DyadChoice dyads = DyadsForPoses(poses, Request(spec, poses));
  if (dyads.status == BurmesterStatus::kInvalidRequest) BadInput(source.empty() ? "synthesis request" : source, "poses/circle_points", dyads.message);
  MotionReport out;
  if (!dyads.message.empty()) out.notes.push_back(dyads.message);
  out.dyads = static_cast<int>(dyads.dyads.size());
  // five poses without a real Ball–Burmester point: no dyad, paired all the same (none)
  if (!dyads.ok() && poses.size() != 5) {
    out.status = DesignStatus::kNoDesign;
    out.message = dyads.message.empty() ? "no dyad meets the poses" : dyads.message;
    return out;
  }
  if (const std::string why = spec.space.Unsupported("synth motion", true, false); !why.empty())
    BadInput(source.empty() ? "synthesis request" : source, "design", why);
  MotionOptions options;
  options.require_crank = spec.require_crank;
  options.space = spec.space;
  options.threads = spec.threads;
  // every ordered pair is a four-bar to re-analyse: the bound on the work, before it starts
  out.four_bars = static_cast<double>(MotionFourBarCount(dyads.dyads.size(), options));
  if (out.four_bars > static_cast<double>(kMaxMotionFourBars)) {
    out.status = DesignStatus::kInvalidRequest;
    out.message = fmt::format("{} dyads make {:.3g} four-bars to re-analyse, more than the limit of {} (kMaxMotionFourBars, about 2.5 ms each)",
                              out.dyads, out.four_bars, kMaxMotionFourBars);
    return out;
  }
  Paired(poses, dyads.dyads, options, source, units, out);
  return out;
}

Designs SynthesiseMotion(const MotionSpec& spec) {
  const MotionReport report = SynthesiseMotionReport(spec);
  if (report.status == DesignStatus::kInvalidRequest) BadInput("synthesis request", "curve_samples/circle_points/grid", report.message);
  Designs out;
  out.status = report.status;
  out.message = report.message;
  out.notes = report.notes;
  if (report.status == DesignStatus::kOk) out.designs = report.designs;
  return out;
}

}  // namespace koppel

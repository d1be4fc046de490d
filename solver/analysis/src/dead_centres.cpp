#include "koppel/analysis/dead_centres.hpp"
#include "koppel/core/angles.hpp"

#include "koppel/analysis/stationary.hpp"

#include <algorithm>
#include <cmath>

namespace koppel {
namespace {

constexpr double kTwoPi = 2 * kPi;
// Crank and coupler count as lined up when the sine of their angle is below this: the
// dead centre is refined to 1e-12, so a true line-up is at roundoff level.
constexpr double kLineUp = 1e-7;

}  // namespace

const char* ToString(DeadCentreKind kind) {
  switch (kind) {
    case DeadCentreKind::kExtended: return "extended";
    case DeadCentreKind::kFolded: return "folded";
    case DeadCentreKind::kUnclassified: return "unclassified";
  }
  return "unclassified";
}

std::string DeadCentreReport::Brief() const {
  return std::string(ToString(status)) + ": " + std::to_string(points.size()) + " dead centre" + (points.size() == 1 ? "" : "s") +
         (has_stroke ? ", stroke " + std::to_string(stroke) : "") + (message.empty() ? "" : "; " + message);
}

DeadCentreKind ClassifyLineUp(const Mechanism& m, const Eigen::VectorXd& q) {
  const Joint& drive = m.joints[m.drive.joint];
  if (drive.type != JointType::kRevolute) return DeadCentreKind::kUnclassified;
  const int crank = m.links[drive.link_a].is_frame ? drive.link_b : drive.link_a;
  const int crank_coupler = OtherJointOfBinaryLink(m, crank, m.drive.joint);
  if (crank_coupler < 0 || m.joints[crank_coupler].type != JointType::kRevolute) return DeadCentreKind::kUnclassified;
  const Joint& cc = m.joints[crank_coupler];
  const int coupler = cc.link_a == crank ? cc.link_b : cc.link_a;
  const int coupler_far = OtherJointOfBinaryLink(m, coupler, crank_coupler);
  if (coupler_far < 0) return DeadCentreKind::kUnclassified;
  const ConstraintSystem system(m);
  double pivot[2], joint[2], far[2];
  system.GlobalPoint(JointPointOn(drive, crank), q.data(), pivot);
  system.GlobalPoint(JointPointOn(cc, crank), q.data(), joint);
  system.GlobalPoint(JointPointOn(m.joints[coupler_far], coupler), q.data(), far);
  const Eigen::Vector2d u(joint[0] - pivot[0], joint[1] - pivot[1]), v(far[0] - joint[0], far[1] - joint[1]);
  if (u.norm() == 0 || v.norm() == 0) return DeadCentreKind::kUnclassified;
  const double cross = (u.x() * v.y() - u.y() * v.x()) / (u.norm() * v.norm());
  if (std::abs(cross) > kLineUp) return DeadCentreKind::kUnclassified;
  return u.dot(v) > 0 ? DeadCentreKind::kExtended : DeadCentreKind::kFolded;
}

DeadCentreReport FindDeadCentres(const Mechanism& m, int output, int component, const SweepOptions& range) {
  DeadCentreReport report;
  SweepOptions options = range;
  options.order = 2;
  const SweepResult sweep = Sweep(m, options);
  report.sweep = EventsOf(sweep);  // dead centres are searched over the part swept
  report.message = sweep.message;
  if (sweep.inputs.empty()) {
    report.status = AnalysisStatus::kFailed;
    return report;
  }
  report.status = sweep.complete() ? AnalysisStatus::kComplete : AnalysisStatus::kPartial;
  const int column = OutputColumn(m, output, component, 2);
  const int n = static_cast<int>(sweep.inputs.size());
  const double resolution = std::abs(options.step);
  for (int i = 0; i + 1 < n; ++i) {
    const double d0 = sweep.outputs(i, column + 1), d1 = sweep.outputs(i + 1, column + 1);
    if (!(d0 == 0.0 || (d0 > 0) != (d1 > 0))) continue;
    int start = std::abs(d0) <= std::abs(d1) ? i : i + 1;
    // no path starts on a singular pose (a dead centre at a change point): start beside it
    if (sweep.singular[start]) start = start == i ? i + 1 : i;
    StationaryOptions stationary;
    stationary.max_step = resolution;
    stationary.continuation = options.continuation;
    const StationaryPoint p = RefineStationary(m, output, component, sweep.inputs[start], sweep.poses.row(start).transpose(), stationary);
    if (!p.ok()) continue;
    // one dead centre per sign change: drop a repeat found from the neighbouring interval
    const bool repeat = std::any_of(report.points.begin(), report.points.end(),
                                    [&](const DeadCentre& d) { return std::abs(d.input - p.input) < 1e-9; });
    const bool full_turn_repeat = m.InputIsAngle() && std::any_of(report.points.begin(), report.points.end(), [&](const DeadCentre& d) {
      return std::abs(std::abs(d.input - p.input) - kTwoPi) < 1e-9;
    });
    if (repeat || full_turn_repeat) continue;
    report.points.push_back({p.input, p.value, p.second, ClassifyLineUp(m, p.q)});
  }
  std::sort(report.points.begin(), report.points.end(), [](const DeadCentre& a, const DeadCentre& b) { return a.input < b.input; });

  // stroke summary: one extended and one folded, else the overall maximum and minimum
  const DeadCentre* a = nullptr;
  const DeadCentre* i = nullptr;
  int extended = 0, folded = 0;
  for (const DeadCentre& d : report.points) {
    if (d.kind == DeadCentreKind::kExtended) { ++extended; a = &d; }
    if (d.kind == DeadCentreKind::kFolded) { ++folded; i = &d; }
  }
  report.classified = extended == 1 && folded == 1;
  if (!report.classified && report.points.size() >= 2) {
    a = &*std::max_element(report.points.begin(), report.points.end(), [](const DeadCentre& x, const DeadCentre& y) { return x.value < y.value; });
    i = &*std::min_element(report.points.begin(), report.points.end(), [](const DeadCentre& x, const DeadCentre& y) { return x.value < y.value; });
  }
  if (a && i && a != i) {
    report.has_stroke = true;
    report.phi_a = a->input;
    report.phi_i = i->input;
    report.s_a = a->value;
    report.s_i = i->value;
    report.stroke = std::abs(a->value - i->value);
    if (m.InputIsAngle()) {
      report.phi_h = std::fmod(std::fmod(i->input - a->input, kTwoPi) + kTwoPi, kTwoPi);
      report.phase_ratio = report.phi_h / (kTwoPi - report.phi_h);
    }
  }
  return report;
}

}  // namespace koppel

#include "koppel/analysis/dead_centres.hpp"
#include "koppel/core/angles.hpp"

#include "extremes_of_search.hpp"
#include "stationary_search.hpp"

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

namespace {

// One extended and one folded dead centre, else the overall maximum and minimum: the stroke.
void Stroke(const Mechanism& m, DeadCentreReport& report) {
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
  if (!a || !i || a == i) return;
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

}  // namespace

DeadCentreReport FindDeadCentres(const Mechanism& m, int output, int component, const SweepOptions& range) {
  DeadCentreReport report;
  const StationarySearch search = SearchStationaryPoints(m, output, component, range);
  report.sweep = EventsOf(search.sweep);  // dead centres are searched over the part swept
  report.message = search.sweep.message;
  report.extremes = ExtremesOf(m, output, search);
  if (search.sweep.inputs.empty()) {
    report.status = AnalysisStatus::kFailed;
    return report;
  }
  report.status = search.sweep.complete() ? AnalysisStatus::kComplete : AnalysisStatus::kPartial;
  for (const StationaryPoint& p : search.points) report.points.push_back({p.input, p.value, p.second, ClassifyLineUp(m, p.q)});
  report.unresolved = search.unresolved;
  if (!search.unresolved.empty()) {
    const std::string why = std::to_string(search.unresolved.size()) + " sign change" + (search.unresolved.size() == 1 ? "" : "s") +
                            " of the first-order transfer function not refined to a dead centre: " + search.unresolved_message;
    report.message = report.message.empty() ? why : report.message + "; " + why;
  }
  Stroke(m, report);
  return report;
}

}  // namespace koppel

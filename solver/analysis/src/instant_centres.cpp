#include "koppel/analysis/instant_centres.hpp"

#include "koppel/core/plane.hpp"
#include "pose_walk.hpp"

#include <Eigen/Geometry>

#include <cmath>

namespace koppel {
namespace {

// A pole farther than this many L is at infinity: a relative turn rate of 1e-9 of the velocities
// is the roundoff of transfer functions good to ~1e-14, amplified by near-cancellation.
constexpr double kInfinityDistance = 1e9;
// Relative motion below this fraction of the mechanism's velocity scale stands still.
constexpr double kStandstill = 1e-9;

Eigen::Matrix2d Rotation(double theta) { return Eigen::Rotation2Dd(theta).toRotationMatrix(); }

}  // namespace

Eigen::Vector2d LinkMotion::PointDerivative(const Eigen::Vector2d& X, int k) const {
  const Eigen::Vector2d d = X - origin[0];
  const double w = theta[1], a = theta[2], j = theta[3];
  switch (k) {
    case 0: return X;
    case 1: return origin[1] + w * Perp(d);
    case 2: return origin[2] + a * Perp(d) - w * w * d;
    default: return origin[3] + (j - w * w * w) * Perp(d) - 3 * w * a * d;
  }
}

LinkMotion MotionOf(const ConstraintSystem& system, const Eigen::MatrixXd& series, int link, int order) {
  LinkMotion m;
  for (auto& o : m.origin) o.setZero();
  const int i = system.CoordinateOf(link);
  if (i < 0) return m;
  double factorial = 1;
  for (int k = 0; k <= std::min<int>(order, static_cast<int>(series.cols()) - 1); ++k) {
    if (k > 0) factorial *= k;
    m.origin[k] = factorial * Eigen::Vector2d(series(i, k), series(i + 1, k));
    m.theta[k] = factorial * series(i + 2, k);
  }
  return m;
}

double VelocityScale(const ConstraintSystem& system, const Eigen::MatrixXd& series) {
  double scale = 0;
  for (int link = 0; link < static_cast<int>(system.mechanism().links.size()); ++link) {
    const LinkMotion m = MotionOf(system, series, link, 1);
    scale = std::max(scale, m.origin[1].norm() + system.length_scale() * std::abs(m.theta[1]));
  }
  return scale;
}

InstantCentre PoleOf(const LinkMotion& a, const LinkMotion& b, int link_a, int link_b, double length_scale, double velocity_scale) {
  InstantCentre pole;
  pole.link_a = link_a;
  pole.link_b = link_b;
  // Delta w J P = c with c = -(o_b' - o_a') + J (w_b o_b - w_a o_a): equal velocities on both links
  double turn = b.theta[1] - a.theta[1];
  Eigen::Vector2d c = -(b.origin[1] - a.origin[1]) + Perp(b.theta[1] * b.origin[0] - a.theta[1] * a.origin[0]);
  const double reach = std::max(1.0, (a.origin[0].norm() + b.origin[0].norm()) / length_scale);
  if (std::abs(turn) * length_scale <= kStandstill * velocity_scale && c.norm() <= kStandstill * velocity_scale * reach) {
    // the relative motion stands still at this instant: its pole is that of the accelerations
    pole.from_acceleration = true;
    turn = b.theta[2] - a.theta[2];
    c = -(b.origin[2] - a.origin[2]) +
        Perp(b.theta[2] * b.origin[0] + b.theta[1] * b.origin[1] - a.theta[2] * a.origin[0] - a.theta[1] * a.origin[1]);
    const double scale = std::max({c.norm(), std::abs(turn) * length_scale, 1e-300});
    if (std::abs(turn) * length_scale <= kStandstill * scale && c.norm() <= kStandstill * scale) {
      pole.defined = false;
      return pole;
    }
  }
  if (std::abs(turn) * kInfinityDistance * length_scale <= c.norm()) {
    // a relative translation: the pole lies at infinity, perpendicular to the relative velocity
    // (the relative velocity of every point is -c, up to the vanishing turn)
    pole.at_infinity = true;
    pole.direction = Perp(c).normalized();
    return pole;
  }
  pole.position = -Perp(c) / turn;  // P = J^-1 c / turn, J^-1 = -J
  return pole;
}

std::vector<InstantCentre> InstantCentres(const ConstraintSystem& system, const Eigen::MatrixXd& series) {
  const int n = static_cast<int>(system.mechanism().links.size());
  const double velocity_scale = VelocityScale(system, series);
  std::vector<LinkMotion> motion;
  for (int link = 0; link < n; ++link) motion.push_back(MotionOf(system, series, link, 2));
  std::vector<InstantCentre> centres;
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) centres.push_back(PoleOf(motion[a], motion[b], a, b, system.length_scale(), velocity_scale));
  }
  return centres;
}

Centrodes TraceCentrodes(const Mechanism& mechanism, int link, int reference, const std::vector<double>& inputs) {
  Centrodes result;
  PoseWalk walk(mechanism);
  if (!walk.started()) {
    result.status = AnalysisStatus::kFailed;
    result.message = walk.error();
    return result;
  }
  const ConstraintSystem& system = walk.solver().system();
  for (double input : inputs) {
    const std::string why = walk.To(input);
    if (!why.empty()) {
      result.status = result.points.empty() ? AnalysisStatus::kFailed : AnalysisStatus::kPartial;
      result.message = why;
      return result;
    }
    const Eigen::MatrixXd& series = walk.walk().Series(2);
    const LinkMotion a = MotionOf(system, series, reference, 2), b = MotionOf(system, series, link, 2);
    const InstantCentre pole = PoleOf(a, b, reference, link, system.length_scale(), VelocityScale(system, series));
    CentrodePoint point;
    point.input = input;
    point.finite = pole.defined && !pole.at_infinity;
    point.link_origin = Rotation(a.theta[0]).transpose() * (b.origin[0] - a.origin[0]);
    point.link_angle = b.theta[0] - a.theta[0];
    if (point.finite) {
      point.fixed = Rotation(a.theta[0]).transpose() * (pole.position - a.origin[0]);
      point.moving = Rotation(b.theta[0]).transpose() * (pole.position - b.origin[0]);
    }
    result.points.push_back(point);
  }
  result.status = AnalysisStatus::kComplete;
  return result;
}

}  // namespace koppel

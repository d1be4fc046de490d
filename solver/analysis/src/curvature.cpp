#include "koppel/analysis/curvature.hpp"

#include "koppel/core/plane.hpp"
#include "pose_walk.hpp"

#include <cmath>

namespace koppel {
namespace {

// Below this fraction of its scale a length or rate counts as zero: roundoff of Taylor
// coefficients good to ~1e-14, with room for cancellation.
constexpr double kZero = 1e-9;

void Append(std::string& message, const std::string& what) { message += (message.empty() ? "" : "; ") + what; }

// The pole, its tangent, the inflection circle and the Ball point of link motion m.
void PoleGeometry(const LinkMotion& m, double length_scale, double velocity_scale, CurvatureResult* r) {
  const double w = m.theta[1];
  if (std::abs(w) * length_scale <= kZero * velocity_scale || (m.origin[1].norm() > std::abs(w) * 1e9 * length_scale)) {
    Append(r->message, "the link translates at this instant: its pole is at infinity, with no inflection circle");
    return;
  }
  r->has_pole = true;
  r->pole = m.origin[0] + Perp(m.origin[1]) / w;
  // dP/dx = o' + J o''/w - J o' w'/w^2
  r->pole_velocity = m.origin[1] + Perp(m.origin[2]) / w - Perp(m.origin[1]) * m.theta[2] / (w * w);
  r->has_pole_tangent = r->pole_velocity.norm() > kZero * velocity_scale / std::abs(w);
  const Eigen::Vector2d a_pole = m.PointDerivative(r->pole, 2);
  r->inflection_pole = r->pole + a_pole / (w * w);
  r->inflection_centre = 0.5 * (r->pole + r->inflection_pole);
  r->inflection_diameter = (r->inflection_pole - r->pole).norm();
  if (r->inflection_diameter <= kZero * length_scale) {
    r->inflection_diameter = 0;
    r->inflection_pole = r->inflection_centre = r->pole;
    Append(r->message, "the link turns about a fixed pivot: the inflection circle shrinks to the pole, there is no Ball point");
    return;
  }
  // Ball point: on the circle and on 3 w w' |X - P|^2 = (X - P).j_P; both circles pass through P,
  // so their second intersection lies on the line through P perpendicular to m = 3 w' a_P - w j_P
  const Eigen::Vector2d j_pole = m.PointDerivative(r->pole, 3);
  const Eigen::Vector2d normal = 3 * m.theta[2] * a_pole - w * j_pole;
  const double normal_scale = 3 * std::abs(m.theta[2]) * a_pole.norm() + std::abs(w) * j_pole.norm();
  if (normal.norm() <= kZero * normal_scale) {
    Append(r->message, "every point of the inflection circle has stationary curvature here: no single Ball point");
    return;
  }
  const Eigen::Vector2d e = Perp(normal).normalized();
  const double along = e.dot(r->inflection_pole - r->pole);
  if (std::abs(along) <= kZero * r->inflection_diameter) {
    Append(r->message, "the Ball point coincides with the pole");
    return;
  }
  r->has_ball_point = true;
  r->ball_point = r->pole + along * e;
}

}  // namespace

CurvatureResult CurvatureAt(const ConstraintSystem& system, const Eigen::MatrixXd& series, double input, const PointRef& point) {
  CurvatureResult r;
  r.input = input;
  const double L = system.length_scale();
  const LinkMotion m = MotionOf(system, series, point.link, 3);
  if (system.CoordinateOf(point.link) < 0) {
    r.status = AnalysisStatus::kFailed;
    r.message = "the point is on the frame: it does not move";
    double xy[2];
    system.GlobalPoint(point, series.col(0).data(), xy);
    r.point = {xy[0], xy[1]};
    return r;
  }
  const double velocity_scale = VelocityScale(system, series);
  PoleGeometry(m, L, velocity_scale, &r);
  double xy[2];
  system.GlobalPoint(point, series.col(0).data(), xy);
  r.point = {xy[0], xy[1]};
  r.velocity = m.PointDerivative(r.point, 1);
  r.acceleration = m.PointDerivative(r.point, 2);
  const double speed = r.velocity.norm();
  if (speed <= kZero * velocity_scale) {
    Append(r.message, "the point stands still at this instant (it is at the pole): its path has a cusp, no radius of curvature");
  } else {
    r.has_curvature = true;
    const double turn = Cross(r.velocity, r.acceleration);
    r.curvature = turn / (speed * speed * speed);
    // an inflection when the curvature is below the roundoff of the acceleration's normal part
    const double roundoff = kInflectionCurvature * (1.0 / L + r.acceleration.norm() / (speed * speed));
    if (std::abs(r.curvature) <= roundoff) {
      r.curvature = 0;
      Append(r.message, "the point's path has an inflection here (it lies on the inflection circle): rho is infinite");
    } else {
      r.rho_finite = true;
      r.rho = 1.0 / r.curvature;
      r.centre = r.point + Perp(r.velocity) * (speed * speed / turn);
    }
  }
  // complete when everything the point and the link have is defined; an inflection is an answer
  const bool complete = r.has_pole && r.has_curvature;
  r.status = complete ? AnalysisStatus::kComplete : AnalysisStatus::kPartial;
  return r;
}

CurvatureResult CurvatureAtInput(const Mechanism& mechanism, const PointRef& point, double input) {
  PoseWalk walk(mechanism);
  const std::string why = walk.To(input);
  if (!why.empty()) {
    CurvatureResult r;
    r.status = AnalysisStatus::kFailed;
    r.input = input;
    r.message = why;
    return r;
  }
  return CurvatureAt(walk.solver().system(), walk.walk().Series(3), input, point);
}

InstantCentresResult InstantCentresAtInput(const Mechanism& mechanism, double input) {
  InstantCentresResult r;
  r.input = input;
  PoseWalk walk(mechanism);
  const std::string why = walk.To(input);
  if (!why.empty()) {
    r.status = AnalysisStatus::kFailed;
    r.message = why;
    return r;
  }
  r.centres = InstantCentres(walk.solver().system(), walk.walk().Series(2));
  r.status = AnalysisStatus::kComplete;
  for (const InstantCentre& c : r.centres) {
    if (!c.defined) {
      r.status = AnalysisStatus::kPartial;
      r.message = "some links move together at this instant: their pole is not defined";
    }
  }
  return r;
}

}  // namespace koppel

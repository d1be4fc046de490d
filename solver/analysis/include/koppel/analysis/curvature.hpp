// Second- and third-order geometry of a link's motion against the frame at one pose: the instant
// centre (pole) P, the velocity of the pole along the fixed centrode (the pole tangent t), the
// inflection circle (Wendekreis) through P and the inflection pole W (Wendepol), the Ball point
// (Ballscher Punkt) where the circle meets the cubic of stationary curvature, and for one point of
// the link its path's radius of curvature and centre of curvature.
//
// With x the drive input, o, theta the link's pose and w = theta' (global frame):
//   P = o + J o' / w;  the body point at P has acceleration a_P = o'' + w' J (P - o) - w^2 (P - o);
//   W = P + a_P / w^2; the inflection circle has diameter PW (every point X on it has
//   (X - P).(X - P) = (X - P).(W - P): its velocity and acceleration are parallel).
//   Ball point U: on the circle, also (X - P).(X - P) 3 w w' = (X - P).j_P with j_P the body
//   point's third derivative at P (the derivative of the curvature vanishes there too), so
//   U - P is perpendicular to m = 3 w' a_P - w j_P, at distance (W - P).e along that direction e.
//   A point K with velocity u = K', acceleration v = K'': curvature k = (u x v) / |u|^3 (positive
//   when the path turns counter-clockwise), rho = 1/k, centre of curvature K + J u |u|^2 / (u x v).
// All of these are independent of how the input is parametrised. The Euler–Savary equation
// (1/PK - 1/PK0 = 1/PW_K along the pole ray, W_K where the ray meets the inflection circle)
// links them; the tests check it against rho from the point's transfer functions.
#pragma once

#include "koppel/analysis/instant_centres.hpp"
#include "koppel/analysis/status.hpp"

#include <Eigen/Core>

#include <string>

namespace koppel {

struct CurvatureResult {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // partial: some quantities are undefined here (see the flags)
  std::string message;                              // what is undefined, and why
  double input = 0;                                 // [rad | length]
  // the pole (instant centre of the link against the frame); false when the link translates
  // at this instant (the pole is at infinity) and none of the pole's quantities are set
  bool has_pole = false;
  Eigen::Vector2d pole = Eigen::Vector2d::Zero();
  Eigen::Vector2d pole_velocity = Eigen::Vector2d::Zero();  // dP/dx: along the pole tangent t
  bool has_pole_tangent = false;  // |dP/dx| not zero
  Eigen::Vector2d inflection_pole = Eigen::Vector2d::Zero();  // W
  Eigen::Vector2d inflection_centre = Eigen::Vector2d::Zero();
  double inflection_diameter = 0;  // |PW|; 0: the link turns about a fixed pivot
  bool has_ball_point = false;
  Eigen::Vector2d ball_point = Eigen::Vector2d::Zero();
  // the point
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero(), acceleration = Eigen::Vector2d::Zero();  // dK/dx, d2K/dx2
  bool has_curvature = false;  // false: the point stands still (a cusp of its path, K at the pole)
  double curvature = 0;        // signed, 1/length; 0 at an inflection
  bool rho_finite = false;     // false: an inflection (|curvature| L below kInflectionCurvature)
  double rho = 0;              // signed radius 1/curvature
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // centre of curvature (finite rho)
};

// |curvature| * L below this is an inflection: the roundoff of k from Taylor coefficients good to
// ~1e-14 is ~1e-13 / L, so a point on the inflection circle reads as an inflection, not as a
// radius of 1e13 L.
inline constexpr double kInflectionCurvature = 1e-9;

// At a solved pose with its Taylor coefficients (at least 4 columns: order 3).
CurvatureResult CurvatureAt(const ConstraintSystem& system, const Eigen::MatrixXd& series, double input, const PointRef& point);

// Walks from the mechanism's assembly to `input` [rad | length] on its branch and evaluates there;
// failed (message why) when the input cannot be reached or the pose is singular.
CurvatureResult CurvatureAtInput(const Mechanism& mechanism, const PointRef& point, double input);

// The same walk for the instant centres of every link pair.
struct InstantCentresResult {
  AnalysisStatus status = AnalysisStatus::kNotRun;
  std::string message;
  double input = 0;
  std::vector<InstantCentre> centres;
};
InstantCentresResult InstantCentresAtInput(const Mechanism& mechanism, double input);

}  // namespace koppel

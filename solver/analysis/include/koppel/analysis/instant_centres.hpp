// Instant centres (Momentanpole) of a mechanism's links at one pose, and the centrodes
// (Polbahnen) a link's pole traces over a range of the input.
//
// Everything is differentiated with respect to the drive input x (radians for an R drive, length
// for a P drive), from the exact Taylor coefficients of q(x) (PositionSolver::Series): a link's
// pose (o, theta) and its derivatives o^(k), theta^(k). The instant centre P_ab of link b
// relative to link a is the point whose velocity is the same on both links:
//   (theta_b' - theta_a') J P = -(o_b' - o_a') + J (theta_b' o_b - theta_a' o_a),  J = rotation by +90 deg,
// so the three instant centres of any three links lie on one line (Aronhold–Kennedy). Where the
// two links turn at the same rate the pole lies at infinity, perpendicular to their relative
// velocity; where both the relative turn and the relative velocity vanish (the rocker at its dead
// centre) the pole is taken one order higher, from the accelerations. Global frame, length units.
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/constraints.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

// A link's pose and its derivatives by the input, orders 0..3 (global frame): origin[k] =
// d^k o / dx^k, theta[k] = d^k theta / dx^k. The frame link's are all zero.
struct LinkMotion {
  Eigen::Vector2d origin[4];
  double theta[4] = {0, 0, 0, 0};
  // d^k/dx^k of the body point now at global X (k = 0..3).
  Eigen::Vector2d PointDerivative(const Eigen::Vector2d& X, int k) const;
};
// From Taylor coefficients (columns d^k q / dx^k / k!, at least `order` + 1 of them; order <= 3).
LinkMotion MotionOf(const ConstraintSystem& system, const Eigen::MatrixXd& series, int link, int order = 3);

struct InstantCentre {
  int link_a = -1, link_b = -1;
  bool at_infinity = false;  // the links translate relative to each other at this instant
  bool from_acceleration = false;  // the relative motion stands still: the pole of its acceleration
  Eigen::Vector2d position = Eigen::Vector2d::Zero();   // finite poles
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // poles at infinity: the unit direction they lie in
  bool defined = true;  // false: neither velocities nor accelerations define it (links moving together)
};

// The pole of link b relative to link a. length_scale: the mechanism's L (a pole beyond 1e9 L is
// at infinity); velocity_scale: the largest |o'| + L |theta'| of any link (what "stands still"
// is measured against: below 1e-9 of it).
InstantCentre PoleOf(const LinkMotion& a, const LinkMotion& b, int link_a, int link_b, double length_scale, double velocity_scale);
// That velocity scale over every link of `system`.
double VelocityScale(const ConstraintSystem& system, const Eigen::MatrixXd& series);

// Every pair a < b of links, in link order (the frame too).
std::vector<InstantCentre> InstantCentres(const ConstraintSystem& system, const Eigen::MatrixXd& series);

// The poles of link `link` relative to link `reference` at the inputs of a walk from the
// mechanism's assembly: the fixed centrode (in the reference link's body frame; for the frame
// link, the global frame) and the moving centrode (in `link`'s body frame).
struct CentrodePoint {
  double input = 0;  // [rad | length]
  bool finite = false;
  Eigen::Vector2d fixed = Eigen::Vector2d::Zero(), moving = Eigen::Vector2d::Zero();
  // the link's pose in the reference link's frame (origin, angle): carries `moving` onto `fixed`
  Eigen::Vector2d link_origin = Eigen::Vector2d::Zero();
  double link_angle = 0;
};
struct Centrodes {
  AnalysisStatus status = AnalysisStatus::kNotRun;  // partial: the walk ended before the last input
  std::string message;
  std::vector<CentrodePoint> points;
};
// inputs in walking order [rad | length].
Centrodes TraceCentrodes(const Mechanism& mechanism, int link, int reference, const std::vector<double>& inputs);

}  // namespace koppel

// Burmester theory (motion generation, Führungsgetriebe-Synthese): the dyads A0 A whose circle
// point A, fixed in a moving plane, lies on one circle about the centre point A0 in every given
// pose of the plane. Two such dyads make a four-bar whose coupler carries the plane through the
// poses (Burmester 1888; Sandor & Erdman, Advanced Mechanism Design, ch. 8).
//
// A pose is the global position of the plane's reference point and the plane's angle (radians,
// counter-clockwise). A circle point is given by its global position in the first pose; in pose
// j it is at P_j + R(theta_j - theta_1)(A - P_1). For fixed A0 the conditions
// |A_j - A0|^2 = |A_1 - A0|^2 (j = 2..n) are linear in A, and for fixed A linear in A0:
//   3 poses: every circle point has one centre point (the circumcentre of A_1 A_2 A_3);
//   4 poses: the centre points lie on a circular cubic, the centre-point curve (Mittelpunkt-
//     kurve), their circle points on the circle-point curve (Kreispunktkurve); both pass
//     through the poles P_ij, and every line through a pole meets the centre-point curve in
//     two more points: the curves are sampled that way;
//   5 poses: the centre points common to the curves of poses 1234 and 1235, the Ball–Burmester
//     points: two circular cubics meet in 9 points, 2 at the circular points at infinity and 3 at
//     the poles P12, P13, P23, which leaves at most four. They are found from the resultant of
//     the two cubics (a univariate polynomial, its roots as companion-matrix eigenvalues), each
//     root polished by Newton's method on all four conditions and kept only when its residual
//     is below 1e-9 of the poses' size.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

struct Pose {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // the plane's reference point, global
  double angle = 0;                                 // the plane's angle [rad]
};

// A dyad: the centre point (frame pivot) and the circle point in the first pose (global).
struct Dyad {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d circle = Eigen::Vector2d::Zero();
};

// Where the plane point at `global` in pose `from` is in pose `to`.
Eigen::Vector2d MovePoint(const Pose& from, const Pose& to, const Eigen::Vector2d& global);

// The size of a pose set: the largest distance of a pose point from their centroid (1 when they
// coincide). Tolerances of this file are relative to it.
double PoseScale(const std::vector<Pose>& poses);

// The largest | |A_j - A0| - |A_1 - A0| | over the poses: 0 for a dyad that meets them all.
double DyadResidual(const std::vector<Pose>& poses, const Dyad& dyad);

enum class BurmesterStatus { kOk, kInvalidRequest, kNoSolution };
const char* ToString(BurmesterStatus status);

struct CentrePointResult {
  BurmesterStatus status = BurmesterStatus::kNoSolution;
  std::string message;
  Dyad dyad;
  double residual = 0;  // DyadResidual over every pose
  bool ok() const { return status == BurmesterStatus::kOk; }
};

// The centre point of `circle_point` (global, first pose) from the first three poses; with more
// poses it must meet them too (residual <= 1e-9 PoseScale), else kNoSolution with the residual.
// kNoSolution when the three positions of the circle point are collinear (the centre lies at
// infinity: a slider would guide it).
CentrePointResult CentrePoint(const std::vector<Pose>& poses, const Eigen::Vector2d& circle_point);

// Two poses leave the centre point free on the perpendicular bisector of A_1 A_2: this one is
// where the crank turns by `crank_turn` (radians, counter-clockwise positive, 0 < |turn| < 2 pi)
// from the first pose to the second. kNoSolution when A does not move.
CentrePointResult CentrePointTwoPoses(const std::vector<Pose>& poses, const Eigen::Vector2d& circle_point, double crank_turn);

struct BurmesterCurveSample {
  Dyad dyad;
  double direction = 0;  // the line through the base pole it was found on [rad]
};

struct BurmesterCurves {
  BurmesterStatus status = BurmesterStatus::kNoSolution;
  std::string message;
  Eigen::Vector2d base_pole = Eigen::Vector2d::Zero();
  std::vector<BurmesterCurveSample> samples;  // in order of direction
  bool ok() const { return status == BurmesterStatus::kOk; }
};

// The centre-point and circle-point curves of four poses, sampled on `directions` lines through
// the pole P_ij of the pair of poses with the largest rotation: up to two points each; with
// `refine`, more lines where the curve runs nearly along them, so that neighbouring samples lie
// within 2 % of the poses' size. Points beyond `reach` PoseScale from the poses' centroid are
// left out.
BurmesterCurves CentrePointCurve(const std::vector<Pose>& poses, int directions, bool refine = true, double reach = 20);

struct BallBurmester {
  BurmesterStatus status = BurmesterStatus::kNoSolution;
  std::string message;
  std::vector<Dyad> dyads;  // the real Ball–Burmester points and their circle points (0, 2 or 4)
  bool ok() const { return status == BurmesterStatus::kOk; }
};

// The Ball–Burmester points of five poses.
BallBurmester BallBurmesterPoints(const std::vector<Pose>& poses);

}  // namespace koppel

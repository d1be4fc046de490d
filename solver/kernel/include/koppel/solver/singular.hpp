// Singular positions (singuläre Lagen) of the position equations F(q, input) = 0, as a sweep of
// the drive meets them.
//
// J = dF/dq is square for a one-DOF mechanism: its rows are the joints' constraint rows J_c and
// the drive row. J is singular in two kinds of position:
// - limit point (dead centre of the drive, Totlage des Antriebs): J_c still has full rank, so the
//   mechanism without its drive moves on one smooth curve, but that motion does not move the
//   drive joint. The input cannot pass the point on this branch: a sweep ends there.
// - branch point (Verzweigungslage, e.g. the change point of a Grashof-neutral four-bar, a loop
//   folding flat, a slider-crank with l2 = l1 + |e|): J_c itself loses rank. The mechanism can
//   carry a self-stress there and two branches of the curve cross; both continue in the input.
//
// Every quantity here uses the scaled Jacobian J S (theta columns divided by the length scale L),
// whose entries are dimensionless, so that thresholds mean the same for any size of mechanism.
#pragma once

#include "koppel/solver/branch_point_action.hpp"
#include "koppel/solver/constraints.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace koppel {

enum class SingularKind { kLimitPoint, kBranchPoint };
const char* ToString(SingularKind kind);  // "limit", "branch-point"


// AnalyseSingularity classifies a pose as at a branch point when sigma_{n-1} / sigma_1 of the
// constraint rows (drive row left out) is below this: the mechanism without its drive is then
// within about 1e-12 L of a flat, self-stressed pose. A walk decides by the bifurcation system
// instead (LocateBranchPoint below: its defect is what the dimensions miss by, wherever the walk
// stalled). Otherwise a singular J is a limit point.
inline constexpr double kBranchPointRcond = 1e-6;
// Rows of a sweep whose pose has a reciprocal condition of J S below this are flagged singular:
// a k-th order transfer function computed there through J^-1 may carry errors of order
// eps / rcond^k.
inline constexpr double kSingularRowRcond = 1e-6;
// A pose whose pivot gauge (PositionSolver::PivotRatio) is above this is taken as regular without
// an SVD: on mechanism Jacobians the pivot ratio of partial pivoting tracks the reciprocal
// condition within a modest factor, and rows are flagged only three decades further down.
inline constexpr double kRegularPivotRatio = 1e-3;

// One singular position met by a sweep.
struct SingularPoint {
  SingularKind kind = SingularKind::kLimitPoint;
  double input = 0.0;       // where [rad for an R drive, length for a P drive]
  double rcond = 0.0;       // reciprocal condition of J S at the pose located there
  std::vector<int> joints;  // the joints whose equations carry the singularity (see below)
  BranchPointAction action = BranchPointAction::kContinue;  // branch points: what the sweep did
};

// The scaled Jacobian J S, all rows (with_drive_row) or the constraint rows only.
Eigen::MatrixXd ScaledJacobian(const ConstraintSystem& system, const Eigen::VectorXd& q, bool with_drive_row);

// sigma_min / sigma_max of J S at q (0 for a rank-deficient J): the exact distance-to-singularity
// gauge behind the flags and the classification.
double ReciprocalCondition(const ConstraintSystem& system, const Eigen::VectorXd& q);

struct SingularStructure {
  double rcond = 0.0;             // of J S
  double constraint_rcond = 0.0;  // sigma_{n-1} / sigma_1 of J_c S
  SingularKind kind = SingularKind::kLimitPoint;
  // Joints with a share of the near-null left singular vector (a self-stress of the constraints
  // for a branch point; the drive's reaction and the load path for a limit point): the joints or
  // the loop involved. Shares below 1e-4 of the largest count as zero.
  std::vector<int> joints;
};

// Classifies the singularity nearest to pose q (an SVD; meant for poses where the pivot gauge
// already says J is nearly singular).
SingularStructure AnalyseSingularity(const ConstraintSystem& system, const Eigen::VectorXd& q);

// At a branch point (q, input) with one branch's tangent dq/dinput, the other branch's tangent:
// both lie on the line t + a w, w the motion of J's null space (the drive held), and satisfy the
// bifurcation equation psi^T F''[t + a w, t + a w] = 0 (psi the left null vector, F'' the second
// derivative of the residuals in q, exact through Taylor<2>). One root is a = 0; the other gives
// the answer. Empty when the point is no simple crossing (complex roots) or the other branch does
// not cross in the input (it would run at constant input).
std::optional<Eigen::VectorXd> OtherBranchTangent(const ConstraintSystem& system, const Eigen::VectorXd& q, double input,
                                                  const Eigen::VectorXd& tangent);

// A limit point located on the augmented (Moore–Spence) system
//   F(q, input) = 0,   J(q) S u = 0,   c . u = 1
// in the 2n + 1 unknowns q, input and u (the null vector of J S; c its first estimate), by Newton
// on all three with the exact Jacobian (the second derivatives F''[S u, .] from Taylor<2>
// residuals by polarisation). The system is regular at a simple fold, so Newton converges
// quadratically and the input is found to roundoff (about 1e-15 rad relative; the tests hold it
// to 1e-13 against the triangle inequality), where the walk's step halving alone stops about
// 1e-10 short.
struct LimitPoint {
  double input = 0.0;      // the limit point [rad for an R drive, length for a P drive]
  Eigen::VectorXd q;       // the pose there
  Eigen::VectorXd null;    // the motion there with the drive held: J null = 0, unit in the scaled norm
  // input(s) = input + curvature s^2 + O(s^3) along the branch q(s) = q + s null + O(s^2): the
  // branch lies on the side sign(curvature) of the limit (0 when the fold is not quadratic)
  double curvature = 0.0;
  int iterations = 0;
};

// A branch point located on the bifurcation system with its unfolding parameter sigma
//   G(q) = sigma psi,   (J_c S)^T psi = 0,   psi . psi = 1
// (G the constraint rows without the drive row, J_c = dG/dq, psi their self-stress, a left null
// vector of J_c S) in the 2n unknowns q, psi and sigma, by Newton with the exact Jacobian (psi^T G''
// from Taylor<2> residuals by polarisation). The system without sigma is overdetermined by one: a
// flat, self-stressed pose exists only for special dimensions (a Grashof-neutral four-bar). With
// sigma it is square and regular at a simple branch point; at its solution G's residual is
// sigma psi, the least-squares residual of the branch-point system, so |sigma| is how far (in L)
// the mechanism is from reaching a branch point near q: about |b + c - a - d| for a four-bar near
// its change point. A mechanism reaches one only where |sigma| <= kBranchPointDefect L.
struct BranchPoint {
  double input = 0.0;   // the drive's value at q [rad for an R drive, length for a P drive]
  Eigen::VectorXd q;    // the flat pose (closing the joints to |sigma|)
  double defect = 0.0;  // |sigma| / L
  int iterations = 0;
};
// The mechanism's dimensions reach a branch point when the defect is below this: roundoff of
// lengths given to 15 digits, far below any built tolerance (1e-12 L is 1 pm on a 1 m linkage).
inline constexpr double kBranchPointDefect = 1e-12;

// Newton on the bifurcation system from a converged pose (input, q) near a flat pose: `input` is
// the reference for the drive's value (the walk's, whole turns included). Empty when Newton does
// not converge (no self-stressed pose near q).
std::optional<BranchPoint> LocateBranchPoint(const ConstraintSystem& system, double input, const Eigen::VectorXd& q);

// Newton on the augmented system from a pose (input, q) near a limit point (q a converged pose
// of F, e.g. where a walk stalled). Empty when Newton does not converge (not near a simple fold:
// a branch point, or too far).
std::optional<LimitPoint> LocateLimitPoint(const ConstraintSystem& system, double input, const Eigen::VectorXd& q);

}  // namespace koppel

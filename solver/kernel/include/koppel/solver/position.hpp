// Position analysis: Newton on the joint residuals of constraints.hpp with the analytic
// Jacobian, assembly from a rough hint, and the exact Taylor coefficients of q(input).
//
// Outcomes are values: a SolveReport with a status, never an exception. On failure the
// caller's q is left as it was.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/solver/block_lu.hpp"
#include "koppel/solver/constraints.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/QR>

#include <functional>
#include <string>
#include <vector>

namespace koppel {

enum class SolveStatus {
  kConverged,
  kNotAssemblable,   // no pose satisfies the joints at this input (links too short, ...)
  kSingular,         // the Jacobian lost rank: a dead centre of the drive or a bifurcation
  kDidNotConverge,   // Newton ran out of iterations or the step was rejected
};

const char* ToString(SolveStatus status);

struct SolveReport {
  SolveStatus status = SolveStatus::kDidNotConverge;
  double residual_norm = 0.0;  // max-norm of F at the returned (or last tried) q
  int iterations = 0;
  int worst_joint = -1;        // joint with the largest residual, -1 for the drive row
  std::string message;
  bool ok() const { return status == SolveStatus::kConverged; }
};

struct NewtonOptions {
  int max_iterations = 20;
  // Converged when |F|_inf <= tolerance * max(L, the largest |x| or |y| of a link's origin) (L =
  // length scale): a few hundred ulps of the coordinates, far below the 1e-9 the closed-form
  // checks ask for (a pose 2000 L out cannot close its rows to 1e-13 L in doubles).
  double tolerance = 1e-13;
  // The linear algebra of each step: by default the Jacobian's block triangular form with a
  // dense LU per block (block_lu.hpp) and the Taylor coefficients order by order without series
  // arithmetic (constraints.hpp); `dense` takes one dense LU of the whole Jacobian and evaluates
  // the residuals on Taylor<N> instead: the straightforward reference the default path is tested
  // against. Redundant (non-square) and structurally singular systems always take the dense path.
  bool dense = false;
};

// Largest order of transfer function the solver computes (Taylor coefficients of q).
inline constexpr int kMaxOrder = 8;

// The column of d^0 of `output` (`component` 0 or 1 for a point) in a table laid out by
// PositionSolver::OutputDerivatives up to `order`; its k-th derivative is k columns further.
// The one place that knows the layout.
int OutputColumn(const Mechanism& mechanism, int output, int component, int order);

// The links whose pose the assembly hint leaves open: its points, the drive and the joints carry
// no angle or place to them, so the assembly's first guess gives each a free one (and later
// attempts others): the branch it lands on is the solver's choice, not the file's. Empty when the
// hint pins every link (a four-bar: one point of the coupler-rocker joint).
std::vector<int> LinksTheHintLeavesOpen(const Mechanism& mechanism);

class PositionSolver {
 public:
  explicit PositionSolver(const Mechanism& mechanism, NewtonOptions options = {});

  const ConstraintSystem& system() const { return system_; }
  const NewtonOptions& options() const { return options_; }
  int NumCoordinates() const { return system_.NumCoordinates(); }

  // Newton from q at `input`. On success q holds the solution and the Jacobian there is
  // factorised (see Series, JacobianSign). On failure q is unchanged.
  SolveReport Correct(double input, Eigen::VectorXd& q);

  // Builds a first guess from the mechanism's frame points, the drive and the assembly hint,
  // then Levenberg–Marquardt, then Newton. The hint describes the pose at mechanism.hint.input;
  // this assembles at exactly that input. On success q is the assembled pose.
  SolveReport Assemble(Eigen::VectorXd& q);
  // The same from the hint's guess, at another input (near the hint's, where the hint still
  // describes the pose): used when the hint's input is itself a singular position.
  SolveReport AssembleAt(double input, Eigen::VectorXd& q);
  // The first guess AssembleAt starts from: the pose the hint describes (at the hint's input).
  Eigen::VectorXd HintGuess() const { return InitialGuess(0); }
  // Levenberg–Marquardt and Newton from the guess `q` at `input` (no hint): the tool for
  // finding every assembly of a mechanism from many starting guesses.
  SolveReport AssembleFrom(double input, Eigen::VectorXd& q);

  // Coefficients of the Taylor series of q about the last converged pose: column k holds
  // d^k q / d input^k / k!, k = 0..order (order <= kMaxOrder). Uses the factorisation of the
  // last successful Correct/Assemble. False for a singular Jacobian.
  bool Series(int order, Eigen::MatrixXd& coefficients);

  // Every output's derivatives from q's Taylor coefficients, in the order output, component
  // (x, y for points), k = 0..order: out[...] = d^k y / d input^k. `out` holds
  // OutputWidth(order) numbers.
  void OutputDerivatives(const Eigen::MatrixXd& q_coefficients, int order, double* out) const;
  // The same with cos and sin of every link angle at q_coefficients.col(0) given (TrigSize()
  // numbers, as ConstraintSystem::Evaluate lays them out), e.g. PointSchedule::Trig.
  void OutputDerivatives(const Eigen::MatrixXd& q_coefficients, int order, double* out, const double* trig) const;
  int OutputWidth(int order) const;

  // Sign of det J at the last converged pose (square systems), 0 when J is singular or not
  // square. A change of sign along a path means the path crossed a singular position.
  int JacobianSign() const { Resolve(); return jacobian_sign_; }
  // Smallest over largest pivot of the last LU of the scaled Jacobian J_hat = J S, where S divides
  // the theta columns by L so that every entry is dimensionless: a cheap distance-to-singularity
  // gauge (an SVD gives the exact reciprocal condition, see singular.hpp).
  double PivotRatio() const { Resolve(); return pivot_ratio_; }
  // det(J_hat) at the last factorised pose (square systems; 0 otherwise): a smooth, signed test
  // function whose simple roots along a branch are its singular positions.
  double ScaledDeterminant() const { Resolve(); return scaled_determinant_; }
  // True when the steps factorise the Jacobian block by block (see NewtonOptions::dense).
  bool UsesBlocks() const { return use_blocks_; }
  const BlockLU& blocks() const { Resolve(); return blocks_; }

  // x = J^-1 rhs with the factorisation of the last converged pose (implicit-function theorem:
  // dq/dp = -J^-1 dF/dp). Precondition: the last Correct/Assemble succeeded.
  Eigen::VectorXd SolveWithJacobian(const Eigen::VectorXd& rhs) const;
  // x = J^-T rhs with the same factorisation: the Lagrange multipliers (multipliers.hpp). False
  // when there is none or J is not square (redundant joints: the multipliers are not unique).
  bool SolveWithJacobianTranspose(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) const;  // multipliers.cpp

  // A solved pose reached without this solver (continuation.hpp's compiled steps): the last
  // converged pose from now on. Its factorisation is made when first needed (Series, the solves
  // with J, the sign and gauges above), by Newton at the pose, so that callers reading the
  // solver after a walk always get the walk's pose.
  // `trig` (optional): cos and sin of every link angle at q, which OutputDerivatives then reuses.
  void AdoptPose(double input, const Eigen::VectorXd& q, const double* trig = nullptr);
  // The same for a pose that its owner writes into q only when asked (`fill`, which must stay
  // callable until the next AdoptPose, AdoptPending or Correct): a walk of compiled steps pays for
  // the pose's angles only when something reads the solver.
  void AdoptPending(double input, const std::function<void(Eigen::VectorXd& q)>* fill);
  bool IsPending(const std::function<void(Eigen::VectorXd& q)>* fill) const { return pending_ && pending_fill_ == fill; }

  // Rank of the constraint rows (drive row excluded) at q, and the actual mobility
  // NumCoordinates() - rank.
  int ConstraintRank(const Eigen::VectorXd& q) const;

 private:
  void Evaluate(const Eigen::VectorXd& q, double input);  // fills residual_ and the Jacobian
  // Factorises at an adopted pose (AdoptPose) if one waits. Logically const: the solver's
  // observable state is the adopted pose either way.
  void Resolve() const;
  void FillDenseJacobian();                               // jacobian_ from the block path's values
  bool Factorize();                                       // factorises jacobian_
  void SolveFactorized(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) const;
  void SolveStep();                                       // q_try_ += the Newton step of residual_ (factorised)
  // The first guess from the frame, the drive and the hint. Links whose angle neither determines
  // get angle 0 on attempt 0 and a spread of angles on later attempts (see AssembleAt).
  Eigen::VectorXd InitialGuess(int attempt) const;
  SolveReport Report(SolveStatus status, int iterations, std::string message) const;
  template <int N> bool SeriesImpl(int order, Eigen::MatrixXd& coefficients);  // the dense path
  void BlockSeries(int order, Eigen::MatrixXd& coefficients);

  const Mechanism& mechanism_;
  ConstraintSystem system_;
  NewtonOptions options_;
  SolveReport AssembleFromGuess(double input, Eigen::VectorXd& x);  // x: the guess, then the result
  bool square_ = true;
  bool use_blocks_ = false;
  Eigen::VectorXd residual_, step_, rhs_;
  Eigen::MatrixXd jacobian_;  // the dense path's Jacobian (and assembly's)
  // the block path: the Jacobian's entries in pattern order, cos and sin of the link angles at
  // the last evaluation and at the last converged pose, their Taylor coefficients
  BlockLU blocks_;
  std::vector<double> jacobian_values_, trig_, trig_solved_, trig_series_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr_;
  Eigen::VectorXd q_solved_;
  double input_solved_ = 0.0;
  bool factorized_ = false;
  int jacobian_sign_ = 0;
  double pivot_ratio_ = 0.0;
  double scaled_determinant_ = 0.0;
  Eigen::VectorXd column_scale_;  // 1 for x, y columns; 1/L for theta columns
  // Taylor workspaces, allocated once.
  mutable std::vector<Taylor<2>> q2_, r2_, trig2_;
  mutable std::vector<Taylor<kMaxOrder>> q8_, r8_, trig8_;
  Eigen::VectorXd q_try_;
  bool pending_ = false;  // an adopted pose waits for its factorisation
  double pending_input_ = 0.0;
  Eigen::VectorXd pending_q_;
  const std::function<void(Eigen::VectorXd&)>* pending_fill_ = nullptr;  // writes pending_q_ when set
  template <int N> std::vector<Taylor<N>>& CoordinateSeries() const {
    if constexpr (N == 2) return q2_; else return q8_;
  }
  template <int N> std::vector<Taylor<N>>& ResidualSeries() const {
    if constexpr (N == 2) return r2_; else return r8_;
  }
  template <int N> std::vector<Taylor<N>>& TrigSeries() const {
    if constexpr (N == 2) return trig2_; else return trig8_;
  }
  template <int N>
  void OutputDerivativesImpl(const Eigen::MatrixXd& q_coefficients, int order, double* out, const double* trig_at_pose) const;
};

}  // namespace koppel

// A compiled walk step in joint-point coordinates: the mechanism, once, as a flat list of fixed-size
// block solves whose unknowns are the global positions of joint points, and whose residuals are
// the joints' and links' own equations (a link keeps the distance between its points, a block
// stays on its slide line). No trigonometry inside Newton: a dyad's loop is a 2 x 2 system in
// one joint point, solved with its exact Jacobian; link angles follow from the points afterwards.
//
// The stages, in solve order (each poses the links it names: angle, origin and their 1st and 2nd
// derivatives with respect to the drive input):
//   drive R:  a link hinged to a posed link by the drive joint: theta_b = theta_a + zero + input;
//   drive P:  a block on a posed guide by the drive joint: on the slide line at zero + input;
//   dyad RR:  two links, each hinged to a posed link, hinged to each other at J:
//             |J - A| = a, |J - B| = b   (A, B the posed hinges);
//   dyad RP:  a link hinged to a posed link at A and to a block at J, the block on the slide line
//             of a posed guide (its angle is the guide's plus the joint's):
//             |J - A| = a, n . (point of the block - point of the line) = 0;
//   dyad PRP: two blocks on posed guides hinged to each other: the meeting point of two lines;
//   dyad RPR: a block hinged to a posed link at A, sliding on the line of a link that turns about
//             a posed pivot B (a slotted link): n . (A - B) = offset (point_schedule_slides.cpp).
// A dyad's gauge is its own normalised determinant, whatever the mechanism's size.
// A mechanism made of other parts (triads, redundant joints) is not compiled (compiled() false, why_not() says what): the caller keeps the general
// kernel (position.hpp) for it. The schedule is the fast path of a regular step, never the only
// one: singular poses, assembly and higher orders stay with the general kernel.
//
// Conventions as constraints.hpp: theta in rad (counter-clockwise from the frame's x axis), the
// same q layout (x, y, theta per moving link), the input in rad (R drive) or lengths (P drive).
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/solver/prediction_weights.hpp"

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <vector>

namespace koppel {

class ConstraintSystem;
namespace point_outputs {
struct ScalarJet;  // a scalar and its 1st and 2nd derivatives (point_schedule_outputs.cpp)
}

class PointSchedule {
 public:
  // Compiles `system`'s mechanism (which must outlive the schedule).
  explicit PointSchedule(const ConstraintSystem& system);
  PointSchedule(const PointSchedule&) = delete;  // holds pointers into its own states
  PointSchedule& operator=(const PointSchedule&) = delete;

  bool compiled() const { return why_not_.empty(); }
  const std::string& why_not() const { return why_not_; }

  // Takes the pose q (ConstraintSystem's layout, a solved pose at `input`) as the state to step
  // from; its series (columns 0..2, as PositionSolver::Series) give the prediction.
  void Load(double input, const Eigen::VectorXd& q, const Eigen::MatrixXd& series);

  // Newton, stage by stage, from the 2nd-order prediction of the loaded (or last solved) state at
  // `input`. False, with the state unchanged, when a stage does not converge within
  // max_iterations, its normalised determinant falls below min_gauge or changes sign (a singular
  // position lies between: the general kernel locates and crosses it), the correction of a predicted joint point exceeds
  // max_correction * L, or its first derivative moved from the predicted one by more than
  // max_tangent_change * (1 + its size / L): the step's guards of continuation.hpp, which keep a
  // walk on its branch. Converged: the last update's residuals (a circle's row is exactly
  // -|update|^2 / 2 after it) at roundoff (kLanding) and within tolerance * L.
  struct StepOptions {
    double tolerance = 1e-13;
    int max_iterations = 8;
    double max_correction = 0.02;
    double max_tangent_change = 0.02;
    double min_gauge = 1e-12;
  };
  bool Step(double input, const StepOptions& options);
  bool Step(double input) { return Step(input, StepOptions()); }

  // The solved state in ConstraintSystem's layout: q, and its Taylor coefficients (columns 0, 1,
  // 2 = q, dq/dinput, d2q/dinput2 / 2).
  void Pose(Eigen::VectorXd& q) const { HistoryPose(0, q); }
  // The last accepted states, kept without copying (each step writes the oldest slot): back = 0
  // is the solved state, back < History(). Load starts the history anew with its state.
  static constexpr int kHistory = 8;
  int History() const { return history_; }
  void ForgetHistory() { history_ = 0; }
  double HistoryInput(int back) const { return state_input_[Slot(back)]; }
  void HistoryPose(int back, Eigen::VectorXd& q) const;
  // (`series` must have NumCoordinates() rows and at least 3 columns: the first 3 are written,
  // nothing is allocated)
  void Series(Eigen::MatrixXd& series) const;
  // Product of the stages' 2 x 2 Jacobian determinant signs: it changes where det J of the whole
  // system does (block triangular form), so a change between steps means a singular position lies
  // between them. Smallest |det| of a stage's normalised Jacobian (a gauge in [0, 1]).
  int DeterminantSign() const;
  double Gauge() const;

  // Every output's value and derivatives up to `order` (0..2) at the solved state, in the layout
  // of PositionSolver::OutputDerivatives (point_schedule_outputs.cpp): each output of
  // ConstraintSystem::Output written out for value, 1st and 2nd derivative from the links' jets
  // (no coefficient matrix, no sincos: the jets carry cos and sin). The tests hold the two to
  // 1e-12.
  void OutputDerivatives(int order, double* out) const;

 private:
  // A link's pose and its first and second derivatives with respect to the input. The angle
  // itself is taken only when asked for (Angle): a link posed by two points has cos and sin from
  // them, and its angle is atan2(s, c) plus the whole turns counted as the walk crossed the
  // negative x axis (a step turns a link by less than 90 degrees, see PoseByTwoPoints); a link
  // posed by angle (the drive's, a block's) has theta[0] set, its turns fixed at Load.
  // Its position is kept as the point it was posed by (`at`, the jet of its local point
  // `at_local`), not as its origin: a step poses every link but asks few for other points.
  struct LinkJet {
    mutable double theta[3] = {0, 0, 0};  // theta[0]: valid unless angle_pending
    double c = 1.0, s = 0.0;
    Eigen::Vector2d at[3] = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
    Eigen::Vector2d at_local = Eigen::Vector2d::Zero();
    int turns = 0;
    mutable bool angle_pending = false;
  };
  // the angle of link l at the solved state, or in history slot `slot` (one atan2 the first
  // time it is asked for)
  double Angle(int l) const { return AngleIn(now_, l); }
  static double AngleIn(const LinkJet* state, int l);
  int Slot(int back) const { return (at_ - back + kHistory) % kHistory; }
  // A global point and its first and second derivatives.
  // (not initialised: every stage writes all three)
  struct PointJet {
    Eigen::Vector2d p[3];
  };
  enum class Kind { kDriveR, kDriveP, kDyadRR, kDyadRP, kDyadPRP, kDyadRPR };
  // A dyad's normalised determinant |det| / norm (in [0, 1]), kept as det and norm^2: a step
  // compares det^2 with gauge^2 norm^2, without a square root or a division.
  struct StageGauge {
    double det = 1.0, norm2 = 1.0;
    double Value() const { return norm2 > 0.0 ? std::abs(det) / std::sqrt(norm2) : 0.0; }
    bool Above(double gauge) const { return norm2 > 0.0 && det * det > gauge * gauge * norm2; }
  };
  // A slide (P joint) of a dyad: its line on `guide` through guide_point along axis, the block's
  // slide point, the block's angle the guide's turned by the joint's (cos_turn, sin_turn).
  struct Slide {
    int guide = -1, block = -1;
    Eigen::Vector2d axis = Eigen::Vector2d::UnitX(), guide_point = Eigen::Vector2d::Zero(), block_point = Eigen::Vector2d::Zero();
    double cos_turn = 1.0, sin_turn = 0.0;
  };
  struct Stage {
    Kind kind = Kind::kDriveR;
    // drive R / P: the posed link `base` and the driven link `link`; sign +1 when the driven link
    // is the joint's link_b
    int base = -1, link = -1;
    double sign = 1.0;
    Eigen::Vector2d base_point, link_point;  // local points of the joint on base and link
    Eigen::Vector2d axis;                     // P: the slide direction, local to the guide
    double angle = 0.0;                       // P: theta_block - theta_guide
    double cos_turn = 1.0, sin_turn = 0.0;    // P: cos and sin of the block's angle from the guide's
    // dyads: links a (hinged to posed `anchor_a` at A) and b (hinged to posed `anchor_b` at B, or
    // a block on the posed guide `anchor_b`), J between a and b
    int a = -1, b = -1, anchor_a = -1, anchor_b = -1;
    Eigen::Vector2d a_at_anchor, anchor_a_point;  // local: A on a, A on anchor_a
    Eigen::Vector2d a_at_j, b_at_j;               // local: J on a, J on b
    Eigen::Vector2d b_at_anchor, anchor_b_point;  // RR: B on b, on anchor_b; RP: the slide's point on b and on the guide
    double length_a = 0.0, length_b = 0.0;        // |J - A| (on a), |J - B| (on b)
    double per_length_a = 0.0, per_length_b = 0.0;  // their inverses (RR, RP: the step multiplies)
    double landing2 = 0.0;  // Newton's last update squared, at most (kLanding times the shorter link's length squared)
    bool block_is_guide_side = false;             // RP: the block is the P joint's link_a
    // RP on a guide at rest (the frame): the block does not turn, so its line's normal and the
    // point X that J keeps the line's offset from are constants, without derivatives
    bool line_at_rest = false;
    Eigen::Vector2d rest_x, rest_n;
    // PRP: two blocks (a, b) on the slides line_a, line_b, hinged to each other at J.
    // RPR: a block a on the line of link b (line_b), each hinged to a posed link (anchor_a at A,
    // anchor_b at B): b's angle from its normal n . (A - B) = offset, on the branch `branch`.
    Slide line_a, line_b;
    Eigen::Vector2d normal = Eigen::Vector2d::UnitY();  // RPR: the line's unit normal, local to b
    double offset = 0.0, branch = 1.0;
    // The solved J, its derivatives, and the last 2 x 2 determinant (sign and gauge).
    // Two of each, double-buffered: a step reads [read_] (the state stepped from) and writes
    // [write_], so a refused step leaves the stage as it was without a copy.
    PointJet j[2];
    int det_sign[2] = {0, 0};
    StageGauge gauge[2];
  };

  // Compiling: a stage for the drive, or for a dyad, when one can be posed next; false if none.
  bool AddDriveStage(std::vector<bool>& posed, std::vector<bool>& used);
  bool AddDyadStage(std::vector<bool>& posed, std::vector<bool>& used);
  // PRP and RPR (point_schedule_slides.cpp)
  bool AddSlideDyadStage(std::vector<bool>& posed, std::vector<bool>& used);
  Slide SlideOf(int prismatic_joint) const;
  // RPR of the P joint k, the block's hinge ka, the line's link's pivot kb
  void CompileRPR(Stage& s, int k, int ka, int kb) const;
  bool SolvePRP(Stage& s, const StepOptions& options);
  bool SolveRPR(Stage& s, const StepOptions& options);
  void LoadSlideDyad(Stage& s);  // the stage's J, branch, sign and gauge at the loaded pose
  // the line row of a block on a posed guide: n . (J - X) = 0 with J the block's point `at_j`
  struct LineRow;
  void PrepareLine(const Slide& slide, const Eigen::Vector2d& at_j, LineRow& row) const;
  // The second half of dyad `s` through its inner joint k: b's R joint to a posed link (RR) or
  // its P joint on a posed guide (RP); that joint, or -1.
  int CloseDyad(Stage& s, int k, const std::vector<bool>& posed, const std::vector<bool>& used) const;
  PointJet GlobalPoint(int link, const Eigen::Vector2d& local) const;
  static PointJet PointOf(const LinkJet& jet, const Eigen::Vector2d& local);  // the same in a given state
  void PoseDrive(const Stage& s, double input);
  struct DyadRows;
  void PrepareDyad(const Stage& s, DyadRows& rows) const;
  // Newton on J from (jx, jy); the iterations taken, or -1 (no convergence, singular).
  int NewtonDyad(const Stage& s, DyadRows& rows, double& jx, double& jy, const StepOptions& options) const;
  // J's jet at the solved J (jj[k]: x and y of the k-th derivative)
  void DyadDerivatives(const Stage& s, const DyadRows& rows, double jx, double jy, double jj[3][2]) const;
  bool SolveDyad(Stage& s, double h, const StepOptions& options);
  // poses link `link` from its point `local_from` at `from` and `local_to` at `to` (jets;
  // `per_span` the inverse distance between the two local points, which the global points keep
  // within the tolerance: a dyad's equation); false when the link turned by 90 degrees or more
  // in the step (its turns could not be counted)
  bool PoseByTwoPoints(int link, const Eigen::Vector2d& local_from, const PointJet& from, const Eigen::Vector2d& local_to,
                       double per_span, const PointJet& to);
  // the angle a stage gives link `link` before whole turns: the drive's, a block's, or for a
  // link posed by two points atan2(s, c) (Load counts the turns against q from it)
  double AngleBeforeTurns(int link, double input) const;
  // poses a link of known angle jet through its local point at `at`
  // (cos and sin of theta given: the stages have them without trigonometry)
  void PoseByAngle(int link, const double theta[3], double c, double s, const Eigen::Vector2d& local, const PointJet& at);
  // the same for a link whose angle is known by cos and sin only: its turns counted against the
  // state stepped from; false when it turned by 90 degrees or more in the step
  bool PoseByCosSin(int link, double c, double s, double t1, double t2, const Eigen::Vector2d& local, const PointJet& at);
  // An output compiled once (point_schedule_outputs.cpp): its points and directions as links and
  // local coordinates, so that a step's outputs look nothing up in the mechanism.
  struct OutputPlan {
    OutputKind kind = OutputKind::kJoint;
    // kJoint: a P joint (else R); kTransmissionAngle: the output link slides on the frame (else
    // it turns about `pivot`)
    bool slide = false;
    // the points p and q: kJoint the joint's on link_a and link_b (R: only the links);
    // kLinkAngle: link_p; kPoint: p; kDistance, kDirection: p and q; kTransmissionAngle: the
    // coupler's line from p to q
    int link_p = -1, link_q = -1;
    Eigen::Vector2d p = Eigen::Vector2d::Zero(), q = Eigen::Vector2d::Zero();
    // a P joint's axis (kJoint, kTransmissionAngle on a slide), local to axis_link
    int axis_link = -1;
    Eigen::Vector2d axis = Eigen::Vector2d::UnitX();
    int pivot_link = -1;
    Eigen::Vector2d pivot = Eigen::Vector2d::Zero();
    double offset = 0.0;  // angle outputs: subtracted from the value
  };
  void CompileOutputs();
  // a transmission angle whose output link slides on the frame (plan.slide), with its derivatives
  point_outputs::ScalarJet SlideTransmission(const OutputPlan& plan) const;
  template <int Order>
  void WriteOutputs(double* out) const;
  // a direction local to `link` in global coordinates, with its derivatives (it turns with theta;
  // u[k]: x and y of the k-th), and the jet q - p so, in scalars (see PointOf)
  void DirectionJet(int link, const Eigen::Vector2d& local, double u[3][2]) const;
  static void Difference(const PointJet& q, const PointJet& p, double d[3][2]);
  static bool IsDyad(Kind k) { return k != Kind::kDriveR && k != Kind::kDriveP; }

  const ConstraintSystem& system_;
  const Mechanism& mechanism_;
  std::string why_not_;
  std::vector<Stage> stages_;
  std::vector<OutputPlan> outputs_;
  // The states: kHistory slots of one LinkJet per link, the solved state in slot at_. A step
  // writes the next slot (now_) from the solved one (before_); a refused step leaves at_.
  std::vector<std::vector<LinkJet>> states_;
  std::vector<double> state_input_;
  int at_ = 0, history_ = 0, n_links_ = 0;
  LinkJet* now_ = nullptr;
  const LinkJet* before_ = nullptr;
  double length_scale_ = 1.0;
  double input_ = 0.0;
  int frame_ = -1;
  int read_ = 0, write_ = 0;  // the stages' buffers (Stage::j) of the solved state and of the step
  // the input step that led to the solved state when the stages' other buffers hold the state
  // before it (the dyads' quintic prediction); 0 when they do not (after Load, a refused step)
  double h_before_ = 0.0;
  // the dyads' prediction of J at the step's input
  PredictionWeights prediction_;
};

// Inline: the stages and the outputs ask for several points a step.
[[gnu::always_inline]] inline PointSchedule::PointJet PointSchedule::PointOf(const LinkJet& l, const Eigen::Vector2d& local) {
  // local - at_local turned with the link (r), from `at`: R' = theta' R perp. Written in scalars:
  // a 2-vector built from two scalars and then added as a pair goes through the stack, where
  // the pair's load waits for the two stores (a store-forwarding stall, 10 % of a step).
  const double vx = local.x() - l.at_local.x(), vy = local.y() - l.at_local.y();
  const double rx = l.c * vx - l.s * vy, ry = l.s * vx + l.c * vy;
  const double t1 = l.theta[1], t2 = l.theta[2], t11 = t1 * t1;
  PointJet g;
  g.p[0].x() = l.at[0].x() + rx;
  g.p[0].y() = l.at[0].y() + ry;
  g.p[1].x() = l.at[1].x() - t1 * ry;
  g.p[1].y() = l.at[1].y() + t1 * rx;
  g.p[2].x() = l.at[2].x() - t2 * ry - t11 * rx;
  g.p[2].y() = l.at[2].y() + t2 * rx - t11 * ry;
  return g;
}

[[gnu::always_inline]] inline PointSchedule::PointJet PointSchedule::GlobalPoint(int link, const Eigen::Vector2d& local) const {
  if (link == frame_) {  // at rest, in its own coordinates
    PointJet g;
    g.p[0] = local;
    g.p[1].setZero();
    g.p[2].setZero();
    return g;
  }
  return PointOf(now_[link], local);
}

}  // namespace koppel

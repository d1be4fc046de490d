#include "koppel/synthesis/motion_synthesis.hpp"

#include "koppel/analysis/extremes.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"
#include "koppel/core/plane.hpp"
#include "koppel/solver/position.hpp"
#include "koppel/solver/sweep.hpp"
#include "koppel/synthesis/four_bar_design.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/worker_threads.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <thread>

namespace koppel {
namespace {

// The 1e-9 of the mechanism's size for the poses; links shorter than this are degenerate.
constexpr double kPoseTolerance = 1e-9;
// The search step of the transmission angle's extremes over the travel [rad] (1 deg): brackets
// them (a four-bar's mu has at most two stationary points and two folds a turn), Newton refines.
constexpr double kMuStep = kPi / 180;

double Positive(double angle) {
  const double r = std::fmod(angle, 2 * kPi);
  return r < 0 ? r + 2 * kPi : r;
}

// The size the tolerances refer to: the longest link or distance between the joints.
double MechanismSize(const Dyad& crank, const Dyad& rocker) {
  const Eigen::Vector2d p[] = {crank.centre, crank.circle, rocker.circle, rocker.centre};
  double size = 0;
  for (const auto& u : p)
    for (const auto& v : p) size = std::max(size, (u - v).norm());
  return size;
}

// The plane's pose error of the assembled pose q against a pose: distance and angle times size.
double PoseError(const PositionSolver& solver, const Eigen::VectorXd& q, const Pose& pose, double size) {
  const ConstraintSystem& s = solver.system();
  const Eigen::Vector2d p(s.Output(0, 0, q.data()), s.Output(0, 1, q.data()));
  return std::max((p - pose.point).norm(), std::abs(AngleDifference(s.Output(1, 0, q.data()), pose.angle)) * size);
}

// The coupler's error in pose j with the mechanism assembled there from that pose's own
// geometry (its hint moved there); nullopt when the solver does not assemble it.
std::optional<double> PoseErrorAssembledAt(const Mechanism& m, const std::vector<Pose>& poses, int j, const Eigen::Vector2d& a,
                                           const Eigen::Vector2d& b, double input, double size) {
  Mechanism at = m;
  const Eigen::Vector2d aj = MovePoint(poses[0], poses[j], a), bj = MovePoint(poses[0], poses[j], b);
  at.hint.points.clear();
  HintInput(at, input);
  HintPoint(at, "crank", "A", aj);
  HintPoint(at, "coupler", "A", aj);
  HintPoint(at, "coupler", "B", bj);
  HintPoint(at, "coupler", "P", poses[j].point);
  HintPoint(at, "rocker", "B", bj);
  PositionSolver solver(at);
  Eigen::VectorXd q(solver.NumCoordinates());
  if (!solver.Assemble(q).ok()) return std::nullopt;
  return PoseError(solver, q, poses[j], size);
}

// Assembles the four-bar f.mechanism in every pose from that pose's own geometry (the crank's
// direction there in phi) and checks the coupler's pose error; notes a change of assembly branch
// between the poses. False, with f->message, when a pose does not assemble or is missed.
bool CouplerHitsEveryPose(const std::vector<Pose>& poses, double size, std::vector<double>* phi, MotionFourBar* f) {
  const Eigen::Vector2d a0 = f->crank.centre, a = f->crank.circle, b = f->rocker.circle, b0 = f->rocker.centre;
  const int n = static_cast<int>(poses.size());
  phi->assign(n, 0.0);
  std::vector<int> branch(n);
  for (int j = 0; j < n; ++j) {
    const Eigen::Vector2d aj = MovePoint(poses[0], poses[j], a), bj = MovePoint(poses[0], poses[j], b);
    (*phi)[j] = Direction(aj - a0);
    branch[j] = FourBarBranch(aj, bj, b0);
    const std::optional<double> error = PoseErrorAssembledAt(f->mechanism, poses, j, a, b, (*phi)[j], size);
    if (!error) {
      f->message = fmt::format("the solver does not assemble the four-bar in pose {}", j + 1);
      return false;
    }
    f->pose_error = std::max(f->pose_error, *error);
  }
  if (f->pose_error > kPoseTolerance * size) {
    f->message = fmt::format("the coupler misses a pose by {:.3g} (tolerance {:.3g})", f->pose_error, kPoseTolerance * size);
    return false;
  }
  for (int j = 1; j < n; ++j) f->branch_defect = f->branch_defect || branch[j] != branch[0];
  return true;
}

// The drivable range of the first pose's branch and the crank angle of each pose (phi) in the
// sense of travel, unwrapped: a full turn's sense is the order of the poses (or, out of order, the
// shorter way to the last); a swinging crank's is its range. Sets the order and reach defects.
std::vector<double> CrankTravelThroughPoses(const std::vector<double>& phi, MotionFourBar* f) {
  const int n = static_cast<int>(phi.size());
  const InputRange reach = DrivableRange(f->mechanism, 2 * kPi * 1.05, DegToRad(1));
  f->crank_turns_fully = !reach.low_limited && !reach.high_limited;
  std::vector<double> travel(n);  // unwrapped inputs in the sense of travel
  if (f->crank_turns_fully) {
    f->drive_from = phi[0];
    f->drive_to = phi[0] + 2 * kPi;
    std::vector<double> ccw(n), cw(n);
    for (int j = 0; j < n; ++j) {
      ccw[j] = Positive(phi[j] - phi[0]);
      cw[j] = Positive(phi[0] - phi[j]);
    }
    const bool in_ccw = std::is_sorted(ccw.begin(), ccw.end()), in_cw = std::is_sorted(cw.begin(), cw.end());
    f->order_defect = !in_ccw && !in_cw;
    const bool sense = in_ccw || (!in_cw && ccw[n - 1] <= cw[n - 1]);  // out of order: the shorter way to the last
    for (int j = 0; j < n; ++j) travel[j] = phi[0] + (sense ? ccw[j] : -cw[j]);
  } else {
    f->drive_from = reach.low;
    f->drive_to = reach.high;
    bool reachable = true;
    for (int j = 0; j < n; ++j) {
      travel[j] = reach.low + Positive(phi[j] - reach.low);
      reachable = reachable && travel[j] <= reach.high + 1e-12;
    }
    f->branch_defect = f->branch_defect || !reachable;
    const bool up = std::is_sorted(travel.begin(), travel.end()), down = std::is_sorted(travel.rbegin(), travel.rend());
    f->order_defect = !up && !down;
  }
  return travel;
}

// Driven from the first pose, the crank reaches every other one on its branch (else a branch
// defect with its message). False, with f->message, when the first pose does not assemble or is
// a singular position.
bool CrankReachesPosesOnItsBranch(const std::vector<Pose>& poses, const std::vector<double>& travel, double size,
                                  MotionFourBar* f) {
  PositionSolver solver(f->mechanism);
  Eigen::VectorXd q(solver.NumCoordinates());
  if (!solver.Assemble(q).ok()) {
    f->message = "the solver does not assemble the four-bar in the first pose";
    return false;
  }
  if (f->branch_defect) return true;
  Continuation path(solver);
  if (!path.Start(travel[0], q).ok()) {
    f->message = "the first pose is a singular position";
    return false;
  }
  for (size_t j = 1; j < travel.size() && !f->branch_defect; ++j) {
    if (!path.AdvanceTo(travel[j], 0.05).ok() || PoseError(solver, path.q(), poses[j], size) > kPoseTolerance * size) {
      f->branch_defect = true;
      f->message = fmt::format("driven from the first pose the crank does not reach pose {} (another circuit)", j + 1);
    }
  }
  return true;
}

// mu_min over the travel from the first pose to the last (on the first pose's branch). False,
// with f->message, when it cannot be evaluated: no number rather than a wrong one.
bool SetMinimumTransmissionAngle(const std::vector<double>& travel, MotionFourBar* f) {
  SweepOptions sweep;
  sweep.from = travel.front();
  sweep.to = travel.back();
  const double span = std::abs(sweep.to - sweep.from);
  sweep.step = span > 0 ? span / std::ceil(span / kMuStep) : kMuStep;
  const OutputExtremes mu = FindOutputExtremes(f->mechanism, 3, 0, sweep);
  if (!Usable(mu.status)) {
    f->message = "the transmission angle over the travel cannot be evaluated: " + mu.message;
    return false;
  }
  f->mu_min = mu.minimum.value;
  if (mu.status == AnalysisStatus::kPartial && f->message.empty()) {
    f->message = "mu_min only over the part of the travel the branch reaches: " + mu.sweep.message;
  }
  return true;
}

}  // namespace

bool MotionOptions::IsValid(std::string* why) const {
  std::string problem;
  if (threads < 0 || threads > kMaxThreads) problem = "threads must be 0 (one per core) to " + std::to_string(kMaxThreads) + " (kMaxThreads)";
  if (why) *why = problem;
  return problem.empty();
}

MotionFourBar AnalyseMotionFourBar(const std::vector<Pose>& poses, const Dyad& crank, const Dyad& rocker) {
  MotionFourBar f;
  f.crank = crank;
  f.rocker = rocker;
  const double size = MechanismSize(crank, rocker);
  const Eigen::Vector2d a0 = crank.centre, a = crank.circle, b = rocker.circle, b0 = rocker.centre;
  const double shortest = std::min({(a - a0).norm(), (b - a).norm(), (b0 - b).norm(), (b0 - a0).norm()});
  if (!(shortest > kPoseTolerance * std::max(size, PoseScale(poses)))) {
    f.message = "a link of zero length (the two dyads share a point)";
    return f;
  }
  FourBarGeometry g;
  g.a0 = a0;
  g.a = a;
  g.b = b;
  g.b0 = b0;
  g.plane_origin = poses[0].point;
  g.plane_angle = poses[0].angle;
  f.mechanism = DesignedFourBar(g, "burmester-four-bar");
  f.grashof = ClassifyChain(f.mechanism).grashof;

  // every pose: assembled by the solver from its own geometry, the plane where the pose says
  std::vector<double> phi;
  if (!CouplerHitsEveryPose(poses, size, &phi, &f)) return f;
  f.pose_inputs = CrankTravelThroughPoses(phi, &f);
  if (!CrankReachesPosesOnItsBranch(poses, f.pose_inputs, size, &f)) return f;
  // the four-bar is reported as failed when its mu_min is not known
  if (!SetMinimumTransmissionAngle(f.pose_inputs, &f)) return f;
  f.passes = true;
  return f;
}

std::uint64_t MotionFourBarCount(std::size_t dyads, const MotionOptions& options) {
  const std::uint64_t n = dyads;
  const std::uint64_t pairs = n < 2 ? 0 : n * (n - 1);  // ordered: each pair driven at either centre
  return options.both_drives ? pairs : pairs / 2;
}

FourBarSizes MotionFourBarSizes(const std::vector<Pose>& poses, const MotionFourBar& f) {
  const Eigen::Vector2d a = f.crank.circle, b = f.rocker.circle, along = (b - a).normalized(), left(-along.y(), along.x());
  const Eigen::Vector2d k = poses.front().point - a;
  return {f.crank.centre, f.rocker.centre, (a - f.crank.centre).norm(), (b - a).norm(), (b - f.rocker.centre).norm(),
          Eigen::Vector2d(k.dot(along), k.dot(left)), f.mu_min};
}

MotionResult FourBarsFromDyads(const std::vector<Pose>& poses, const std::vector<Dyad>& dyads, const MotionOptions& options) {
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < static_cast<int>(dyads.size()); ++i) {
    for (int j = 0; j < static_cast<int>(dyads.size()); ++j) {
      if (i == j || (!options.both_drives && j < i)) continue;
      pairs.push_back({i, j});
    }
  }
  std::vector<MotionFourBar> all(pairs.size());
  std::atomic<size_t> next{0};
  auto work = [&] {
    for (size_t k = next++; k < pairs.size(); k = next++) all[k] = AnalyseMotionFourBar(poses, dyads[pairs[k].first], dyads[pairs[k].second]);
  };
  RunOnThreads(options.threads, work);
  MotionResult result;
  for (MotionFourBar& f : all) {
    if (!f.passes) {
      // a shared point is no four-bar, not a failed one
      if (f.message.rfind("a link of zero length", 0) == 0) continue;
      ++result.failed;
      result.failures.push_back(f.message);
    } else if (options.require_crank && !f.crank_turns_fully) {
      ++result.rejected;
    } else if (const std::string v = options.space.Violation(MotionFourBarSizes(poses, f)); !v.empty()) {
      if (result.outside_space++ == 0) result.outside_reason = v;
    } else {
      result.four_bars.push_back(std::move(f));
    }
  }
  // a four-bar with a branch or order defect does not carry the plane through the poses when
  // driven: every defect-free one first, then by mu_min
  std::stable_sort(result.four_bars.begin(), result.four_bars.end(), [](const MotionFourBar& x, const MotionFourBar& y) {
    if (x.DefectFree() != y.DefectFree()) return x.DefectFree();
    return x.mu_min > y.mu_min;
  });
  result.defect_free = static_cast<int>(std::count_if(result.four_bars.begin(), result.four_bars.end(), [](const MotionFourBar& f) { return f.DefectFree(); }));
  return result;
}

}  // namespace koppel

#include "koppel/analysis/ranges.hpp"

#include "same_pose.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/assembly.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace koppel {
namespace {

// Probe inputs: every 30 degrees of a rotating drive, every L/4 of a sliding one.
constexpr int kProbesPerTurn = 12;
constexpr double kProbeSpacingOfL = 0.25;

RangeEnd EndOf(WalkStatus status) {
  switch (status) {
    case WalkStatus::kLimitPoint: return RangeEnd::kLimit;
    case WalkStatus::kBranchPointStop: return RangeEnd::kBranchPoint;
    default: return RangeEnd::kFailed;
  }
}

class RangeFinder {
 public:
  RangeFinder(const Mechanism& m, const RangeOptions& options)
      : m_(m), options_(options), solver_(m), angle_(m.InputIsAngle()), scale_(solver_.system().length_scale()),
        grid_origin_(m.hint.input), grid_step_(angle_ ? 2 * kPi / kProbesPerTurn : kProbeSpacingOfL * scale_) {}

  PositionSolver& solver() { return solver_; }

  // Follows the branch through (input, q) both ways and records its poses at the probe inputs.
  BranchRange Follow(int branch, double input, const Eigen::VectorXd& q) {
    BranchRange range;
    range.branch = branch;
    range.start = input;
    range.start_q = q;
    records_.push_back({input, q});
    if (angle_) {
      FollowRotating(range);
    } else {
      const double span = options_.span * scale_;
      WalkOneWay(range, +1.0, input + span, &range.to, &range.to_kind);
      WalkOneWay(range, -1.0, input - span, &range.from, &range.from_kind);
    }
    std::sort(range.singular_points.begin(), range.singular_points.end(),
              [](const SingularPoint& a, const SingularPoint& b) { return a.input < b.input; });
    return range;
  }

  // True when (input, q) lies on a branch already followed: a pose recorded at the same probe
  // input (modulo a turn for a rotating drive) is the same pose.
  bool Known(double input, const Eigen::VectorXd& q) const {
    for (const Record& r : records_) {
      const double d = angle_ ? AngleDifference(r.input, input) : r.input - input;
      if (std::abs(d) < 1e-9 * (angle_ ? 1.0 : scale_) && SamePose(r.q, q, scale_)) return true;
    }
    return false;
  }

  // Poses at the probe inputs of one turn (or of the span) from seeded random guesses.
  std::vector<std::pair<double, Eigen::VectorXd>> Candidates() {
    std::vector<std::pair<double, Eigen::VectorXd>> found;
    std::mt19937 random(options_.seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const int n = solver_.NumCoordinates();
    const int probes = angle_ ? kProbesPerTurn : 2 * static_cast<int>(std::lround(2.0 / kProbeSpacingOfL)) + 1;
    for (int k = 0; k < probes; ++k) {
      const double input = angle_ ? grid_origin_ + k * grid_step_ : grid_origin_ + (k - probes / 2) * grid_step_;
      for (int s = 0; s < options_.starts_per_input; ++s) {
        Eigen::VectorXd q(n);
        for (int i = 0; i < n; ++i) q(i) = i % 3 == 2 ? kPi * unit(random) : 2.0 * scale_ * unit(random);
        if (!solver_.AssembleFrom(input, q).ok()) continue;
        if (ReciprocalCondition(solver_.system(), q) < kSingularRowRcond) continue;
        const bool repeat = std::any_of(found.begin(), found.end(), [&](const auto& f) {
          return std::abs(f.first - input) < 1e-12 && SamePose(f.second, q, scale_);
        });
        if (!repeat) found.emplace_back(input, q);
      }
    }
    return found;
  }

 private:
  struct Record {
    double input;
    Eigen::VectorXd q;
  };

  // Probe inputs strictly between `from` and `to` (either order), in walking order.
  std::vector<double> ProbesBetween(double from, double to) const {
    std::vector<double> probes;
    const double direction = to > from ? 1.0 : -1.0;
    double k = direction > 0 ? std::floor((from - grid_origin_) / grid_step_) + 1 : std::ceil((from - grid_origin_) / grid_step_) - 1;
    for (;; k += direction) {
      const double p = grid_origin_ + k * grid_step_;
      if (direction * (to - p) <= 0) break;
      if (direction * (p - from) > 1e-12 * grid_step_) probes.push_back(p);
    }
    return probes;
  }

  void Absorb(const Continuation& path, BranchRange& range) {
    range.singular_points.insert(range.singular_points.end(), path.singular_points().begin(), path.singular_points().end());
  }

  // Walks one way to `bound`, recording the probes; *end and *kind say where and why it ended.
  void WalkOneWay(BranchRange& range, double direction, double bound, double* end, RangeEnd* kind) {
    Continuation path(solver_, options_.continuation);
    path.Start(range.start, range.start_q);
    std::vector<double> targets = ProbesBetween(range.start, bound);
    targets.push_back(bound);
    for (double target : targets) {
      const WalkReport report = path.AdvanceTo(target, std::numeric_limits<double>::infinity());
      if (!report.ok()) {
        *end = report.input;
        *kind = EndOf(report.status);
        if (*kind == RangeEnd::kFailed) range.message = report.message;
        Absorb(path, range);
        return;
      }
      records_.push_back({target, path.q()});
    }
    *end = bound;
    *kind = RangeEnd::kBound;
    (void)direction;
    Absorb(path, range);
  }

  // A rotating drive: up, turn by turn, until a limit or the pose repeats; down only when limited.
  void FollowRotating(BranchRange& range) {
    Continuation path(solver_, options_.continuation);
    path.Start(range.start, range.start_q);
    for (int turn = 1; turn <= options_.max_turns; ++turn) {
      const double turn_end = range.start + turn * 2 * kPi;
      std::vector<double> targets = ProbesBetween(turn_end - 2 * kPi, turn_end);
      targets.push_back(turn_end);
      for (double target : targets) {
        const WalkReport report = path.AdvanceTo(target, std::numeric_limits<double>::infinity());
        if (!report.ok()) {
          range.to = report.input;
          range.to_kind = EndOf(report.status);
          if (range.to_kind == RangeEnd::kFailed) range.message = report.message;
          Absorb(path, range);
          WalkOneWay(range, -1.0, range.start - options_.max_turns * 2 * kPi, &range.from, &range.from_kind);
          return;
        }
        records_.push_back({target, path.q()});
      }
      if (SamePose(path.q(), range.start_q, scale_)) {
        range.period = turn * 2 * kPi;
        break;
      }
    }
    Absorb(path, range);
    // turns fully: the pose repeats after `period` (or, unknown period, at least max_turns turns)
    range.from = 0.0;
    range.to = range.period > 0 ? range.period : 2 * kPi;
    range.from_kind = range.to_kind = RangeEnd::kFullTurn;
  }

  const Mechanism& m_;
  const RangeOptions& options_;
  PositionSolver solver_;
  bool angle_;
  double scale_;
  double grid_origin_, grid_step_;
  std::vector<Record> records_;
};

}  // namespace

const char* ToString(RangeEnd end) {
  switch (end) {
    case RangeEnd::kLimit: return "limit";
    case RangeEnd::kBranchPoint: return "branch-point";
    case RangeEnd::kFullTurn: return "full-turn";
    case RangeEnd::kBound: return "bound";
    case RangeEnd::kFailed: return "failed";
  }
  return "failed";
}

const char* ToString(RangeStatus status) {
  switch (status) {
    case RangeStatus::kNotRun: return "not run";
    case RangeStatus::kDone: return "done";
    case RangeStatus::kNotAssemblable: return "not assemblable";
    case RangeStatus::kInvalidOptions: return "invalid options";
  }
  return "not run";
}

bool RangeOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (max_turns < 1 || max_turns > 64) return fail("max_turns must lie in 1..64");
  if (!(span > 0) || !std::isfinite(span) || span > 1e6) return fail("span must lie in (0, 1e6] lengths L");
  if (starts_per_input < 1 || starts_per_input > 10000) return fail("starts_per_input must lie in 1..10000");
  return continuation.IsValid(why);
}

bool RangeReport::HasFailure() const {
  return std::any_of(branches.begin(), branches.end(), [](const BranchRange& b) {
    return b.from_kind == RangeEnd::kFailed || b.to_kind == RangeEnd::kFailed;
  });
}

std::string RangeReport::Brief() const {
  std::string brief = std::string(ToString(status)) + ": " + std::to_string(branches.size()) + " branch" +
                      (branches.size() == 1 ? "" : "es");
  if (HasFailure()) brief += ", some walks failed";
  return brief;
}

RangeReport DrivableRanges(const Mechanism& m, const RangeOptions& options) {
  RangeReport report;
  std::string why;
  if (!options.IsValid(&why)) {
    report.status = RangeStatus::kInvalidOptions;
    report.message = why;
    return report;
  }
  RangeFinder finder(m, options);
  const Assembly assembly = AssembleRegular(m, finder.solver(), options.continuation);
  if (!assembly.ok()) {
    report.status = RangeStatus::kNotAssemblable;
    report.message = assembly.error;
    return report;
  }
  report.notes = assembly.notes;
  report.branches.push_back(finder.Follow(0, assembly.input, assembly.q));
  if (options.all_branches) {
    for (const auto& [input, q] : finder.Candidates()) {
      if (finder.Known(input, q)) continue;
      report.branches.push_back(finder.Follow(static_cast<int>(report.branches.size()), input, q));
    }
  }
  report.status = RangeStatus::kDone;
  return report;
}

}  // namespace koppel

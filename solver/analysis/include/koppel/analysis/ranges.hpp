// Drivable ranges: for each assembly branch (Einbaulage) of a mechanism, the interval of the
// drive input over which it assembles, and what ends it.
//
// A branch is followed by continuation from one of its poses, up and down: a limit point (dead
// centre of the drive) ends it; a branch point ends it only with BranchPointAction::kStop; a
// rotating drive that comes back to the same pose after k full turns turns fully (period
// 2 pi k); the search bound (max_turns turns, or span L for a P drive) ends it otherwise.
// With all_branches, poses are also searched from many seeded random guesses at inputs spread
// over a turn (or over the span), and every pose not on a branch already followed starts another.
#pragma once

#include "koppel/core/mechanism.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/singular.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

enum class RangeEnd {
  kLimit,        // a limit point of the drive
  kBranchPoint,  // a branch point, where the options say stop
  kFullTurn,     // the drive turns fully: the pose repeats after `period`
  kBound,        // the search bound was reached
  kFailed,       // no pose beyond (Newton failed without a singular position): see message
};
const char* ToString(RangeEnd end);  // "limit", "branch-point", "full-turn", "bound", "failed"

struct BranchRange {
  int branch = 0;           // 0: the branch the mechanism's assembly hint chooses
  double from = 0.0, to = 0.0;  // [rad for an R drive, length for a P drive]; full turn: 0 .. period
  RangeEnd from_kind = RangeEnd::kBound, to_kind = RangeEnd::kBound;
  double period = 0.0;      // full turn: the input after which the pose repeats (2 pi k); else 0
  double start = 0.0;       // an input on the branch, and its pose there
  Eigen::VectorXd start_q;
  std::vector<SingularPoint> singular_points;  // met between from and to
  std::string message;      // why a walk failed (RangeEnd::kFailed)
};

struct RangeOptions {
  bool all_branches = false;
  ContinuationOptions continuation;
  int max_turns = 4;           // R drive: turns followed each way while looking for the period
  double span = 100.0;         // P drive: search bound each way, in units of the length scale L
  int starts_per_input = 24;   // all_branches: random guesses per probe input
  unsigned seed = 1;           // all_branches: the guesses' seed (the search is reproducible)
  bool IsValid(std::string* why) const;
};

enum class RangeStatus { kNotRun, kDone, kNotAssemblable, kInvalidOptions };
const char* ToString(RangeStatus status);

struct RangeReport {
  RangeStatus status = RangeStatus::kNotRun;
  std::string message;             // why not done
  std::vector<std::string> notes;  // e.g. the hint's input is a singular position
  std::vector<BranchRange> branches;
  // True when a walk failed: the intervals are then incomplete.
  bool HasFailure() const;
  std::string Brief() const;
};

RangeReport DrivableRanges(const Mechanism& mechanism, const RangeOptions& options = {});

}  // namespace koppel

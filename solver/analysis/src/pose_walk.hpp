// A walk from a mechanism's assembly to the inputs asked for, on the assembly branch: the pose
// and its Taylor coefficients at each. Private to the analysis library.
#pragma once

#include "koppel/solver/assembly.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/position.hpp"

#include <memory>
#include <string>

namespace koppel {

class PoseWalk {
 public:
  // The mechanism must outlive the walk.
  explicit PoseWalk(const Mechanism& mechanism) : solver_(mechanism) {
    const Assembly assembly = AssembleRegular(mechanism, solver_);
    if (!assembly.ok()) {
      error_ = "the mechanism does not assemble: " + assembly.error;
      return;
    }
    walk_ = std::make_unique<Continuation>(solver_);
    const SolveReport start = walk_->Start(assembly.input, assembly.q);
    if (!start.ok()) {
      error_ = "the mechanism does not assemble: " + start.message;
      walk_.reset();
    }
  }
  bool started() const { return walk_ != nullptr; }
  const std::string& error() const { return error_; }
  // Walks to `input`; on success the solver's factorisation is at the pose reached. Empty
  // string when reached and regular, else why not.
  std::string To(double input) {
    if (!walk_) return error_;
    const WalkReport report = walk_->AdvanceTo(input, ContinuationOptions{}.max_step);
    if (!report.ok()) return report.message.empty() ? std::string(ToString(report.status)) : report.message;
    if (walk_->AtSingularPose()) return "the pose is a singular position of the mechanism";
    return {};
  }
  Continuation& walk() { return *walk_; }
  PositionSolver& solver() { return solver_; }

 private:
  PositionSolver solver_;
  std::unique_ptr<Continuation> walk_;
  std::string error_;
};

}  // namespace koppel

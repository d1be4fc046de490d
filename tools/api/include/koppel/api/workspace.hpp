// The mutable part beside an immutable koppel::Model: a current pose and the walk along the
// drive's branch that moves it (the solver and the continuation of koppel/solver). Units as in
// koppel/api/model.hpp. A Workspace keeps its own copy of the model (copies share the file), so
// the model it was made from may go; it is not safe for concurrent use, and a copy of it starts
// without a pose.
#pragma once

#include "koppel/api/model.hpp"

#include <memory>

namespace koppel {

class Workspace {
 public:
  explicit Workspace(Model model);
  Workspace(const Workspace& other);
  Workspace& operator=(const Workspace& other);
  Workspace(Workspace&&) noexcept;
  Workspace& operator=(Workspace&&) noexcept;
  ~Workspace();

  const Model& model() const { return model_; }

  // Assembles at the file's assembly hint and makes that the current pose; transfer functions up
  // to `order` (0..8).
  PoseResult Assemble(int order = 2);
  // Drives from the current pose (assembling first if there is none) along its branch to `input`
  // [deg | length]: through branch points as `at_branch_point` says, never past a limit point.
  // On failure the pose stays where the walk ended and the status is failed.
  PoseResult MoveTo(double input, int order = 2, AtBranchPoint at_branch_point = AtBranchPoint::kContinue);
  bool assembled() const;

 private:
  struct Walk;
  Model model_;
  std::unique_ptr<Walk> walk_;  // null until assembled
};

}  // namespace koppel

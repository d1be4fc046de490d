#include "koppel/api/workspace.hpp"

#include "display.hpp"
#include "model_impl.hpp"

#include "koppel/solver/assembly.hpp"
#include "koppel/solver/continuation.hpp"
#include "koppel/solver/position.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace koppel {

using namespace api_detail;

// A solver and a walk on the workspace's model: both hold references into the model's file,
// which the workspace's own copy of the model keeps alive and unchanged.
struct Workspace::Walk {
  std::unique_ptr<PositionSolver> solver;
  std::unique_ptr<Continuation> walk;
  AtBranchPoint action = AtBranchPoint::kContinue;

  void Start(const Assembly& assembly, AtBranchPoint at_branch_point) {
    ContinuationOptions options;
    options.at_branch_point = at_branch_point;
    walk = std::make_unique<Continuation>(*solver, options);
    action = at_branch_point;
    walk->Start(assembly.input, assembly.q);
  }

  PoseResult Pose(const Model& model, int order) const {
    const Mechanism& m = model.mechanism();
    const SweepColumns layout = SweepLayout(m, order, model.length_unit());
    PoseResult r;
    r.status = AnalysisStatus::kComplete;
    r.input = InputShown(m, walk->input());
    r.columns = layout.names;
    r.values.resize(layout.names.size());
    // the Taylor series of q to at least 2nd order: OutputDerivatives reads the angles' rates
    const Eigen::MatrixXd& series = walk->Series(std::max(order, 2));
    std::vector<double> outputs(solver->OutputWidth(order));
    solver->OutputDerivatives(series, order, outputs.data());
    r.valid_order = std::min(walk->ValidOrder(), order);
    r.singular = walk->AtSingularPose();
    DisplayRow(m, layout, walk->input(), outputs.data(), r.valid_order, r.singular, r.values.data());
    return r;
  }
};

namespace {

void CheckOrder(const std::string& file, int order) {
  if (order < 0 || order > kMaxOrder)
    BadInput(file, "order", "the transfer-function order must be 0.." + std::to_string(kMaxOrder) + ", not " + std::to_string(order));
}

}  // namespace

Workspace::Workspace(Model model) : model_(std::move(model)) {}
Workspace::Workspace(const Workspace& other) : model_(other.model_) {}  // the pose is not copied: the copy assembles anew
Workspace& Workspace::operator=(const Workspace& other) {
  if (this != &other) {
    model_ = other.model_;
    walk_.reset();
  }
  return *this;
}
Workspace::Workspace(Workspace&&) noexcept = default;
Workspace& Workspace::operator=(Workspace&&) noexcept = default;
Workspace::~Workspace() = default;

bool Workspace::assembled() const { return walk_ != nullptr; }

PoseResult Workspace::Assemble(int order) {
  CheckOrder(model_.path(), order);
  walk_.reset();
  auto walk = std::make_unique<Walk>();
  walk->solver = std::make_unique<PositionSolver>(model_.mechanism());
  const Assembly assembly = AssembleRegular(model_.mechanism(), *walk->solver);
  if (!assembly.ok()) {
    PoseResult r;
    r.status = AnalysisStatus::kFailed;
    r.message = assembly.error;
    r.input = InputShown(model_.mechanism(), model_.mechanism().hint.input);
    return r;
  }
  walk->Start(assembly, AtBranchPoint::kContinue);
  walk_ = std::move(walk);
  return walk_->Pose(model_, order);
}

PoseResult Workspace::MoveTo(double input, int order, AtBranchPoint at_branch_point) {
  CheckOrder(model_.path(), order);
  if (!std::isfinite(input)) BadInput(model_.path(), "input", "the input is not a finite number");
  if (!assembled()) {
    const PoseResult assembled_pose = Assemble(order);
    if (assembled_pose.status != AnalysisStatus::kComplete) return assembled_pose;
  }
  if (walk_->action != at_branch_point) {
    // a walk keeps its options: start one with these from the current pose
    walk_->Start(Assembly{walk_->walk->q(), walk_->walk->input(), "", {}}, at_branch_point);
  }
  const WalkReport report = walk_->walk->AdvanceTo(InputInternal(model_.mechanism(), input), std::numeric_limits<double>::infinity());
  PoseResult r = walk_->Pose(model_, order);
  if (!report.ok()) {
    r.status = AnalysisStatus::kFailed;
    r.message = report.message;
  }
  return r;
}

}  // namespace koppel

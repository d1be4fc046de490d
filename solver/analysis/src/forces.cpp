#include "koppel/analysis/forces.hpp"

#include "koppel/analysis/inertia.hpp"
#include "koppel/analysis/loads_at_pose.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace koppel {
namespace {

// The size of the drive torque the loads make: sum |F| L + |M| (L the mechanism's length scale,
// in metres), over L for a P drive's force. What the two drives are compared to, also where the
// loads do no work (a dead centre of the loaded point) or cancel.
double LoadScale(const PoseMotion& pose, const AppliedLoads& loads) {
  const double lever = pose.system().length_scale() * pose.metres_per_unit();
  double scale = 0.0;
  for (const AppliedLoads::Force& f : loads.forces) scale += f.force.norm() * lever;
  for (const AppliedLoads::Torque& t : loads.torques) scale += std::abs(t.torque);
  return pose.system().mechanism().InputIsAngle() ? scale : scale / lever;
}

// The name of the first value that is not a finite number, or nullptr.
const char* FirstNonFinite(const std::vector<std::pair<const char*, double>>& values) {
  for (const auto& [name, value] : values) {
    if (!std::isfinite(value)) return name;
  }
  return nullptr;
}

std::string NotFiniteMessage(const char* quantity) {
  return std::string(quantity) + " is not a finite number: it overflows a double (loads, masses or length unit too large)";
}

}  // namespace

bool ForcesOptions::IsValid(std::string* why) const {
  if (speed && !std::isfinite(*speed)) {
    if (why) *why = "the drive speed must be a finite number";
    return false;
  }
  return sweep.IsValid(why);
}

std::string ForcesResult::Brief() const {
  int computed = 0;
  for (const ForcesRow& row : rows) computed += row.computed;
  std::string brief = std::string(ToString(status)) + (kinetostatic ? " (kinetostatics)" : " (statics)") + ": forces at " +
                      std::to_string(computed) + " of " + std::to_string(rows.size()) + " samples";
  if (indeterminate) brief += ", reactions statically indeterminate";
  return brief;
}

namespace {

// What every pose of a force analysis shares.
struct ForcesContext {
  const Loads& loads;
  const LoadModel& model;
  PositionSolver& solver;
  const ForcesOptions& options;
  bool indeterminate;
};

// The forces of one computed sample into `row` (its input and pose set); the error says why a
// sample has none. row.virtual_work tells whether the virtual-work drive torque was reached.
Outcome ForcesAt(const ForcesContext& c, Eigen::MatrixXd& series, ForcesRow& row) {
  if (row.singular)
    return Outcome::Error("the pose is singular: at a limit point the drive torque to hold the loads is unbounded, at a branch "
                          "point the reactions are not determined");
  const SolveReport solved = c.solver.Correct(row.input, row.q);
  if (!solved.ok() || !c.solver.Series(2, series)) return Outcome::Error("the pose does not solve again: " + solved.message);
  const PoseMotion pose(c.solver.system(), series, c.loads.metres_per_unit);
  MotionState state;
  state.input = row.input;
  state.speed = c.options.speed.value_or(0.0);
  state.time = state.speed != 0.0 ? (row.input - c.options.sweep.from) / state.speed : 0.0;
  AppliedLoads applied;
  if (Outcome evaluated = c.model.Evaluate(pose, state, &applied); !evaluated) return evaluated;
  if (c.options.speed) applied.Add(InertiaLoads(pose, c.loads.masses, state));
  const ReducedInertia inertia = ReduceInertia(pose, c.loads.masses);
  // a number that overflowed (huge loads, masses or length unit) is no force: the sample says which
  if (const char* name = FirstNonFinite({{"the reduced moment of inertia", inertia.value},
                                         {"its derivative", inertia.derivative},
                                         {"the drive torque by virtual work", VirtualWorkDrive(applied)},
                                         {"the loads' size", LoadScale(pose, applied)}}))
    return Outcome::Error(NotFiniteMessage(name));
  row.reduced_inertia = inertia.value;
  row.reduced_inertia_derivative = inertia.derivative;
  row.drive_virtual_work = VirtualWorkDrive(applied);
  row.load_scale = LoadScale(pose, applied);
  row.virtual_work = true;
  if (c.indeterminate) return Outcome::Error("the joint reactions are statically indeterminate (redundant joints)");
  Reactions reactions;
  if (!JointReactions(c.solver, row.q, GeneralizedForces(pose, applied), c.loads.metres_per_unit, &reactions))
    return Outcome::Error("the multipliers could not be solved for at this pose");
  std::vector<std::pair<const char*, double>> reaction_values = {{"the drive torque from the joint reactions", reactions.drive}};
  for (const JointReaction& j : reactions.joints) {
    for (double v : {j.force.x(), j.force.y(), j.normal, j.moment}) reaction_values.emplace_back("a joint reaction", v);
  }
  if (const char* name = FirstNonFinite(reaction_values)) return Outcome::Error(NotFiniteMessage(name));
  row.drive = reactions.drive;
  row.joints = std::move(reactions.joints);
  row.computed = true;
  return Done();
}

}  // namespace

ForcesResult AnalyseForces(const Mechanism& m, const Loads& loads, const ForcesOptions& options) {
  ForcesResult result;
  result.kinetostatic = options.speed.has_value();
  std::string why;
  auto fail = [&](std::string message, bool bad_input) {
    result.status = AnalysisStatus::kFailed;
    result.message = std::move(message);
    result.bad_input = bad_input;
    return result;
  };
  if (!options.IsValid(&why)) return fail(why, true);
  LoadModel model;
  if (const Outcome prepared = model.Prepare(m, loads); !prepared) return fail(prepared.error(), true);
  SweepOptions sweep_options = options.sweep;
  sweep_options.order = 0;  // the table of outputs is not needed: poses are
  const SweepResult sweep = Sweep(m, sweep_options);
  result.sweep = EventsOf(sweep);
  if (sweep.status == SweepStatus::kNotAssemblable || sweep.status == SweepStatus::kInvalidOptions)
    return fail(sweep.message, sweep.status == SweepStatus::kInvalidOptions);

  PositionSolver solver(m);
  result.indeterminate = solver.system().NumEquations() != solver.NumCoordinates();
  const ForcesContext context{loads, model, solver, options, result.indeterminate};
  Eigen::MatrixXd series;
  int missing = 0;
  for (size_t i = 0; i < sweep.inputs.size(); ++i) {
    ForcesRow row;
    row.input = sweep.inputs[i];
    row.singular = sweep.singular[i] != 0;
    row.q = sweep.poses.row(i).transpose();
    if (const Outcome done = ForcesAt(context, series, row); !done) {
      row.problem = done.error();
      ++missing;
    } else if (row.load_scale > 0.0) {
      result.worst_disagreement = std::max(result.worst_disagreement, std::abs(row.drive - row.drive_virtual_work) / row.load_scale);
    }
    result.rows.push_back(std::move(row));
  }

  if (result.worst_disagreement > kVirtualWorkAgreement)
    return fail("the drive torque from the joint reactions and by virtual work disagree by " +
                    std::to_string(result.worst_disagreement) + " of the loads' size: a bug, please report it",
                false);
  if (sweep.complete() && missing == 0) {
    result.status = AnalysisStatus::kComplete;
    return result;
  }
  result.status = AnalysisStatus::kPartial;
  std::string message;
  if (missing > 0) message = std::to_string(missing) + " of " + std::to_string(sweep.inputs.size()) + " computed samples have no forces";
  if (result.indeterminate) message += ": the mechanism has redundant joints, so its joint reactions are statically indeterminate";
  if (!sweep.complete()) message += (message.empty() ? "" : "; ") + sweep.message;
  result.message = message;
  return result;
}

}  // namespace koppel

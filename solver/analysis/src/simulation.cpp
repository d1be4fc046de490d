#include "koppel/analysis/simulation.hpp"

#include "koppel/analysis/inertia.hpp"
#include "koppel/analysis/loads_at_pose.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/solver/assembly.hpp"

#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace koppel {
namespace {

namespace odeint = boost::numeric::odeint;
using State = std::array<double, 2>;  // input, speed

// Thrown out of the right-hand side where the motion cannot go on; caught by Simulate, which
// first retries with shorter steps (the failing point may be a rejected trial beyond the motion).
struct Stop {
  std::string message;
};

// J_red below this fraction of its largest value along the run counts as zero: the input then
// drives no mass and its acceleration is not determined by the equation of motion.
constexpr double kVanishingInertia = 1e-12;
// A step this much shorter than the output step that still fails means the failure is real.
constexpr double kSmallestRetryStep = 1e-10;
// The step size has collapsed when this many accepted steps in a row are shorter than
// kCollapsedStep of the run: a stiff equation (-1e9*phi_dot against a small inertia needs steps
// of 1e-12 s) or one that explodes; the explicit integrator would take hours, printing nothing.
// After a failed trial (a dead centre ahead) the controller regrows its step within a few dozen
// steps, so a run of this length is not that.
constexpr double kCollapsedStep = 1e-9;
constexpr int kCollapsedSteps = 1000;
// The input one right-hand side may move from the last pose, in turns of the drive (or drive
// lengths of a P drive): the continuation walks there pose by pose, so a speed that explodes
// (a torque exp(1000 t)) would make one evaluation walk millions of turns.
constexpr double kLongestWalk = 50.0;

std::string Where(const Mechanism& m, double t, double input) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "at t = %.9g s, %s = %.9g%s", t, m.drive.input_name.c_str(),
                m.InputIsAngle() ? RadToDeg(input) : input, m.InputIsAngle() ? " deg" : "");
  return buffer;
}

// "1.5e+06 turns" (or drive lengths of a P drive, said the same way: a scale, not a unit).
std::string FormatTurns(double turns) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3g turns", turns);
  return buffer;
}

// The drive's equation of motion with the solver in the loop.
class Dynamics {
 public:
  Dynamics(const Mechanism& m, const Loads& loads, const DriveLaw& drive, const LoadModel& model, const CompiledFormula* formula,
           PositionSolver& solver, Continuation& path)
      : m_(m), loads_(loads), drive_(drive), model_(model), formula_(formula), solver_(solver), path_(path) {}

  // What the right-hand side computed at (t, x), for the table.
  struct Point {
    double acceleration = 0.0, drive = 0.0, kinetic = 0.0, potential = 0.0;
  };

  Point Evaluate(const State& x, double t) {
    const double input = x[0], speed = x[1];
    if (!std::isfinite(input) || !std::isfinite(speed)) throw Stop{"the motion has no finite state " + Where(m_, t, input)};
    const double turn = m_.InputIsAngle() ? 2.0 * kPi : solver_.system().length_scale();
    const double move = std::abs(input - path_.input());
    if (move > kLongestWalk * turn)
      throw Stop{"the motion explodes " + Where(m_, t, input) + ": the input moves " + FormatTurns(move / turn) +
                 " within one step (speed " + FormatTurns(speed / turn) + " per second)"};
    // the work of a run is the walking: a bound on it bounds the run, whatever the speed
    walked_ += move;
    if (walked_ > kMaxSimulationWalk * turn)
      throw Stop{"the position solver walked the input over more than " + FormatTurns(kMaxSimulationWalk) +
                 " (kMaxSimulationWalk) by " + Where(m_, t, input) + ": the motion explodes, or the run is longer than one call does"};
    const WalkReport walk = path_.AdvanceTo(input, std::numeric_limits<double>::infinity());
    if (!walk.ok()) throw Stop{"the mechanism cannot move on " + Where(m_, t, input) + ": " + walk.message};
    const Eigen::MatrixXd& series = path_.Series(2);
    const PoseMotion pose(solver_.system(), series, loads_.metres_per_unit);
    MotionState state;
    state.input = input;
    state.speed = speed;
    state.time = t;
    AppliedLoads applied;
    if (const Outcome evaluated = model_.Evaluate(pose, state, &applied); !evaluated)
      throw Stop{evaluated.error() + " " + Where(m_, t, input)};
    Point p;
    p.drive = DriveTorque(pose, state);
    const ReducedInertia inertia = ReduceInertia(pose, loads_.masses);
    largest_inertia_ = std::max(largest_inertia_, inertia.value);
    if (!(inertia.value > kVanishingInertia * largest_inertia_))
      throw Stop{"the reduced moment of inertia vanishes " + Where(m_, t, input) + ": no mass moves with the input there"};
    // J phi'' + 1/2 J' phi'^2 = M in the SI input (rad, or metres of slide)
    const double per_input = pose.metres_per_input();
    const double speed_si = speed * per_input;
    const double moment = p.drive - VirtualWorkDrive(applied);
    p.acceleration = (moment - 0.5 * inertia.derivative * speed_si * speed_si) / inertia.value / per_input;
    p.kinetic = 0.5 * inertia.value * speed_si * speed_si;
    p.potential = model_.PotentialEnergy(pose);
    // an overflow (a huge torque, speed or mass) ends the motion there, named, never a row
    for (const auto& [name, value] : {std::pair<const char*, double>{"the drive torque", p.drive},
                                      {"the acceleration", p.acceleration},
                                      {"the kinetic energy", p.kinetic},
                                      {"the potential energy", p.potential}}) {
      if (!std::isfinite(value)) throw Stop{std::string(name) + " is not a finite number (it overflows a double) " + Where(m_, t, input)};
    }
    ++evaluations_;
    return p;
  }

  void operator()(const State& x, State& dxdt, double t) {
    dxdt[0] = x[1];
    dxdt[1] = Evaluate(x, t).acceleration;
  }

  long evaluations() const { return evaluations_; }

  // The outputs at the pose of the last Evaluate.
  void Outputs(std::vector<double>* out) {
    out->resize(solver_.OutputWidth(0));
    path_.OutputDerivatives(0, out->data());
  }

  void SetLargestInertia(double value) { largest_inertia_ = value; }

 private:
  double DriveTorque(const PoseMotion& pose, const MotionState& state) const {
    switch (drive_.kind) {
      case DriveLaw::Kind::kNone: return 0.0;
      case DriveLaw::Kind::kFormula: {
        const std::vector<double> variables = model_.Variables(pose, state);
        const double value = formula_->Evaluate(variables.data());
        if (!std::isfinite(value))
          throw Stop{"the drive torque formula '" + drive_.formula + "' has no finite value " + Where(m_, state.time, state.input)};
        return value;
      }
      case DriveLaw::Kind::kMotor: {
        const std::vector<double>& n = drive_.speeds;
        if (state.speed < n.front() || state.speed > n.back())
          throw Stop{"the drive speed leaves the motor curve " + Where(m_, state.time, state.input)};
        size_t k = 1;
        while (k + 1 < n.size() && state.speed > n[k]) ++k;
        const double f = (state.speed - n[k - 1]) / (n[k] - n[k - 1]);
        // weighted, not a + f (b - a): the difference of two finite torques may overflow
        return (1.0 - f) * drive_.torques[k - 1] + f * drive_.torques[k];
      }
    }
    return 0.0;
  }

  const Mechanism& m_;
  const Loads& loads_;
  const DriveLaw& drive_;
  const LoadModel& model_;
  const CompiledFormula* formula_;
  PositionSolver& solver_;
  Continuation& path_;
  double largest_inertia_ = 0.0;
  double walked_ = 0.0;  // input walked by all evaluations so far, there and back [rad or length unit]
  long evaluations_ = 0;
};

Outcome CheckDriveLaw(const DriveLaw& drive) {
  if (drive.kind != DriveLaw::Kind::kMotor) return Done();
  if (drive.speeds.size() < 2 || drive.speeds.size() != drive.torques.size())
    return Outcome::Error("a motor curve needs at least two points (speed, torque)");
  for (size_t k = 0; k < drive.speeds.size(); ++k) {
    if (!std::isfinite(drive.speeds[k]) || !std::isfinite(drive.torques[k]) || (k > 0 && !(drive.speeds[k] > drive.speeds[k - 1] && std::isfinite(drive.speeds[k] - drive.speeds[k - 1]))))
      return Outcome::Error("the motor curve's speeds must be finite and strictly ascending, its torques finite");
  }
  return Done();
}

// Why a run cannot start, and which part of the input is at fault.
struct SimulationRefusal {
  std::string message;
  SimulationResult::BadPart bad = SimulationResult::BadPart::kNone;
};

// Checks the options, the loads and the drive law, prepares the load model and compiles the
// drive's torque formula; the refusal when one of them is bad.
std::optional<SimulationRefusal> PrepareSimulation(const Mechanism& m, const Loads& loads, const DriveLaw& drive,
                                                   const SimulationOptions& options, LoadModel* model, CompiledFormula* formula) {
  using BadPart = SimulationResult::BadPart;
  std::string why;
  if (!options.IsValid(&why)) return SimulationRefusal{why, BadPart::kOptions};
  if (const Outcome prepared = model->Prepare(m, loads); !prepared) return SimulationRefusal{prepared.error(), BadPart::kLoads};
  if (const Outcome checked = CheckDriveLaw(drive); !checked) return SimulationRefusal{checked.error(), BadPart::kDrive};
  if (drive.kind == DriveLaw::Kind::kFormula) {
    Expected<CompiledFormula> compiled = CompiledFormula::Compile(drive.formula, loads.parameters, LoadVariables(m));
    if (!compiled) return SimulationRefusal{compiled.error(), BadPart::kDrive};
    *formula = std::move(*compiled);
  }
  if (!loads.HasMass())
    return SimulationRefusal{"no link has a mass or a moment of inertia: the motion is not determined", BadPart::kLoads};
  return std::nullopt;
}

// Appends the table row at (t, state): what the right-hand side computes there, and the outputs.
void AppendSimulationRow(Dynamics& dynamics, double t, const State& state, std::vector<SimulationRow>* rows) {
  const Dynamics::Point p = dynamics.Evaluate(state, t);
  SimulationRow row;
  row.time = t;
  row.input = state[0];
  row.speed = state[1];
  row.acceleration = p.acceleration;
  row.drive = p.drive;
  row.kinetic_energy = p.kinetic;
  row.potential_energy = p.potential;
  dynamics.Outputs(&row.outputs);
  rows->push_back(std::move(row));
}

// How a run ended.
struct MotionEnd {
  AnalysisStatus status = AnalysisStatus::kComplete;
  std::string message;
};

std::string CollapsedStepMessage(const Mechanism& m, double t, double input, double dt) {
  char size[32];
  std::snprintf(size, sizeof size, "%.3g", dt);
  return std::string("the step size collapsed to ") + size + " s " + Where(m, t, input) +
         ": the equation is stiff (a damping or stiffness far too large for the inertia) or the motion explodes";
}

// Integrates the equation of motion from x at t_start (whose row is written) to t_end with the
// dense-output Dormand-Prince stepper, appending a row at each output time; counts the steps.
MotionEnd IntegrateMotion(const Mechanism& m, const SimulationOptions& options, Dynamics& dynamics, State x,
                          SimulationResult* result) {
  const double span = options.t_end - options.t_start;
  // rows every output_step from the start, the last one at t_end whatever the step: at least one
  // row after the start (an output step longer than the run, --dt 1e308, gave only the t_start row)
  const long outputs = std::max(1L, static_cast<long>(std::ceil(span / options.output_step - 1e-9)));
  auto output_time = [&](long k) { return k == outputs ? options.t_end : options.t_start + k * options.output_step; };
  // the integrator's longest step: an output step, never more than the run
  const double longest_step = std::min(options.output_step, span);
  auto stepper =
      odeint::make_dense_output(options.absolute_tolerance, options.relative_tolerance, longest_step, odeint::runge_kutta_dopri5<State>());
  double t = options.t_start;
  double dt = longest_step * 1e-3;  // the controller grows it from here
  stepper.initialize(x, t, dt);
  long next = 1;
  int tiny_steps = 0;  // accepted steps in a row shorter than kCollapsedStep of the run
  std::string last_failure;
  while (next <= outputs) {
    if (result->steps >= options.max_steps)
      return {AnalysisStatus::kPartial,
              "the integrator needed more than " + std::to_string(options.max_steps) + " steps " + Where(m, t, x[0])};
    try {
      stepper.do_step(std::ref(dynamics));
    } catch (const Stop& s) {
      last_failure = s.message;
    } catch (const odeint::step_adjustment_error& e) {
      last_failure = std::string("the step size control failed ") + Where(m, t, x[0]);
    }
    if (!last_failure.empty()) {
      // a trial stage may lie beyond where the motion goes (past a dead centre it never reaches):
      // start again from the last accepted state with a shorter step; a failure that persists at
      // the shortest step is where the motion really ends
      dt = std::min(dt, stepper.current_time_step()) / 8.0;
      if (dt < kSmallestRetryStep * longest_step) return {AnalysisStatus::kPartial, last_failure};
      stepper.initialize(x, t, dt);
      last_failure.clear();
      continue;
    }
    ++result->steps;
    x = stepper.current_state();
    t = stepper.current_time();
    dt = stepper.current_time_step();
    tiny_steps = dt < kCollapsedStep * span ? tiny_steps + 1 : 0;
    // the rows up to here are kept: the motion is known that far
    if (tiny_steps >= kCollapsedSteps && t < options.t_end) return {AnalysisStatus::kPartial, CollapsedStepMessage(m, t, x[0], dt)};
    try {
      while (next <= outputs && output_time(next) <= t) {
        State at;
        stepper.calc_state(output_time(next), at);
        AppendSimulationRow(dynamics, output_time(next), at, &result->rows);
        ++next;
      }
    } catch (const Stop& s) {
      return {AnalysisStatus::kPartial, s.message};
    }
  }
  return {AnalysisStatus::kComplete, ""};
}

}  // namespace

bool SimulationOptions::IsValid(std::string* why) const {
  auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(std::isfinite(t_start) && std::isfinite(t_end) && t_end > t_start)) return fail("the end time must come after the start time");
  if (!std::isfinite(initial_input) || !std::isfinite(initial_speed)) return fail("the initial input and speed must be finite");
  if (!(std::isfinite(output_step) && output_step > 0.0)) return fail("the output step must be a positive number of seconds");
  if ((t_end - t_start) / output_step + 1 > kMaxSimulationRows) {
    if (why) {
      char text[160];
      std::snprintf(text, sizeof text, "the run asks for %.3g output rows, more than the limit of %ld (kMaxSimulationRows): a longer step",
                    (t_end - t_start) / output_step + 1, kMaxSimulationRows);
      *why = text;
    }
    return false;
  }
  if (!(relative_tolerance > 0.0 && absolute_tolerance > 0.0 && relative_tolerance < 1.0))
    return fail("the tolerances must be positive (and the relative one below 1)");
  if (max_steps <= 0) return fail("the step budget must be positive");
  return continuation.IsValid(why);
}

std::string SimulationResult::Brief() const {
  std::string brief = std::string(ToString(status)) + ": " + std::to_string(rows.size()) + " rows, " + std::to_string(steps) +
                      " steps, " + std::to_string(evaluations) + " solved poses";
  if (!rows.empty()) brief += ", t = " + std::to_string(rows.back().time) + " s";
  return brief;
}

SimulationResult Simulate(const Mechanism& m, const Loads& loads, const DriveLaw& drive, const SimulationOptions& options) {
  SimulationResult result;
  auto fail = [&](std::string message, SimulationResult::BadPart bad) {
    result.status = AnalysisStatus::kFailed;
    result.message = std::move(message);
    result.bad_input = bad != SimulationResult::BadPart::kNone;
    result.bad_part = bad;
    return result;
  };
  LoadModel model;
  CompiledFormula formula;
  if (const std::optional<SimulationRefusal> refused = PrepareSimulation(m, loads, drive, options, &model, &formula))
    return fail(refused->message, refused->bad);

  PositionSolver solver(m);
  const Assembly assembly = AssembleRegular(m, solver, options.continuation);
  if (!assembly.ok()) return fail(assembly.error, SimulationResult::BadPart::kNone);
  Continuation path(solver, options.continuation);
  path.Start(assembly.input, assembly.q);
  if (const WalkReport to_start = path.AdvanceTo(options.initial_input, std::numeric_limits<double>::infinity()); !to_start.ok())
    return fail("the initial input cannot be reached on the assembly's branch: " + to_start.message, SimulationResult::BadPart::kNone);

  Dynamics dynamics(m, loads, drive, model, &formula, solver, path);
  const State x = {options.initial_input, options.initial_speed};
  MotionEnd end;
  bool started = true;
  try {
    AppendSimulationRow(dynamics, options.t_start, x, &result.rows);
  } catch (const Stop& s) {
    end = {AnalysisStatus::kPartial, s.message};
    started = false;
  }
  if (started) end = IntegrateMotion(m, options, dynamics, x, &result);
  result.status = end.status;
  result.message = std::move(end.message);
  result.evaluations = dynamics.evaluations();
  result.singular_points = path.singular_points();
  return result;
}

}  // namespace koppel

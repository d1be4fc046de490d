// The motion of a one-degree-of-freedom mechanism under its drive torque and loads: the equation
// of motion of the drive (Lagrange, reduced to the input; inertia.hpp)
//   J_red(phi) phi'' + 1/2 dJ_red/dphi phi'^2 = M_drive(phi, phi', t) + M_loads(phi, phi', t),
// M_loads = sum of the loads times their transfer functions (gravity, forces, torques, springs,
// dampers), integrated by Boost.Odeint's Dormand–Prince 5(4) with error control and dense output.
// The positions come from the solver at every evaluation: a continuation walk (continuation.hpp)
// follows the input, so J_red and the loads are exact at each stage, never interpolated.
//
// The input is in radians (R drive) or the length unit (P drive), speeds per second, torques in
// N m (forces in N for a P drive), SI otherwise (loads.hpp).
// The run stops, keeping the rows computed so far, where the motion cannot go on: the drive
// reaches a limit point (dead centre) of the mechanism, J_red vanishes (no mass moves with the
// input), a formula has no finite value, or the speed leaves the motor curve.
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/core/loads.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/continuation.hpp"

#include <string>
#include <vector>

namespace koppel {

// The torque (force for a P drive) the drive applies to its joint's link_b.
struct DriveLaw {
  enum class Kind {
    kNone,     // no drive torque: the mechanism moves under its loads alone
    kFormula,  // a formula of the load variables (LoadVariables) and parameters [N m]
    kMotor,    // a motor characteristic: torque over speed, linear between the points
  };
  Kind kind = Kind::kNone;
  std::string formula;
  std::vector<double> speeds;   // kMotor: strictly ascending [rad/s or length unit/s]
  std::vector<double> torques;  // kMotor: one per speed [N m or N]
};

// Turns (drive lengths of a P drive) the position solver may walk the input over in one
// simulation, every evaluation's move counted there and back: about 1 ms a turn, so 20 000 is
// under half a minute, some 10 000 turns of travel (3 000 rpm for 3 min). A torque exp(1000 t)
// walked 36 000 turns in 0.023 s of simulated time, minutes of work.
inline constexpr double kMaxSimulationWalk = 20'000;

struct SimulationOptions {
  double t_start = 0.0;        // [s]
  double t_end = 1.0;          // [s] > t_start
  double initial_input = 0.0;  // [rad or length unit]
  double initial_speed = 0.0;  // [rad/s or length unit/s]
  double output_step = 0.01;   // [s] > 0: table rows at t_start, t_start + output_step, ..., t_end
  // Error control per step of the integrator: |error| <= absolute + relative |state| for the input
  // and its speed (in their units). The defaults keep the energy of a conservative system to
  // about 1e-9 of its size over some periods.
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 1e-10;
  long max_steps = 5'000'000;  // integrator steps: the run is refused beyond, never endless
  ContinuationOptions continuation;

  bool IsValid(std::string* why) const;
};

struct SimulationRow {
  double time = 0.0;          // [s]
  double input = 0.0;         // [rad or length unit]
  double speed = 0.0;         // [per second]
  double acceleration = 0.0;  // [per second^2]
  double drive = 0.0;         // the drive law's torque [N m or N]
  double kinetic_energy = 0.0;    // [J]
  double potential_energy = 0.0;  // gravity and springs [J]
  std::vector<double> outputs;    // every output's value (PositionSolver::OutputDerivatives, order 0)
};

struct SimulationResult {
  // kComplete: reached t_end; kPartial: the motion cannot go on (message), rows up to there;
  // kFailed: bad input (bad_input: the loads, the drive law or the options), or no pose at the
  // initial input on the hint's branch.
  AnalysisStatus status = AnalysisStatus::kNotRun;
  bool bad_input = false;
  // Which input is bad: the loads (the mechanism file), the drive law or the options.
  enum class BadPart { kNone, kLoads, kDrive, kOptions };
  BadPart bad_part = BadPart::kNone;
  std::string message;
  std::vector<SimulationRow> rows;
  long steps = 0;       // accepted integrator steps
  long evaluations = 0;  // right-hand sides (each a solved pose)
  std::vector<SingularPoint> singular_points;  // met on the way (branch points passed)

  bool complete() const { return status == AnalysisStatus::kComplete; }
  std::string Brief() const;
};

// Precondition: CheckConsistency(mechanism) is empty.
SimulationResult Simulate(const Mechanism& mechanism, const Loads& loads, const DriveLaw& drive, const SimulationOptions& options);

}  // namespace koppel

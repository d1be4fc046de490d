// Statics and kinetostatics over a sweep of the drive: at every sample, the drive torque (force
// for a P drive) that holds the loads, every joint's reaction (multipliers.hpp), the same drive
// torque by the principle of virtual work as a check, and the reduced moment of inertia with its
// derivative (inertia.hpp).
//
// Statics: the loads alone (gravity, forces, torques, springs) at rest. Kinetostatics
// (ForcesOptions::speed set): the drive turns at that constant speed, and the inertia forces of
// the masses join the loads; dampers see the speed; the time t of the load formulas runs from 0 at
// the first sample (t = (input - from) / speed).
//
// Rows whose pose is singular (a limit point of the drive, where the torque to hold the loads is
// unbounded; a branch point, where the reactions are not determined) carry no forces: `computed`
// is false and `problem` says why; the result is then partial, never a huge number as if fine.
#pragma once

#include "koppel/analysis/status.hpp"
#include "koppel/core/loads.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/multipliers.hpp"
#include "koppel/solver/sweep.hpp"

#include <optional>
#include <string>
#include <vector>

namespace koppel {

// The drive by the multipliers and by virtual work must agree to this, relative to the size of
// the loads (sum |F| L + |M|, L the length scale; over L for a P drive): both are exact, and rows
// no closer to a singular pose than kSingularRowRcond lose at most about eps / rcond = 2e-10 of it.
inline constexpr double kVirtualWorkAgreement = 1e-7;

struct ForcesOptions {
  SweepOptions sweep;
  // Constant drive speed [rad/s for an R drive, length unit/s for a P drive]; empty: statics.
  std::optional<double> speed;

  bool IsValid(std::string* why) const;  // the sweep's options, and a finite speed
};

struct ForcesRow {
  double input = 0.0;        // rad or length unit
  Eigen::VectorXd q;         // the pose (the solver's coordinates, constraints.hpp)
  bool singular = false;     // the sweep flagged the pose singular
  bool computed = false;     // drive and reactions below are valid
  bool virtual_work = false;  // drive_virtual_work and the reduced inertia are valid
  std::string problem;       // why not computed
  double drive = 0.0;                // from the multipliers [N m or N]
  double drive_virtual_work = 0.0;   // the same by virtual work
  double load_scale = 0.0;  // the loads' size, sum |F| L + |M| (over L for a P drive): what the two drives are compared to
  double reduced_inertia = 0.0;      // J_red [kg m^2 or kg]
  double reduced_inertia_derivative = 0.0;  // dJ_red/dinput [kg m^2/rad or kg/m]
  std::vector<JointReaction> joints;         // in joint order (empty when not computed)
};

struct ForcesResult {
  // kComplete: every requested sample has its forces; kPartial: some samples are missing (sweep
  // gaps) or have none (see rows); kFailed: the message says why — bad input (bad_input: the loads
  // do not fit the mechanism, a formula does not compile, invalid options), no assembly, or the
  // drive by the multipliers and by virtual work disagree (a bug; the rows are kept).
  AnalysisStatus status = AnalysisStatus::kNotRun;
  bool bad_input = false;
  std::string message;
  SweepEvents sweep;          // of the sweep underneath
  bool kinetostatic = false;  // a speed was given
  // The mechanism has redundant joints: the drive torque follows by virtual work, the reactions are
  // statically indeterminate (rows have computed = false and drive_virtual_work set).
  bool indeterminate = false;
  std::vector<ForcesRow> rows;  // the sweep's computed samples, in sweep order
  double worst_disagreement = 0.0;  // max |drive - drive_virtual_work| / load_scale over the rows

  bool complete() const { return status == AnalysisStatus::kComplete; }
  std::string Brief() const;
};

// Precondition: CheckConsistency(mechanism) is empty.
ForcesResult AnalyseForces(const Mechanism& mechanism, const Loads& loads, const ForcesOptions& options);

}  // namespace koppel

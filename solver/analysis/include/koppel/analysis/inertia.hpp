// The inertia of a mechanism seen from its drive (as in VDI guideline 2149 on the dynamics of rigid-body mechanisms): the reduced
// (equivalent) moment of inertia J_red = sum m |v_S / input'|^2 + J_S (theta' / input')^2 over
// the moving links, S the centre of gravity, and dJ_red/dinput, both from the exact first- and
// second-order transfer functions; and the inertia (d'Alembert) forces of a state of motion.
// The kinetic energy is J_red input'^2 / 2, and the equation of motion of a one-DOF mechanism
// J_red input'' + 1/2 dJ_red/dinput input'^2 = M follows from it.
// Units: kg m^2 and kg m^2/rad for an R drive; kg (reduced mass) and kg/m for a P drive.
#pragma once

#include "koppel/analysis/loads_at_pose.hpp"

namespace koppel {

struct ReducedInertia {
  double value = 0.0;       // J_red
  double derivative = 0.0;  // dJ_red / dinput (per radian, or per metre of slide)
};

ReducedInertia ReduceInertia(const PoseMotion& pose, const std::vector<LinkMass>& masses);

// -m a_S at each centre of gravity and -J_S theta'' on each link, with the accelerations of
// `state` (a = p'' speed^2 + p' acceleration, SI speeds: the state's converted by the input's unit).
AppliedLoads InertiaLoads(const PoseMotion& pose, const std::vector<LinkMass>& masses, const MotionState& state);

// The kinetic energy [J] of the state: J_red speed^2 / 2 (speed converted to rad/s or m/s).
double KineticEnergy(const PoseMotion& pose, const std::vector<LinkMass>& masses, double speed);

}  // namespace koppel

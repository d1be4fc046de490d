// Joint reactions (Gelenkkräfte) and the drive's torque as the Lagrange multipliers of the
// position equations (constraints.hpp): at a pose, the applied and inertia forces Q on the
// coordinates and the joints' forces balance, Q + J^T lambda = 0, so lambda = -J^-T Q with the
// factorisation Newton left behind. Each joint's rows turn into the force system it carries:
//   R joint rows p_a - p_b: the force link_a exerts on link_b is -lambda, at the joint point;
//   P joint rows n_a . (p_b - p_a) and L (theta_b - theta_a - angle): the guide (link_a) pushes the
//     block (link_b) with lambda_0 along the slide's normal n_a, acting at the block's point p_b,
//     and turns it with the moment lambda_1 L (the moment across the slide);
//   drive row L (theta_b - theta_a - ...): the drive torque lambda L on link_b (by link_a); for a
//     P drive, s - ...: the drive force lambda along the axis on the block.
// Units: Q in N on the x, y coordinates and N m on theta, with the geometry's lengths taken as
// `metres_per_unit` metres each; forces come out in N, torques and moments in N m.
#pragma once

#include "koppel/solver/position.hpp"

#include <Eigen/Core>

#include <vector>

namespace koppel {

struct JointReaction {
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  // link_a on link_b, global frame [N]
  double normal = 0.0;  // P joints: the force along the slide normal n_a (axis turned +90 deg) [N]
  double moment = 0.0;  // P joints: link_a on link_b, about the block's point p_b [N m]
};

struct Reactions {
  // What the drive exerts on its joint's link_b (by link_a): a torque [N m] for an R drive, a
  // force along the slide axis [N] for a P drive. The work it does per unit input is this number.
  double drive = 0.0;
  std::vector<JointReaction> joints;  // in joint order
};

// The reactions at the solver's last converged pose `q` under the generalised forces `q_force`
// (NumCoordinates() entries, SI as above). False when the solver holds no factorisation or the
// mechanism has redundant joints (then the reactions are statically indeterminate).
bool JointReactions(const PositionSolver& solver, const Eigen::VectorXd& q, const Eigen::VectorXd& q_force,
                    double metres_per_unit, Reactions* reactions);

}  // namespace koppel

#include "koppel/solver/multipliers.hpp"

#include <cmath>

namespace koppel {

bool PositionSolver::SolveWithJacobianTranspose(const Eigen::VectorXd& rhs, Eigen::VectorXd& x) const {
  Resolve();
  if (!factorized_ || !square_) return false;
  if (use_blocks_) {
    x = rhs;
    blocks_.SolveTransposed(x.data());
  } else {
    x = lu_.transpose().solve(rhs);
  }
  return x.allFinite();
}

bool JointReactions(const PositionSolver& solver, const Eigen::VectorXd& q, const Eigen::VectorXd& q_force,
                    double metres_per_unit, Reactions* reactions) {
  const ConstraintSystem& system = solver.system();
  const Mechanism& m = system.mechanism();
  // In SI coordinates (x, y in metres) the residuals are metres_per_unit times the file's and
  // J_SI = metres_per_unit J D^-1 with D = diag(s, s, 1) per link, so J_SI^T lambda = -Q is
  // J^T lambda = -D Q / metres_per_unit: the moments are divided by the unit, the forces kept.
  Eigen::VectorXd rhs = -q_force;
  for (int i = 2; i < rhs.size(); i += 3) rhs(i) /= metres_per_unit;
  Eigen::VectorXd lambda;
  if (!solver.SolveWithJacobianTranspose(rhs, lambda)) return false;
  const double rotation_scale = system.length_scale() * metres_per_unit;  // rotation rows carry L
  reactions->joints.assign(m.joints.size(), JointReaction{});
  for (int k = 0; k < static_cast<int>(m.joints.size()); ++k) {
    const Joint& j = m.joints[k];
    const int row = system.FirstRowOf(k);
    JointReaction& r = reactions->joints[k];
    if (j.type == JointType::kRevolute) {
      r.force = -Eigen::Vector2d(lambda(row), lambda(row + 1));
      continue;
    }
    const double theta_a = system.LinkAngle(j.link_a, q.data());
    const Eigen::Vector2d axis(std::cos(theta_a) * j.axis.x() - std::sin(theta_a) * j.axis.y(),
                               std::sin(theta_a) * j.axis.x() + std::cos(theta_a) * j.axis.y());
    const Eigen::Vector2d normal(-axis.y(), axis.x());
    r.normal = lambda(row);
    r.force = r.normal * normal;
    r.moment = lambda(row + 1) * rotation_scale;
  }
  const double drive = lambda(system.DriveRow());
  reactions->drive = m.InputIsAngle() ? drive * rotation_scale : drive;
  return true;
}

}  // namespace koppel

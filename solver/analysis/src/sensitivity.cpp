#include "koppel/analysis/sensitivity.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/taylor.hpp"

#include <cmath>

namespace koppel {
bool Perturb(const MechanismBuilder& builder, const std::vector<double>& p, Perturbations* out, double relative_step) {
  const size_t n = p.size();
  out->plus.resize(n);
  out->minus.resize(n);
  out->step.resize(n);
  for (size_t j = 0; j < n; ++j) {
    out->step[j] = relative_step * std::max(1.0, std::abs(p[j]));
    std::vector<double> pp = p, pm = p;
    pp[j] += out->step[j];
    pm[j] -= out->step[j];
    Expected<Mechanism> plus = builder(pp), minus = builder(pm);
    if (!plus || !minus) return false;
    out->plus[j] = std::move(*plus);
    out->minus[j] = std::move(*minus);
  }
  return true;
}

Eigen::VectorXd PoseSensitivity(const PositionSolver& solver, const Eigen::VectorXd& q, double input, const Perturbations& perturbed, int j) {
  Eigen::VectorXd r_plus(solver.system().NumEquations()), r_minus(solver.system().NumEquations());
  ConstraintSystem(perturbed.plus[j]).Residuals(q.data(), input, r_plus.data());
  ConstraintSystem(perturbed.minus[j]).Residuals(q.data(), input, r_minus.data());
  return -solver.SolveWithJacobian((r_plus - r_minus) / (2 * perturbed.step[j]));
}

namespace {

// q + t dq as first-order series in t
std::vector<Taylor<1>> Line(const Eigen::VectorXd& q, const Eigen::VectorXd& dq) {
  std::vector<Taylor<1>> line(q.size());
  for (int i = 0; i < q.size(); ++i) {
    line[i].c[0] = q[i];
    line[i].c[1] = dq[i];
  }
  return line;
}

template <class T>
T OutputOnLinksAt(const ConstraintSystem& system, int output, int component, std::vector<T> q) {
  const Mechanism& m = system.mechanism();
  const Output& o = m.outputs[output];
  const TransmissionGeometry& g = system.transmission(output);
  // a slide's direction is the frame's, the coupler line the coupler's own: nothing to move
  if (o.kind != OutputKind::kTransmissionAngle || g.slide_joint >= 0) return system.Output(output, component, q.data());
  const int coupler = g.coupler_to.link, i = system.CoordinateOf(coupler);
  if (i < 0) return system.Output(output, component, q.data());  // no coupler to move (it is the frame)
  T on_coupler[2], on_output_link[2];
  system.GlobalPoint(g.coupler_to, q.data(), on_coupler);
  system.GlobalPoint(JointPointOn(m.joints[o.joint], g.pivot.link), q.data(), on_output_link);
  // a translation of the coupler: its direction stays, its joint point meets the output link's
  q[i] += on_output_link[0] - on_coupler[0];
  q[i + 1] += on_output_link[1] - on_coupler[1];
  return system.Output(output, component, q.data());
}

}  // namespace

double OutputDirectional(const ConstraintSystem& system, int output, int component, const Eigen::VectorXd& q, const Eigen::VectorXd& dq) {
  return system.Output(output, component, Line(q, dq).data()).c[1];
}

void DisplacePin(Mechanism* mechanism, int joint, const Eigen::Vector2d& offset) {
  Joint& j = mechanism->joints[joint];
  Link& link = mechanism->links[j.link_b];
  NamedPoint pin = link.points[j.point_b];
  pin.name += "~play";
  pin.local += offset;
  link.points.push_back(pin);
  j.point_b = static_cast<int>(link.points.size()) - 1;
}

double OutputOnLinks(const ConstraintSystem& system, int output, int component, const Eigen::VectorXd& q) {
  return OutputOnLinksAt(system, output, component, std::vector<double>(q.data(), q.data() + q.size()));
}

void OutputSensitivity(const PositionSolver& solver, const Eigen::VectorXd& q, double input, const Perturbations& perturbed, int output,
                       int first_component, int comps, bool angle, Eigen::MatrixXd* d) {
  const int n = static_cast<int>(perturbed.step.size());
  d->resize(comps, n);
  for (int j = 0; j < n; ++j) {
    const double h = perturbed.step[j];
    const Eigen::VectorXd dq = PoseSensitivity(solver, q, input, perturbed, j);
    const ConstraintSystem sp(perturbed.plus[j]), sm(perturbed.minus[j]);
    for (int c = 0; c < comps; ++c) {
      // the output's own dependence on p at the fixed pose, plus its change along dq/dp
      const double change = sp.Output(output, first_component + c, q.data()) - sm.Output(output, first_component + c, q.data());
      (*d)(c, j) = (angle ? WrapToHalfTurn(change) : change) / (2 * h) + OutputDirectional(solver.system(), output, first_component + c, q, dq);
    }
  }
}

Eigen::Vector2d ClearanceGradient(const PositionSolver& solver, const Eigen::VectorXd& q, int joint, int output, int component) {
  const ConstraintSystem& system = solver.system();
  Eigen::Vector2d gradient;
  for (int axis = 0; axis < 2; ++axis) {
    // R rows are p_a - p_b; moving p_b by delta (DisplacePin) gives dF/d delta = -I in the joint's two rows
    Eigen::VectorXd dF = Eigen::VectorXd::Zero(system.NumEquations());
    dF[system.FirstRowOf(joint) + axis] = -1.0;
    const Eigen::VectorXd dq = -solver.SolveWithJacobian(dF);
    gradient[axis] = OutputOnLinksAt(system, output, component, Line(q, dq)).c[1];
  }
  return gradient;
}

}  // namespace koppel

#include "fit_model.hpp"

#include "koppel/analysis/stationary.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/solver/sweep.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace koppel {
FitUnit TargetUnit(const Mechanism& m, const FitTarget& t) {
  if (t.point || t.straight) return FitUnit::kLength;
  if (t.deadcentre) return m.InputIsAngle() ? FitUnit::kAngle : FitUnit::kLength;
  return m.OutputIsAngle(t.output) ? FitUnit::kAngle : FitUnit::kLength;
}

double WrappedAngle(double difference) {
  const double r = std::remainder(difference, 2 * kPi);  // in [-pi, pi]
  return r <= -kPi ? r + 2 * kPi : r;
}

bool TargetModel::Evaluate(const double* unknowns, int n_params, double* residuals, double* jacobian) const {
  std::vector<double> p(unknowns, unknowns + n_params);
  const Expected<Mechanism> built = builder_(p);
  if (!built) return false;
  const Mechanism& m = *built;
  PositionSolver solver(m);
  Eigen::VectorXd q(solver.NumCoordinates());
  if (!solver.Assemble(q).ok()) return false;
  const int n_unknowns = n_params + FreeInputs();
  // the perturbed mechanisms, built once and shared by every target's sensitivities
  Perturbations perturbed;
  if (jacobian && !Perturb(builder_, p, &perturbed)) return false;
  const Perturbations* sensitivities = jacobian ? &perturbed : nullptr;
  int row = 0, free_index = 0;
  for (const FitTarget& t : targets_) {
    if (t.deadcentre) {
      if (!DeadCentre(m, solver, q, sensitivities, t, residuals + row, jacobian ? jacobian + row * n_unknowns : nullptr, n_unknowns)) return false;
      ++row;
      continue;
    }
    if (t.straight) {
      if (!Straight(m, solver, q, sensitivities, t, residuals + row, jacobian ? jacobian + row * n_unknowns : nullptr, n_unknowns)) return false;
      row += t.samples;
      continue;
    }
    const double input = t.input_free ? unknowns[n_params + free_index] : t.input;
    const int free_column = t.input_free ? n_params + free_index : -1;
    if (!OutputAt(m, solver, q, sensitivities, t, input, free_column, residuals + row, jacobian ? jacobian + row * n_unknowns : nullptr,
                  n_params, n_unknowns))
      return false;
    const int comps = t.point ? 2 : 1;
    row += comps;
    if (t.input_free) ++free_index;
  }
  return true;
}

bool TargetModel::OutputAt(const Mechanism& m, PositionSolver& solver, const Eigen::VectorXd& q_hint, const Perturbations* perturbed,
                           const FitTarget& t, double input, int free_column, double* residuals, double* jacobian, int n_params,
                           int n_unknowns) const {
  Continuation path(solver);
  if (!path.Start(m.hint.input, q_hint).ok() || !path.AdvanceTo(input, 0.05).ok()) return false;
  const Eigen::VectorXd& qt = path.q();
  const Eigen::MatrixXd& series = path.Series(1);  // factorises J at qt, gives dq/dinput
  const int comps = t.point ? 2 : 1;
  // an angle is compared by its wrapped difference, whatever range the output is reported in
  const bool angle = TargetUnit(m, t) == FitUnit::kAngle;
  auto difference = [angle](double a, double b) { return angle ? WrappedAngle(a - b) : a - b; };
  for (int c = 0; c < comps; ++c) {
    const int comp = t.point ? c : t.component;
    const double y = solver.system().Output(t.output, comp, qt.data());
    const double goal = t.point ? t.position[c] : t.value;
    residuals[c] = t.weight * difference(y, goal);
  }
  if (!jacobian) return true;
  for (int c = 0; c < comps; ++c) std::fill(jacobian + c * n_unknowns, jacobian + (c + 1) * n_unknowns, 0.0);
  // parameters: IFT
  Eigen::MatrixXd d;
  OutputSensitivity(solver, qt, input, *perturbed, t.output, t.point ? 0 : t.component, comps, angle, &d);
  for (int c = 0; c < comps; ++c) {
    for (int j = 0; j < n_params; ++j) jacobian[c * n_unknowns + j] = t.weight * d(c, j);
  }
  if (free_column >= 0) {
    // dy/dinput: the exact first-order transfer function, through the output's gradient
    const ConstraintSystem& system = solver.system();
    const double h = 1e-7;
    const Eigen::VectorXd q_plus = qt + h * series.col(1), q_minus = qt - h * series.col(1);
    for (int c = 0; c < comps; ++c) {
      const int comp = t.point ? c : t.component;
      jacobian[c * n_unknowns + free_column] =
          t.weight * difference(system.Output(t.output, comp, q_plus.data()), system.Output(t.output, comp, q_minus.data())) / (2 * h);
    }
  }
  return true;
}

bool TargetModel::Straight(const Mechanism& m, PositionSolver& solver, const Eigen::VectorXd& q_hint, const Perturbations* perturbed,
                           const FitTarget& t, double* residuals, double* jacobian, int n_unknowns) const {
  const int n = t.samples;
  std::vector<Eigen::Vector2d> points(n);
  std::vector<Eigen::MatrixXd> sensitivity(n);
  Continuation path(solver);
  if (!path.Start(m.hint.input, q_hint).ok()) return false;
  for (int i = 0; i < n; ++i) {
    const double input = t.input + (t.to - t.input) * i / (n - 1);
    if (!path.AdvanceTo(input, 0.05).ok()) return false;
    const Eigen::VectorXd& qi = path.q();
    points[i] = {solver.system().Output(t.output, 0, qi.data()), solver.system().Output(t.output, 1, qi.data())};
      if (jacobian) OutputSensitivity(solver, qi, input, *perturbed, t.output, 0, 2, false, &sensitivity[i]);
  }
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& x : points) centre += x / n;
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector2d& x : points) scatter += (x - centre) * (x - centre).transpose();
  // the line's normal: the eigenvector of the smallest eigenvalue of the scatter matrix
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(scatter);
  const Eigen::Vector2d normal = eigen.eigenvectors().col(0), along = eigen.eigenvectors().col(1);
  for (int i = 0; i < n; ++i) residuals[i] = t.weight * normal.dot(points[i] - centre);
  if (!jacobian) return true;
  // the line moves with the points: its centroid by the mean sensitivity, its angle by
  // d theta = sum(a_i n.e_i + b_i u.e_i) / sum(a_i^2 - b_i^2) (first-order change of the
  // total-least-squares direction), so d b_i = n.e_i - a_i d theta with e_i = dK_i - mean dK
  double spread = 0;
  for (const Eigen::Vector2d& x : points) spread += std::pow(along.dot(x - centre), 2) - std::pow(normal.dot(x - centre), 2);
  const int n_params = jacobian ? static_cast<int>(perturbed->step.size()) : 0;
  for (int j = 0; j < n_params; ++j) {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (int i = 0; i < n; ++i) mean += sensitivity[i].col(j) / n;
    double turn = 0;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d e = sensitivity[i].col(j) - mean, x = points[i] - centre;
      turn += (along.dot(x) * normal.dot(e) + normal.dot(x) * along.dot(e)) / spread;
    }
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d e = sensitivity[i].col(j) - mean;
      jacobian[i * n_unknowns + j] = t.weight * (normal.dot(e) - along.dot(points[i] - centre) * turn);
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = n_params; j < n_unknowns; ++j) jacobian[i * n_unknowns + j] = 0.0;
  }
  return true;
}

bool TargetModel::DeadCentre(const Mechanism& m, PositionSolver& solver, const Eigen::VectorXd& q_hint, const Perturbations* perturbed,
                             const FitTarget& t, double* residual, double* jacobian_row, int n_unknowns) const {
  Continuation path(solver);
  if (!path.Start(m.hint.input, q_hint).ok() || !path.AdvanceTo(t.input, 0.05).ok()) return false;
  const StationaryPoint dc = RefineStationary(m, t.output, t.component, path.input(), path.q());
  if (!dc.ok() || dc.second == 0.0) return false;
  *residual = t.weight * (m.InputIsAngle() ? WrappedAngle(dc.input - t.input) : dc.input - t.input);
  if (!jacobian_row) return true;
  std::fill(jacobian_row, jacobian_row + n_unknowns, 0.0);
  // dq/dp at the dead centre needs the Jacobian factorised there
  Eigen::VectorXd q = dc.q;
  if (!solver.Correct(dc.input, q).ok()) return false;
  for (size_t j = 0; j < perturbed->step.size(); ++j) {
    const double h = perturbed->step[j];
    const Eigen::VectorXd dq = PoseSensitivity(solver, q, dc.input, *perturbed, static_cast<int>(j));
    // y' of each perturbed mechanism at the same input, from its predicted pose
    double slope[2];
    for (int side = 0; side < 2; ++side) {
      const Mechanism& mechanism = side == 0 ? perturbed->plus[j] : perturbed->minus[j];
      PositionSolver ps(mechanism);
      Eigen::VectorXd qs = q + (side == 0 ? h : -h) * dq;
      if (!ps.Correct(dc.input, qs).ok()) return false;
      Eigen::MatrixXd series;
      ps.Series(1, series);
      std::vector<double> d(ps.OutputWidth(1));
      ps.OutputDerivatives(series, 1, d.data());
      int column = 0;
      for (int o = 0; o < t.output; ++o) column += mechanism.outputs[o].Components() * 2;
      slope[side] = d[column + t.component * 2 + 1];
    }
    jacobian_row[j] = -t.weight * ((slope[0] - slope[1]) / (2 * h)) / dc.second;
  }
  return true;
}

int TargetModel::Residuals() const {
  int n = 0;
  for (const FitTarget& t : targets_) n += t.straight ? t.samples : t.point ? 2 : 1;
  return n;
}

int TargetModel::FreeInputs() const {
  int n = 0;
  for (const FitTarget& t : targets_) n += t.input_free ? 1 : 0;
  return n;
}

}  // namespace koppel

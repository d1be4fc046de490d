// The one translation unit of koppel that includes Ceres.
#include "koppel/synthesis/fit.hpp"

#include "koppel/solver/position.hpp"
#include "koppel/analysis/stationary.hpp"
#include "koppel/solver/sweep.hpp"

#include <ceres/ceres.h>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <iostream>
#include <random>

namespace koppel {
namespace {

// Relative step of the parameter differences: central differences of smooth residuals, error
// O(h^2) ~ 1e-12 against roundoff O(eps/h) ~ 1e-10.
constexpr double kParameterStep = 1e-6;

// Solves every target's pose for one parameter vector, following each target's input from the
// assembly hint by continuation, and gives values and IFT derivatives.
class TargetModel {
 public:
  TargetModel(const MechanismBuilder& builder, const std::vector<FitTarget>& targets) : builder_(builder), targets_(targets) {}

  // residuals: per target 2 (point) or 1; jacobian (row-major, residuals x unknowns) if non-null.
  // unknowns = parameters then one per free input.
  bool Evaluate(const double* unknowns, int n_params, double* residuals, double* jacobian) const {
    std::vector<double> p(unknowns, unknowns + n_params);
    Mechanism m;
    std::string error;
    if (!builder_(p, &m, &error)) return false;
    PositionSolver solver(m);
    Eigen::VectorXd q(solver.NumCoordinates());
    if (!solver.Assemble(q).ok()) return false;
    const int n_unknowns = n_params + FreeInputs();
    int row = 0, free_index = 0;
    for (const FitTarget& t : targets_) {
      if (t.deadcentre) {
        if (!DeadCentre(m, solver, q, p, t, residuals + row, jacobian ? jacobian + row * n_unknowns : nullptr, n_unknowns)) return false;
        ++row;
        continue;
      }
      if (t.straight) {
        if (!Straight(m, solver, q, p, t, residuals + row, jacobian ? jacobian + row * n_unknowns : nullptr, n_unknowns)) return false;
        row += t.samples;
        continue;
      }
      const double input = t.input_free ? unknowns[n_params + free_index] : t.input;
      Continuation path(solver);
      if (!path.Start(m.hint.input, q).ok() || !path.AdvanceTo(input, 0.05).ok()) return false;
      const Eigen::VectorXd& qt = path.q();
      const Eigen::MatrixXd& series = path.Series(1);  // factorises J at qt, gives dq/dinput
      const int comps = t.point ? 2 : 1;
      for (int c = 0; c < comps; ++c) {
        const int comp = t.point ? c : t.component;
        const double y = solver.system().Output(t.output, comp, qt.data());
        const double goal = t.point ? t.position[c] : t.value;
        residuals[row + c] = t.weight * (y - goal);
      }
      if (jacobian) {
        for (int c = 0; c < comps; ++c) std::fill(jacobian + (row + c) * n_unknowns, jacobian + (row + c + 1) * n_unknowns, 0.0);
        // parameters: IFT
        Eigen::MatrixXd d;
        if (!OutputSensitivity(solver, qt, input, p, t.output, t.point ? 0 : t.component, comps, &d)) return false;
        for (int c = 0; c < comps; ++c) {
          for (int j = 0; j < n_params; ++j) jacobian[(row + c) * n_unknowns + j] = t.weight * d(c, j);
        }
        const ConstraintSystem& system = solver.system();
        if (t.input_free) {
          // dy/dinput: the exact first-order transfer function, through the output's gradient
          const double h = 1e-7;
          const Eigen::VectorXd q_plus = qt + h * series.col(1), q_minus = qt - h * series.col(1);
          for (int c = 0; c < comps; ++c) {
            const int comp = t.point ? c : t.component;
            jacobian[(row + c) * n_unknowns + n_params + free_index] =
                t.weight * (system.Output(t.output, comp, q_plus.data()) - system.Output(t.output, comp, q_minus.data())) / (2 * h);
          }
        }
      }
      row += comps;
      if (t.input_free) ++free_index;
    }
    return true;
  }

  // dq/dp_j at a converged pose (the solver's factorisation is at q): -J^-1 dF/dp_j, with dF/dp_j
  // one central difference of the residuals of the rebuilt mechanisms at the fixed pose.
  bool PoseSensitivity(const PositionSolver& solver, const Eigen::VectorXd& q, double input, const std::vector<double>& p, int j,
                       Mechanism* plus, Mechanism* minus, Eigen::VectorXd* dq, double* h) const {
    *h = kParameterStep * std::max(1.0, std::abs(p[j]));
    std::vector<double> pp = p, pm = p;
    pp[j] += *h;
    pm[j] -= *h;
    std::string error;
    if (!builder_(pp, plus, &error) || !builder_(pm, minus, &error)) return false;
    Eigen::VectorXd r_plus(solver.system().NumEquations()), r_minus(solver.system().NumEquations());
    ConstraintSystem(*plus).Residuals(q.data(), input, r_plus.data());
    ConstraintSystem(*minus).Residuals(q.data(), input, r_minus.data());
    *dq = -solver.SolveWithJacobian((r_plus - r_minus) / (2 * *h));
    return true;
  }

  // d(output components)/dp at a converged pose: one directional difference of the output along
  // (dq/dp_j, e_j) per parameter. `d` is comps x parameters.
  bool OutputSensitivity(const PositionSolver& solver, const Eigen::VectorXd& q, double input, const std::vector<double>& p,
                         int output, int first_component, int comps, Eigen::MatrixXd* d) const {
    d->resize(comps, static_cast<int>(p.size()));
    for (int j = 0; j < static_cast<int>(p.size()); ++j) {
      Mechanism mp, mm;
      Eigen::VectorXd dq;
      double h = 0;
      if (!PoseSensitivity(solver, q, input, p, j, &mp, &mm, &dq, &h)) return false;
      const ConstraintSystem sp(mp), sm(mm);
      const Eigen::VectorXd q_plus = q + h * dq, q_minus = q - h * dq;
      for (int c = 0; c < comps; ++c)
        (*d)(c, j) = (sp.Output(output, first_component + c, q_plus.data()) - sm.Output(output, first_component + c, q_minus.data())) / (2 * h);
    }
    return true;
  }

  // One straight-line target: distances of the samples from their total-least-squares line.
  bool Straight(const Mechanism& m, PositionSolver& solver, const Eigen::VectorXd& q_hint, const std::vector<double>& p,
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
      if (jacobian && !OutputSensitivity(solver, qi, input, p, t.output, 0, 2, &sensitivity[i])) return false;
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
    for (int j = 0; j < static_cast<int>(p.size()); ++j) {
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
      for (int j = static_cast<int>(p.size()); j < n_unknowns; ++j) jacobian[i * n_unknowns + j] = 0.0;
    }
    return true;
  }

  // One dead-centre target: residual = (input of the dead centre next to t.input) - t.input.
  bool DeadCentre(const Mechanism& m, PositionSolver& solver, const Eigen::VectorXd& q_hint, const std::vector<double>& p,
                  const FitTarget& t, double* residual, double* jacobian_row, int n_unknowns) const {
    Continuation path(solver);
    if (!path.Start(m.hint.input, q_hint).ok() || !path.AdvanceTo(t.input, 0.05).ok()) return false;
    const StationaryPoint dc = RefineStationary(m, t.output, t.component, path.input(), path.q());
    if (!dc.found || dc.second == 0.0) return false;
    *residual = t.weight * (dc.input - t.input);
    if (!jacobian_row) return true;
    std::fill(jacobian_row, jacobian_row + n_unknowns, 0.0);
    // dq/dp at the dead centre needs the Jacobian factorised there
    Eigen::VectorXd q = dc.q;
    if (!solver.Correct(dc.input, q).ok()) return false;
    for (size_t j = 0; j < p.size(); ++j) {
      Mechanism mp, mm;
      Eigen::VectorXd dq;
      double h = 0;
      if (!PoseSensitivity(solver, q, dc.input, p, static_cast<int>(j), &mp, &mm, &dq, &h)) return false;
      // y' of each perturbed mechanism at the same input, from its predicted pose
      double slope[2];
      for (int side = 0; side < 2; ++side) {
        const Mechanism& perturbed = side == 0 ? mp : mm;
        PositionSolver ps(perturbed);
        Eigen::VectorXd qs = q + (side == 0 ? h : -h) * dq;
        if (!ps.Correct(dc.input, qs).ok()) return false;
        Eigen::MatrixXd series;
        ps.Series(1, series);
        std::vector<double> d(ps.OutputWidth(1));
        ps.OutputDerivatives(series, 1, d.data());
        int column = 0;
        for (int o = 0; o < t.output; ++o) column += perturbed.outputs[o].Components() * 2;
        slope[side] = d[column + t.component * 2 + 1];
      }
      jacobian_row[j] = -t.weight * ((slope[0] - slope[1]) / (2 * h)) / dc.second;
    }
    return true;
  }

  int Residuals() const {
    int n = 0;
    for (const FitTarget& t : targets_) n += t.straight ? t.samples : t.point ? 2 : 1;
    return n;
  }
  int FreeInputs() const {
    int n = 0;
    for (const FitTarget& t : targets_) n += t.input_free ? 1 : 0;
    return n;
  }

 private:
  const MechanismBuilder& builder_;
  const std::vector<FitTarget>& targets_;
};

class FitCost : public ceres::CostFunction {
 public:
  FitCost(const TargetModel& model, int n_params) : model_(model), n_params_(n_params) {
    set_num_residuals(model.Residuals());
    mutable_parameter_block_sizes()->push_back(n_params + model.FreeInputs());
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    return model_.Evaluate(parameters[0], n_params_, residuals, jacobians ? jacobians[0] : nullptr);
  }

 private:
  const TargetModel& model_;
  int n_params_;
};

bool AssemblesOver(const MechanismBuilder& builder, const std::vector<double>& values, const FitOptions& options) {
  if (options.require_to == options.require_from) return true;
  Mechanism m;
  std::string error;
  if (!builder(values, &m, &error)) return false;
  SweepOptions range;
  range.from = options.require_from;
  range.to = options.require_to;
  range.step = (options.require_to - options.require_from) / 360;
  range.order = 0;
  return Sweep(m, range).complete();
}

}  // namespace

FitReport Fit(const MechanismBuilder& builder, const std::vector<FitParameter>& parameters, const std::vector<FitTarget>& targets,
              const FitOptions& options) {
  FitReport best;
  const TargetModel model(builder, targets);
  const int n = static_cast<int>(parameters.size());
  std::mt19937 rng(options.seed);
  for (int start = 0; start < std::max(1, options.starts); ++start) {
    std::vector<double> x;
    for (const FitParameter& p : parameters) {
      double v = p.start;
      if (start > 0 && std::isfinite(p.lower) && std::isfinite(p.upper) && p.lower > -1e299 && p.upper < 1e299)
        v = std::uniform_real_distribution<double>(p.lower, p.upper)(rng);
      x.push_back(v);
    }
    for (const FitTarget& t : targets) {
      if (t.input_free) x.push_back(t.input);
    }
    ceres::Problem problem;
    problem.AddResidualBlock(new FitCost(model, n), nullptr, x.data());
    for (int j = 0; j < n; ++j) {
      if (parameters[j].lower > -1e299) problem.SetParameterLowerBound(x.data(), j, parameters[j].lower);
      if (parameters[j].upper < 1e299) problem.SetParameterUpperBound(x.data(), j, parameters[j].upper);
    }
    ceres::Solver::Options solver_options;
    solver_options.max_num_iterations = options.max_iterations;
    solver_options.linear_solver_type = ceres::DENSE_QR;
    solver_options.function_tolerance = 1e-15;
    solver_options.gradient_tolerance = 1e-15;
    solver_options.parameter_tolerance = 1e-14;
    solver_options.minimizer_progress_to_stdout = false;
    ceres::Solver::Summary summary;
    ceres::Solve(solver_options, &problem, &summary);
    if (!options.quiet) std::cerr << "koppel synth fit: start " << start + 1 << ": " << summary.BriefReport() << "\n";
    if (!summary.IsSolutionUsable()) continue;
    // residuals at the result
    std::vector<double> r(model.Residuals());
    if (!model.Evaluate(x.data(), n, r.data(), nullptr)) continue;
    double cost = 0;
    for (double v : r) cost += 0.5 * v * v;
    // designs that assemble over the required input range win over any that do not
    const bool assembles = AssemblesOver(builder, std::vector<double>(x.begin(), x.begin() + n), options);
    if (best.ok && (assembles < best.assembles_over_range || (assembles == best.assembles_over_range && cost >= best.cost))) continue;
    best.assembles_over_range = assembles;
    best.ok = true;
    best.cost = cost;
    best.iterations = static_cast<int>(summary.iterations.size());
    best.start_index = start;
    best.values.assign(x.begin(), x.begin() + n);
    best.target_residuals.clear();
    best.fitted_inputs.clear();
    int row = 0, free_index = 0;
    for (const FitTarget& t : targets) {
      const double w = t.weight != 0 ? t.weight : 1;
      double residual = t.point ? std::hypot(r[row], r[row + 1]) : std::abs(r[row]);
      for (int k = 1; t.straight && k < t.samples; ++k) residual = std::max(residual, std::abs(r[row + k]));
      best.target_residuals.push_back(residual / std::abs(w));
      best.fitted_inputs.push_back(t.input_free ? x[n + free_index++] : t.input);
      row += t.straight ? t.samples : t.point ? 2 : 1;
    }
  }
  if (!best.ok) {
    best.message = "no start gave a design that assembles at every target";
    return best;
  }
  return best;
}

}  // namespace koppel

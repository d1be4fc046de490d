// The one translation unit of koppel that includes Ceres.
#include "koppel/solver/fit.hpp"

#include "koppel/solver/position.hpp"
#include "koppel/solver/stationary.hpp"
#include "koppel/solver/sweep.hpp"

#include <ceres/ceres.h>

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
        const ConstraintSystem& system = solver.system();
        Eigen::VectorXd r_plus(system.NumEquations()), r_minus(system.NumEquations()), dq(system.NumCoordinates());
        for (int j = 0; j < n_params; ++j) {
          const double h = kParameterStep * std::max(1.0, std::abs(p[j]));
          std::vector<double> pp = p, pm = p;
          pp[j] += h;
          pm[j] -= h;
          Mechanism mp, mm;
          if (!builder_(pp, &mp, &error) || !builder_(pm, &mm, &error)) return false;
          const ConstraintSystem sp(mp), sm(mm);
          sp.Residuals(qt.data(), input, r_plus.data());
          sm.Residuals(qt.data(), input, r_minus.data());
          const Eigen::VectorXd dF = (r_plus - r_minus) / (2 * h);
          dq = -solver.SolveWithJacobian(dF);
          // total derivative of the output along (dq/dp_j, e_j): one directional difference
          const Eigen::VectorXd q_plus = qt + h * dq, q_minus = qt - h * dq;
          for (int c = 0; c < comps; ++c) {
            const int comp = t.point ? c : t.component;
            const double d = (sp.Output(t.output, comp, q_plus.data()) - sm.Output(t.output, comp, q_minus.data())) / (2 * h);
            jacobian[(row + c) * n_unknowns + j] = t.weight * d;
          }
        }
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
    const ConstraintSystem& system = solver.system();
    Eigen::VectorXd r_plus(system.NumEquations()), r_minus(system.NumEquations());
    std::string error;
    for (size_t j = 0; j < p.size(); ++j) {
      const double h = kParameterStep * std::max(1.0, std::abs(p[j]));
      std::vector<double> pp = p, pm = p;
      pp[j] += h;
      pm[j] -= h;
      Mechanism mp, mm;
      if (!builder_(pp, &mp, &error) || !builder_(pm, &mm, &error)) return false;
      ConstraintSystem(mp).Residuals(q.data(), dc.input, r_plus.data());
      ConstraintSystem(mm).Residuals(q.data(), dc.input, r_minus.data());
      const Eigen::VectorXd dq = -solver.SolveWithJacobian((r_plus - r_minus) / (2 * h));
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
    for (const FitTarget& t : targets_) n += t.point ? 2 : 1;
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
      best.target_residuals.push_back(t.point ? std::hypot(r[row], r[row + 1]) / std::abs(w) : std::abs(r[row]) / std::abs(w));
      best.fitted_inputs.push_back(t.input_free ? x[n + free_index++] : t.input);
      row += t.point ? 2 : 1;
    }
  }
  if (!best.ok) {
    best.message = "no start gave a design that assembles at every target";
    return best;
  }
  return best;
}

}  // namespace koppel

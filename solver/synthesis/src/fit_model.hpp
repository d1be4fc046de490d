// The residuals of a fit and their Jacobian through the solver (see fit.hpp): private to fit.cpp.
#pragma once

#include "koppel/analysis/sensitivity.hpp"
#include "koppel/solver/position.hpp"
#include "koppel/synthesis/fit.hpp"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace koppel {

// The difference a - b wrapped to (-pi, pi].
double WrappedAngle(double difference);

// Solves every target's pose for one parameter vector, following each target's input from the
// assembly hint by continuation, and gives residuals and IFT derivatives. Stateless between
// calls: one model serves several threads.
class TargetModel {
 public:
  TargetModel(MechanismBuilder builder, std::vector<FitTarget> targets) : builder_(std::move(builder)), targets_(std::move(targets)) {}

  // residuals: per target 2 (point), `samples` (straight) or 1; jacobian (row-major, residuals x
  // unknowns) if non-null. unknowns = parameters then one per free input. false where the
  // mechanism cannot be built or does not reach a target's input.
  bool Evaluate(const double* unknowns, int n_params, double* residuals, double* jacobian) const;

  int Residuals() const;
  int FreeInputs() const;

 private:
  // One output target (a value or a point) at `input`, reached from q_hint: its residuals
  // (t.weight times the wrapped difference) and, if jacobian is non-null, their rows: the
  // parameters' columns by the implicit function theorem, and free_column (>= 0: the input is
  // free) by the transfer function.
  bool OutputAt(const Mechanism& m, PositionSolver& solver, const Eigen::VectorXd& q_hint, const Perturbations* perturbed, const FitTarget& t,
                double input, int free_column, double* residuals, double* jacobian, int n_params, int n_unknowns) const;
  // One straight-line target: distances of the samples from their total-least-squares line.
  bool Straight(const Mechanism& m, PositionSolver& solver, const Eigen::VectorXd& q_hint, const Perturbations* perturbed, const FitTarget& t,
                double* residuals, double* jacobian, int n_unknowns) const;
  // One dead-centre target: residual = (input of the dead centre next to t.input) - t.input.
  bool DeadCentre(const Mechanism& m, PositionSolver& solver, const Eigen::VectorXd& q_hint, const Perturbations* perturbed, const FitTarget& t,
                  double* residual, double* jacobian_row, int n_unknowns) const;

  const MechanismBuilder builder_;
  const std::vector<FitTarget> targets_;
};

}  // namespace koppel

// Exact first-order sensitivities of a solved pose to the mechanism's parameters and to play in
// its joints, by the implicit-function theorem: at a converged pose F(q, input; p) = 0, so
// dq/dp = -J^-1 dF/dp with the Jacobian J the solver has already factorised there. dF/dp is one
// central difference of the residual function at the fixed pose (no Newton inside a difference:
// error O(h^2) ~ 1e-12 relative), and an output's total derivative adds its explicit dependence
// on p (a coupler point's position on its link) to its gradient along dq/dp, which is taken
// exactly on a first-order Taylor series. The fit (synthesis/fit.hpp) and the tolerance analysis
// (tolerance.hpp) share these.
#pragma once

#include "koppel/core/expected.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/solver/position.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace koppel {

// Builds the mechanism for parameter values, or says why the values make no mechanism. Called
// from several threads at once: it must not share mutable state.
using MechanismBuilder = std::function<Expected<Mechanism>(const std::vector<double>& values)>;

// The mechanisms at p +- step_j e_j (step_j = relative_step * max(1, |p_j|)), built once and
// shared by every pose's sensitivities.
struct Perturbations {
  std::vector<Mechanism> plus, minus;
  std::vector<double> step;
};
// Relative step of the parameter differences: central differences of smooth residuals, error
// O(h^2) ~ 1e-12 against roundoff O(eps/h) ~ 1e-10.
inline constexpr double kParameterStep = 1e-6;
// False when the builder refuses one of the perturbed values.
bool Perturb(const MechanismBuilder& builder, const std::vector<double>& p, Perturbations* out, double relative_step = kParameterStep);

// dq/dp_j at a converged pose (the solver's factorisation must be at q): -J^-1 dF/dp_j.
Eigen::VectorXd PoseSensitivity(const PositionSolver& solver, const Eigen::VectorXd& q, double input, const Perturbations& perturbed, int j);

// d(output component)/d(q) . dq, exact (Taylor<1> through the output's formula).
double OutputDirectional(const ConstraintSystem& system, int output, int component, const Eigen::VectorXd& q, const Eigen::VectorXd& dq);

// d(output components first_component .. + comps - 1)/dp at a converged pose: comps x parameters.
// Angles (angle = true) are differenced wrapped, so an output reported across +-pi is smooth.
void OutputSensitivity(const PositionSolver& solver, const Eigen::VectorXd& q, double input, const Perturbations& perturbed, int output,
                       int first_component, int comps, bool angle, Eigen::MatrixXd* d);

// The gradient d y / d delta [1/1, global frame] of an output component to a revolute joint's
// play: the joint's point on link_a displaced by delta from its point on link_b (the pin free in
// its hole), at a converged pose. The output moves by at most c |gradient| for a pin anywhere
// within a circle of radius c (first order).
Eigen::Vector2d ClearanceGradient(const PositionSolver& solver, const Eigen::VectorXd& q, int joint, int output, int component);

}  // namespace koppel

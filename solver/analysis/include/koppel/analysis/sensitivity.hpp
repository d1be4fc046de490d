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

// Play in a revolute joint, the one model the linear gradient and the Monte Carlo share (tolerance.hpp):
// the pin sits off the centre of its hole by delta, so the joint's point on link_a lies delta
// from its point on link_b (R rows p_a - p_b = delta); every link keeps its own geometry, and an
// output is read off the links it names (OutputOnLinks). In a single loop a gap at any joint
// enters the loop's closure alike, so an output read off link directions (a link angle, a joint
// angle, a transmission angle) has the same |dy/d delta| whichever of the loop's joints has the play.

// The mechanism with joint `joint`'s pin moved by `offset` [length, body frame of link_b] in its
// hole: a new point on link_b (so a point that another joint or an output names stays put). The
// joint must be revolute. Read the outputs of the result with a system of the mechanism before
// the move (OutputOnLinks): the moved point is a joint's, not a point of the part.
void DisplacePin(Mechanism* mechanism, int joint, const Eigen::Vector2d& offset);

// An output component at pose q read off the links' own geometry, also where play leaves a
// joint's two points apart (`system` of the mechanism without play). Every output reads named
// points of named links, but for one: a transmission angle about a pivot takes the coupler's
// point of the output joint as the output link's point too (the kernel's formula, exact where
// the joint is closed). Here the coupler is first shifted onto the output link's own point: that
// keeps the coupler's direction (all the angle reads of it) and makes the radius the output
// link's own, so mu depends on the two links' directions alone, as it does without play.
double OutputOnLinks(const ConstraintSystem& system, int output, int component, const Eigen::VectorXd& q);

// The gradient d y / d delta [1/1, global frame] of an output component (read by OutputOnLinks)
// to a revolute joint's play delta at a converged pose. The output moves by at most c |gradient|
// for a pin anywhere within a circle of radius c (first order).
Eigen::Vector2d ClearanceGradient(const PositionSolver& solver, const Eigen::VectorXd& q, int joint, int output, int component);

}  // namespace koppel

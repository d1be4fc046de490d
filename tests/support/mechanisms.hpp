// Mechanisms built in code, with the seeds' conventions, so the solver's tests do not depend on
// the YAML reader (the catalog files get their own tests in tests/catalog).
#pragma once

#include "koppel/core/mechanism.hpp"

namespace koppel::test {

// Seed 000 conventions: A0 = (0, -e), foot point F = (0, 0), A = A0 + l1 (sin phi, -cos phi),
// slide along +x through F; outputs "s" (slide), "mu" (transmission angle).
Mechanism SliderCrank(double l1, double l2, double e);
// Seed 001: A0 = 0, B0 = (l6, 0), slot through B0 and A, slider 5 on x = l6 - h; output "s".
Mechanism ProportionalLinkage(double l6, double l1, double h);
// Four-bar A0 = 0, B0 = (l4, 0), crank angle phi from A0->B0; B assembled on `side` (+1: left of
// A -> B0, as the catalog's seed 003 file); coupler point K at AK = k, angle BAK = kappa.
// Outputs "K" (point), "psi" (rocker angle), "mu". `drive_at_rocker` drives B0 instead of A0.
Mechanism FourBar(double l1, double l2, double l3, double l4, double k, double kappa, int side, bool drive_at_rocker = false);
// A Watt six-bar (two independent loops): a four-bar A0 A B B0 whose rocker carries a second
// dyad C D to the frame pivot D0. Output "chi": the last link's angle.
Mechanism WattSixBar();

// A plain four-bar: A0 = 0, B0 = (d, 0), crank A0A = a, coupler AB = b, rocker B0B = c, every
// link's body x axis along its bar; driven at A0 (or at B0 with `drive_at_rocker`), assembled
// at `input` [rad] with B near `hint_b`. Outputs "psi" (rocker angle B0 -> B) and "theta"
// (coupler angle A -> B).
Mechanism PlainFourBar(double a, double b, double c, double d, double input, Eigen::Vector2d hint_b, bool drive_at_rocker = false);

// A Watt six-bar whose second loop folds flat mid-sweep: the crank-rocker A0 A B B0 (1, 3.5, 3, 4)
// carries on its rocker C (B0C = r, at angle gamma from B0B) a parallelogram loop B0 C D D0
// (CD = B0D0 = e, D0D = r) whose frame side B0D0 points along `fold_direction`: the loop lines up
// (a branch point) wherever the direction of B0 -> C passes fold_direction (mod pi).
// Outputs "psi" (rocker angle) and "chi" (angle of D0 -> D).
Mechanism FoldingSixBar(double r, double gamma, double e, double fold_direction);

// A five-bar (two degrees of freedom) with one drive: frame A0 = 0, E0 = (4, 0); links 1.5, 3, 3,
// 1.5. Not a one-drive mechanism.
Mechanism FiveBar();
// The parallelogram 1, 3, 1, 3 with a redundant third crank E0E (E0 = (1.5, 0), E on the coupler
// at 1.5): Grübler 0, yet it moves (rank mobility 1).
Mechanism RedundantParallelogram();

// The mechanism with every length (points, assembly hint, P-drive zero) times `factor`.
Mechanism Scaled(const Mechanism& mechanism, double factor);

}  // namespace koppel::test

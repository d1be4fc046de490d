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

}  // namespace koppel::test

// The mechanisms `koppel bench` times, built in code with the seeds' conventions, and the
// hand-written closed forms that do the same work per step (every output with its first and
// second derivative with respect to the input) as the generic solver's baseline.
#pragma once

#include "koppel/core/mechanism.hpp"

namespace koppel::bench {

// Seed 003's crank-rocker cognate of a Meyer zur Capellen linkage (catalog mzc-crank-rocker):
// A0 = 0, B0 = (4, 0), l1 = 1, l2 = l3 = 5/2 sqrt 3, coupler point K at AK = 25/3, angle BAK =
// acos(5/9 sqrt 3), B above A0B0. Outputs K (point), psi (rocker angle), mu.
Mechanism SeedFourBar();
// Seed 000's slider-crank, l1 = 1, l2 = 2.6, e = 0.8 (catalog slider-crank-offset). Outputs s, mu.
Mechanism SeedSliderCrank();
// Seed 001's proportional linkage, l6 = 1, l1 = 0.5, h = 1.83 (catalog proportional-linkage).
// Output s.
Mechanism SeedProportional();
// A chain of `loops` four-bar loops, each rocker driving the next: the crank-rocker A0 A B B0
// (1, 3.5, 3, 4), then parallelograms (2.5, 4, 2.5, 4) whose rockers are pivoted 4 apart along
// the x axis. Every rocker turns like the first (between about 100 and 140 deg, never near the
// frame line where a parallelogram folds). Output psi: the last rocker's angle.
Mechanism Chain(int loops);

// value, first and second derivative with respect to the input
struct Jet {
  double v = 0, d1 = 0, d2 = 0;
};
struct FourBarValues {
  Jet kx, ky, psi, mu;
};
struct SliderCrankValues {
  Jet s, mu;
};

// Closed forms at crank angle phi [rad] (vector loop l1 e^{i phi} + l2 e^{i theta} = l4 + l3
// e^{i psi} differentiated twice; seed 000's s/l1 = sin phi + cos psi / lambda; seed 001's
// s = l1 h / l6 sin phi / (1 - lambda cos phi)).
FourBarValues SeedFourBarClosedForm(double phi);
// The positions alone (B and K, no derivatives, no angles): the closed form of what the
// positions benchmarks solve (libslvs's sketch, koppel's walk without outputs).
struct FourBarPoints {
  double bx, by, kx, ky;
};
FourBarPoints SeedFourBarPositionsClosedForm(double phi);
SliderCrankValues SeedSliderCrankClosedForm(double phi);
Jet SeedProportionalClosedForm(double phi);

}  // namespace koppel::bench

// What the tests of the cycle pictures share: seed 003's crank-rocker (mzc-crank-rocker.yaml,
// l1 = 1, l2 = l3 = 5/2 sqrt 3, l4 = 4, AK = 25/3, angle BAK = acos(5/9 sqrt 3)) built in code,
// with B left of A -> B0, and cycle options for a mechanism: its point outputs traced, the
// default part sizes, the sweep a full turn.
#pragma once

#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/plot/cycle.hpp"

#include <cmath>

namespace koppel::test {

inline const double kMzcCoupler = 2.5 * std::sqrt(3.0);
inline const double kMzcK = 25.0 / 3;
inline const double kMzcKappa = std::acos(5.0 / 9 * std::sqrt(3.0));

inline Mechanism MzcCrankRocker() { return FourBar(1, kMzcCoupler, kMzcCoupler, 4, kMzcK, kMzcKappa, +1); }

// The closed form's B and K at crank angle phi [rad].
inline Eigen::Vector2d MzcB(double phi) { return FourBarRocker(1, kMzcCoupler, kMzcCoupler, 4, phi, +1)->b; }
inline Eigen::Vector2d MzcK(double phi) { return FourBarCouplerPoint(1, kMzcCoupler, kMzcCoupler, 4, kMzcK, kMzcKappa, phi, +1); }

// A Grashof double rocker (coupler shortest: catalog/entries/double-rocker.yaml), assembled
// above at 70 deg; it swings between 49.2 and 97.2 deg.
inline Mechanism DoubleRocker() { return PlainFourBar(3, 1, 3.5, 3, DegToRad(70), {2, 3.4}); }

inline plot::CycleOptions CycleOptionsFor(const Mechanism& m) {
  plot::CycleOptions o;
  o.traced = plot::PointOutputs(m);
  o.sizes = plot::DefaultPartSizes(m);
  o.sweep.from = 0;
  o.sweep.to = 2 * kPi;
  return o;
}

}  // namespace koppel::test

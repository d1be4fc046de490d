// The Taylor coefficients q, q', q''/2 of a mechanism's coordinates at one input on the hint's
// branch: the pose the dynamics tests evaluate loads and inertia at.
#pragma once

#include "koppel/solver/sweep.hpp"

#include <catch2/catch.hpp>

namespace koppel::test {

inline Eigen::MatrixXd SeriesAt(const Mechanism& m, double input) {
  SweepOptions o;
  o.from = o.to = input;
  const SweepResult s = Sweep(m, o);
  REQUIRE(s.inputs.size() == 1);
  PositionSolver solver(m);
  Eigen::VectorXd q = s.poses.row(0).transpose();
  REQUIRE(solver.Correct(input, q).ok());
  Eigen::MatrixXd series;
  REQUIRE(solver.Series(2, series));
  return series;
}

}  // namespace koppel::test

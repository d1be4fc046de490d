// SampleMechanism and PoseAt (tools/plot/src/sampled_run.cpp): the pictures' adapter of the
// kernel's sweep. Checked on a Grashof double-rocker driven across its limits (the case of
// tests/solver/kernel/continuation_test.cpp) against the four-bar's closed form (circle
// intersection and the law of cosines, tests/support/closed_forms).
#include "koppel/plot/sampled_run.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/solver/constraints.hpp"
#include "koppel/solver/position.hpp"
#include "support/closed_forms.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

namespace koppel::sampled_run_test {
namespace {

// The solver's poses and limit points against the closed form: Newton converges to 1e-13 of the
// size; the kernel's tests hold poses and limits to 1e-9.
constexpr double kPose = 1e-9;

// The coupler (1) shortest: the input link a = 3 swings while 2.5 <= |A B0| <= 4.5; limits at
// 38.62 and 78.58 deg (and their mirrors).
constexpr double kA = 3, kB = 1, kC = 3.5, kD = 4;

Mechanism DoubleRocker() {
  const Eigen::Vector2d hint = test::FourBarRocker(kA, kB, kC, kD, DegToRad(60), +1)->b;
  return test::PlainFourBar(kA, kB, kC, kD, DegToRad(60), hint);
}

SweepOptions Degrees(double from, double to, double step) {
  SweepOptions s;
  s.from = DegToRad(from);
  s.to = DegToRad(to);
  s.step = DegToRad(step);
  return s;
}

TEST_CASE("a run across the limits: one stretch, the gaps beyond, the limits marked", "[sampled_run]") {
  const Mechanism m = DoubleRocker();
  const plot::SampledRun run = plot::SampleMechanism(m, Degrees(0, 120, 1));
  CHECK_FALSE(run.complete);
  CHECK_FALSE(run.message.empty());
  REQUIRE(run.size() == 40);  // 39 .. 78 deg: hand count of whole degrees inside the limits
  REQUIRE(run.stretches.size() == 1);
  CHECK(run.stretches[0].begin == 0);
  CHECK(run.stretches[0].end == 40);
  const std::vector<double> limits = test::FourBarLimits(kA, kB, kC, kD);
  const double low = *std::min_element(limits.begin(), limits.end()), high = limits[0];
  REQUIRE(run.gaps.size() == 2);
  CHECK(run.gaps[0].from == 0.0);
  CHECK(std::abs(run.gaps[0].to - low) < kPose);
  CHECK(std::abs(run.gaps[1].from - high) < kPose);
  CHECK(run.gaps[1].to == DegToRad(120));
  REQUIRE(run.singular.size() == 2);
  for (double s : run.singular) CHECK(std::min(std::abs(s - low), std::abs(s - high)) < kPose);
  // the samples are the rocker of the closed form, read through Column
  const int psi = run.Column(m, 0, 0, 0);
  CHECK(psi == OutputColumn(m, 0, 0, run.order));
  for (int i = 0; i < run.size(); ++i) {
    INFO("phi = " << RadToDeg(run.inputs[i]));
    const double ref = test::FourBarRocker(kA, kB, kC, kD, run.inputs[i], +1)->psi;
    CHECK(std::abs(AngleDifference(run.outputs(i, psi), ref)) < kPose);
    CHECK(run.poses.rows() == run.size());
  }
}

TEST_CASE("a run over two turns shows each limit in both turns", "[sampled_run]") {
  // the sweep meets each limit once (its inputs are a turn apart at most); the run marks it
  // wherever the requested range shows it, modulo a turn: reference, the hand count 2 limits x 2 turns
  const Mechanism m = DoubleRocker();
  const plot::SampledRun run = plot::SampleMechanism(m, Degrees(0, 720, 1));
  const std::vector<double> limits = test::FourBarLimits(kA, kB, kC, kD);
  const double low = *std::min_element(limits.begin(), limits.end()), high = limits[0];
  int shown = 0;
  for (double s : run.singular) {
    CHECK(s >= 0);
    CHECK(s <= DegToRad(720));
    for (double limit : {low, high})
      for (double turn : {0.0, 2 * kPi}) shown += std::abs(s - (limit + turn)) < kPose ? 1 : 0;
  }
  CHECK(shown >= 4);
  // no stretch joins samples across a gap
  for (const plot::Stretch& st : run.stretches) {
    for (int i = st.begin; i + 1 < st.end; ++i) {
      const double a = run.inputs[i], b = run.inputs[i + 1];
      for (const plot::InputGap& g : run.gaps) CHECK_FALSE((std::min(g.from, g.to) >= std::min(a, b) && std::max(g.from, g.to) <= std::max(a, b)));
    }
  }
  // the stretches cover the samples once, in order
  int next = 0;
  for (const plot::Stretch& st : run.stretches) {
    CHECK(st.begin == next);
    next = st.end;
  }
  CHECK(next == run.size());
}

TEST_CASE("a pose between samples is on the run's branch; beyond a limit there is none", "[sampled_run]") {
  const Mechanism m = DoubleRocker();
  const plot::SampledRun run = plot::SampleMechanism(m, Degrees(40, 75, 5));
  const ConstraintSystem system(m);
  const int rocker = system.CoordinateOf(m.FindLink("rocker"));
  for (double phi_deg : {42.5, 61.0, 74.9}) {
    const Expected<Eigen::VectorXd> q = plot::PoseAt(m, run, DegToRad(phi_deg));
    REQUIRE(q);
    const double ref = test::FourBarRocker(kA, kB, kC, kD, DegToRad(phi_deg), +1)->psi;
    CHECK(std::abs(AngleDifference((*q)[rocker + 2], ref)) < kPose);
  }
  CHECK_FALSE(plot::PoseAt(m, run, DegToRad(100)));  // past the upper limit, 78.58 deg
  CHECK_FALSE(plot::PoseAt(m, plot::SampledRun{}, 0.0));
}

}  // namespace
}  // namespace koppel::sampled_run_test

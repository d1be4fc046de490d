// The slider-crank built in code (koppel/core/build.hpp) and its dead centres
// (koppel/analysis/dead_centres.hpp): the stroke against seed 000's closed form.
#include <koppel/analysis/dead_centres.hpp>
#include <koppel/core/build.hpp>

#include <cmath>
#include <cstdio>

int main() {
  const double l1 = 1, l2 = 2.6, e = 0.8;
  koppel::Mechanism m;
  koppel::AddLink(m, "frame", {{"A0", {0, -e}}, {"F", {0, 0}}}, true);
  koppel::AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {0, -l1}}});
  koppel::AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {l2, 0}}});
  koppel::AddLink(m, "slider", {{"B", {0, 0}}});
  koppel::Revolute(m, "A0", "frame", "crank");
  koppel::Revolute(m, "A", "crank", "coupler");
  koppel::Revolute(m, "B", "coupler", "slider");
  koppel::Prismatic(m, "S", "frame", "F", "slider", "B", {1, 0});
  koppel::SetDrive(m, "A0");
  koppel::JointOutput(m, "s", "S");
  koppel::HintPoint(m, "slider", "B", {l1 + l2, 0});
  koppel::SweepOptions range;  // a full turn in steps of 1 degree
  const koppel::DeadCentreReport r = koppel::FindDeadCentres(m, 0, 0, range);
  const double expected = std::sqrt((l1 + l2) * (l1 + l2) - e * e) - std::sqrt((l2 - l1) * (l2 - l1) - e * e);
  std::printf("stroke %.12f, closed form %.12f\n", r.stroke, expected);
  return r.has_stroke && std::abs(r.stroke - expected) < 1e-9 ? 0 : 1;
}

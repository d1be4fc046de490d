#include "support/mechanisms.hpp"

#include "koppel/core/build.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace koppel::test {

Mechanism SliderCrank(double l1, double l2, double e) {
  Mechanism m;
  m.name = "slider-crank";
  AddLink(m, "frame", {{"A0", {0, -e}}, {"F", {0, 0}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {0, -l1}}});
  AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {l2, 0}}});
  AddLink(m, "slider", {{"B", {0, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "coupler");
  Revolute(m, "B", "coupler", "slider");
  Prismatic(m, "S", "frame", "F", "slider", "B", {1, 0});
  SetDrive(m, "A0");
  JointOutput(m, "s", "S");
  TransmissionOutput(m, "mu", "coupler", "B");
  HintPoint(m, "slider", "B", {l1 + l2, 0});
  return m;
}

Mechanism ProportionalLinkage(double l6, double l1, double h) {
  Mechanism m;
  m.name = "proportional-linkage";
  AddLink(m, "frame", {{"A0", {0, 0}}, {"B0", {l6, 0}}, {"G", {l6 - h, 0}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {l1, 0}}});
  AddLink(m, "block2", {{"A", {0, 0}}});
  AddLink(m, "slot", {{"B0", {0, 0}}});
  AddLink(m, "block4", {{"D", {0, 0}}});
  AddLink(m, "slider", {{"D", {0, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "block2");
  Prismatic(m, "S23", "slot", "B0", "block2", "A", {1, 0});
  Revolute(m, "B0", "frame", "slot");
  Prismatic(m, "S34", "slot", "B0", "block4", "D", {1, 0});
  Revolute(m, "D", "block4", "slider");
  Prismatic(m, "S50", "frame", "G", "slider", "D", {0, 1});
  SetDrive(m, "A0");
  JointOutput(m, "s", "S50");
  HintPoint(m, "slider", "D", {l6 - h, 0});
  return m;
}

Mechanism FourBar(double l1, double l2, double l3, double l4, double k, double kappa, int side, bool drive_at_rocker) {
  Mechanism m;
  m.name = "four-bar";
  AddLink(m, "frame", {{"A0", {0, 0}}, {"B0", {l4, 0}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {l1, 0}}});
  AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {l2, 0}}, {"K", {k * std::cos(kappa), k * std::sin(kappa)}}});
  AddLink(m, "rocker", {{"B0", {0, 0}}, {"B", {l3, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "coupler");
  Revolute(m, "B", "coupler", "rocker");
  Revolute(m, "B0", "frame", "rocker");
  SetDrive(m, drive_at_rocker ? "B0" : "A0");
  PointOutput(m, "K", "coupler", "K");
  LinkAngleOutput(m, "psi", "rocker");
  JointOutput(m, "phi", "A0");
  if (!drive_at_rocker) TransmissionOutput(m, "mu", "coupler", "B");
  // at input 0 the crank points along +x: B lies roughly above/below the middle of A B0
  const double mid = 0.5 * (l1 + l4);
  const double height = std::sqrt(std::max(l2 * l2 - std::pow(0.5 * (l4 - l1), 2), 0.25));
  HintPoint(m, "coupler", "B", {mid, side * height});
  return m;
}

Mechanism WattSixBar() {
  Mechanism m;
  m.name = "watt-six-bar";
  AddLink(m, "frame", {{"A0", {0, 0}}, {"B0", {4, 0}}, {"D0", {7, 1}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {1, 0}}});
  AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {4, 0}}});
  AddLink(m, "rocker", {{"B0", {0, 0}}, {"B", {3.5, 0}}, {"C", {2.5, 1.0}}});
  AddLink(m, "link5", {{"C", {0, 0}}, {"D", {3.0, 0}}});
  AddLink(m, "link6", {{"D0", {0, 0}}, {"D", {2.5, 0}}});
  for (const auto& [joint, a, b] : std::vector<std::array<std::string, 3>>{{"A0", "frame", "crank"},  {"A", "crank", "coupler"},
                                                                           {"B", "coupler", "rocker"}, {"B0", "frame", "rocker"},
                                                                           {"C", "rocker", "link5"},   {"D", "link5", "link6"},
                                                                           {"D0", "frame", "link6"}})
    Revolute(m, joint, a, b);
  SetDrive(m, "A0");
  LinkAngleOutput(m, "chi", "link6");
  HintPoint(m, "rocker", "B", {3, 3});
  HintPoint(m, "link6", "D", {7, 3.5});
  return m;
}

Mechanism PlainFourBar(double a, double b, double c, double d, double input, Eigen::Vector2d hint_b, bool drive_at_rocker) {
  Mechanism m;
  m.name = "four-bar";
  AddLink(m, "frame", {{"A0", {0, 0}}, {"B0", {d, 0}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {a, 0}}});
  AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {b, 0}}});
  AddLink(m, "rocker", {{"B0", {0, 0}}, {"B", {c, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "coupler");
  Revolute(m, "B", "coupler", "rocker");
  Revolute(m, "B0", "frame", "rocker");
  SetDrive(m, drive_at_rocker ? "B0" : "A0");
  LinkAngleOutput(m, "psi", "rocker");
  LinkAngleOutput(m, "theta", "coupler");
  HintInput(m, input);
  HintPoint(m, "coupler", "B", hint_b);
  return m;
}

Mechanism FoldingSixBar(double r, double gamma, double e, double fold_direction) {
  Mechanism m;
  m.name = "folding-six-bar";
  const Eigen::Vector2d d0(4 + e * std::cos(fold_direction), e * std::sin(fold_direction));
  AddLink(m, "frame", {{"A0", {0, 0}}, {"B0", {4, 0}}, {"D0", d0}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {1, 0}}});
  AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {3.5, 0}}});
  AddLink(m, "rocker", {{"B0", {0, 0}}, {"B", {3, 0}}, {"C", {r * std::cos(gamma), r * std::sin(gamma)}}});
  AddLink(m, "link5", {{"C", {0, 0}}, {"D", {e, 0}}});
  AddLink(m, "link6", {{"D0", {0, 0}}, {"D", {r, 0}}});
  for (const auto& [joint, a, b] : std::vector<std::array<std::string, 3>>{{"A0", "frame", "crank"},  {"A", "crank", "coupler"},
                                                                           {"B", "coupler", "rocker"}, {"B0", "frame", "rocker"},
                                                                           {"C", "rocker", "link5"},   {"D", "link5", "link6"},
                                                                           {"D0", "frame", "link6"}})
    Revolute(m, joint, a, b);
  SetDrive(m, "A0");
  LinkAngleOutput(m, "psi", "rocker");
  LinkAngleOutput(m, "chi", "link6");
  // assembled at phi = 90 deg with B above A0B0 and the second loop a parallelogram
  const Eigen::Vector2d a(0, 1), b0(4, 0), u = (b0 - a).normalized(), n(-u.y(), u.x());
  const double dist = (b0 - a).norm(), along = (3.5 * 3.5 - 3.0 * 3.0 + dist * dist) / (2 * dist);
  const Eigen::Vector2d b = a + along * u + std::sqrt(3.5 * 3.5 - along * along) * n;
  const double psi_at = std::atan2(b.y(), b.x() - 4);
  const Eigen::Vector2d c = b0 + r * Eigen::Vector2d(std::cos(psi_at + gamma), std::sin(psi_at + gamma));
  HintInput(m, M_PI / 2);
  HintPoint(m, "coupler", "B", b);
  HintPoint(m, "link6", "D", c + (d0 - b0));
  return m;
}

Mechanism FiveBar() {
  Mechanism m;
  m.name = "five-bar";
  AddLink(m, "frame", {{"A0", {0, 0}}, {"E0", {4, 0}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {1.5, 0}}});
  AddLink(m, "l2", {{"A", {0, 0}}, {"C", {3, 0}}});
  AddLink(m, "l3", {{"C", {0, 0}}, {"E", {3, 0}}});
  AddLink(m, "l4", {{"E0", {0, 0}}, {"E", {1.5, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "l2");
  Revolute(m, "C", "l2", "l3");
  Revolute(m, "E", "l3", "l4");
  Revolute(m, "E0", "frame", "l4");
  SetDrive(m, "A0");
  HintInput(m, M_PI / 2);
  HintPoint(m, "l2", "C", {2, 3});
  HintPoint(m, "l4", "E", {4, 1.5});
  return m;
}

Mechanism RedundantParallelogram() {
  Mechanism m = PlainFourBar(1, 3, 1, 3, M_PI / 2, {3, 1});
  m.name = "redundant-parallelogram";
  m.links[m.FindLink("frame")].points.push_back({"E0", {1.5, 0}});
  m.links[m.FindLink("coupler")].points.push_back({"E", {1.5, 0}});
  AddLink(m, "third", {{"E0", {0, 0}}, {"E", {1, 0}}});
  Revolute(m, "E0", "frame", "third");
  Revolute(m, "E", "coupler", "third");
  return m;
}

Mechanism Scaled(const Mechanism& original, double factor) {
  Mechanism m = original;
  for (Link& link : m.links) {
    for (NamedPoint& p : link.points) p.local *= factor;
  }
  for (AssemblyHint::Entry& e : m.hint.points) e.global *= factor;
  if (!m.InputIsAngle()) {
    m.drive.zero *= factor;
    m.hint.input *= factor;
  }
  return m;
}

}  // namespace koppel::test

#include "support/mechanisms.hpp"

#include <cmath>

namespace koppel::test {
namespace {

Joint Revolute(const Mechanism& m, const std::string& name, const std::string& a, const std::string& b) {
  return PinJoint(m, name, m.FindLink(a), m.FindLink(b));
}

Joint Prismatic(const Mechanism& m, const std::string& name, const std::string& guide, const std::string& on_guide,
                const std::string& block, const std::string& on_block, Eigen::Vector2d axis) {
  Joint j;
  j.name = name;
  j.type = JointType::kPrismatic;
  j.link_a = m.FindLink(guide);
  j.link_b = m.FindLink(block);
  j.point_a = m.links[j.link_a].FindPoint(on_guide);
  j.point_b = m.links[j.link_b].FindPoint(on_block);
  j.axis = axis.normalized();
  return j;
}

Output JointOutput(const Mechanism& m, const std::string& name, const std::string& joint) {
  Output o;
  o.name = name;
  o.kind = OutputKind::kJoint;
  o.joint = m.FindJoint(joint);
  return o;
}

void Hint(Mechanism& m, const std::string& link, const std::string& point, Eigen::Vector2d where) {
  const int l = m.FindLink(link);
  m.hint.points.push_back({{l, m.links[l].FindPoint(point)}, where});
}

}  // namespace

Mechanism SliderCrank(double l1, double l2, double e) {
  Mechanism m;
  m.name = "slider-crank";
  m.links = {{"frame", true, {{"A0", {0, -e}}, {"F", {0, 0}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {0, -l1}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {l2, 0}}}},
             {"slider", false, {{"B", {0, 0}}}}};
  m.joints = {Revolute(m, "A0", "frame", "crank"), Revolute(m, "A", "crank", "coupler"), Revolute(m, "B", "coupler", "slider"),
              Prismatic(m, "S", "frame", "F", "slider", "B", {1, 0})};
  m.drive.joint = 0;
  Output mu;
  mu.name = "mu";
  mu.kind = OutputKind::kTransmissionAngle;
  mu.link = 2;
  mu.joint = 2;
  m.outputs = {JointOutput(m, "s", "S"), mu};
  Hint(m, "slider", "B", {l1 + l2, 0});
  return m;
}

Mechanism ProportionalLinkage(double l6, double l1, double h) {
  Mechanism m;
  m.name = "proportional-linkage";
  m.links = {{"frame", true, {{"A0", {0, 0}}, {"B0", {l6, 0}}, {"G", {l6 - h, 0}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {l1, 0}}}},
             {"block2", false, {{"A", {0, 0}}}},
             {"slot", false, {{"B0", {0, 0}}}},
             {"block4", false, {{"D", {0, 0}}}},
             {"slider", false, {{"D", {0, 0}}}}};
  m.joints = {Revolute(m, "A0", "frame", "crank"),
              Revolute(m, "A", "crank", "block2"),
              Prismatic(m, "S23", "slot", "B0", "block2", "A", {1, 0}),
              Revolute(m, "B0", "frame", "slot"),
              Prismatic(m, "S34", "slot", "B0", "block4", "D", {1, 0}),
              Revolute(m, "D", "block4", "slider"),
              Prismatic(m, "S50", "frame", "G", "slider", "D", {0, 1})};
  m.drive.joint = 0;
  m.outputs = {JointOutput(m, "s", "S50")};
  Hint(m, "slider", "D", {l6 - h, 0});
  return m;
}

Mechanism FourBar(double l1, double l2, double l3, double l4, double k, double kappa, int side, bool drive_at_rocker) {
  Mechanism m;
  m.name = "four-bar";
  m.links = {{"frame", true, {{"A0", {0, 0}}, {"B0", {l4, 0}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {l1, 0}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {l2, 0}}, {"K", {k * std::cos(kappa), k * std::sin(kappa)}}}},
             {"rocker", false, {{"B0", {0, 0}}, {"B", {l3, 0}}}}};
  m.joints = {Revolute(m, "A0", "frame", "crank"), Revolute(m, "A", "crank", "coupler"), Revolute(m, "B", "coupler", "rocker"),
              Revolute(m, "B0", "frame", "rocker")};
  m.drive.joint = drive_at_rocker ? 3 : 0;
  Output k_out;
  k_out.name = "K";
  k_out.kind = OutputKind::kPoint;
  k_out.p = {2, 2};
  Output psi;
  psi.name = "psi";
  psi.kind = OutputKind::kLinkAngle;
  psi.link = 3;
  m.outputs = {k_out, psi, JointOutput(m, "phi", "A0")};
  if (!drive_at_rocker) {
    Output mu;
    mu.name = "mu";
    mu.kind = OutputKind::kTransmissionAngle;
    mu.link = 2;
    mu.joint = 2;
    m.outputs.push_back(mu);
  }
  // at input 0 the crank points along +x: B lies roughly above/below the middle of A B0
  const double mid = 0.5 * (l1 + l4);
  const double height = std::sqrt(std::max(l2 * l2 - std::pow(0.5 * (l4 - l1), 2), 0.25));
  Hint(m, "coupler", "B", {mid, side * height});
  return m;
}

Mechanism WattSixBar() {
  Mechanism m;
  m.name = "watt-six-bar";
  m.links = {{"frame", true, {{"A0", {0, 0}}, {"B0", {4, 0}}, {"D0", {7, 1}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {1, 0}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {4, 0}}}},
             {"rocker", false, {{"B0", {0, 0}}, {"B", {3.5, 0}}, {"C", {2.5, 1.0}}}},
             {"link5", false, {{"C", {0, 0}}, {"D", {3.0, 0}}}},
             {"link6", false, {{"D0", {0, 0}}, {"D", {2.5, 0}}}}};
  m.joints = {Revolute(m, "A0", "frame", "crank"), Revolute(m, "A", "crank", "coupler"), Revolute(m, "B", "coupler", "rocker"),
              Revolute(m, "B0", "frame", "rocker"), Revolute(m, "C", "rocker", "link5"), Revolute(m, "D", "link5", "link6"),
              Revolute(m, "D0", "frame", "link6")};
  m.drive.joint = 0;
  Output chi;
  chi.name = "chi";
  chi.kind = OutputKind::kLinkAngle;
  chi.link = 5;
  m.outputs = {chi};
  Hint(m, "rocker", "B", {3, 3});
  Hint(m, "link6", "D", {7, 3.5});
  return m;
}

Mechanism PlainFourBar(double a, double b, double c, double d, double input, Eigen::Vector2d hint_b, bool drive_at_rocker) {
  Mechanism m;
  m.name = "four-bar";
  m.links = {{"frame", true, {{"A0", {0, 0}}, {"B0", {d, 0}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {a, 0}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {b, 0}}}},
             {"rocker", false, {{"B0", {0, 0}}, {"B", {c, 0}}}}};
  m.joints = {Revolute(m, "A0", "frame", "crank"), Revolute(m, "A", "crank", "coupler"), Revolute(m, "B", "coupler", "rocker"),
              Revolute(m, "B0", "frame", "rocker")};
  m.drive.joint = drive_at_rocker ? 3 : 0;
  Output psi, theta;
  psi.name = "psi";
  psi.kind = OutputKind::kLinkAngle;
  psi.link = 3;
  theta.name = "theta";
  theta.kind = OutputKind::kLinkAngle;
  theta.link = 2;
  m.outputs = {psi, theta};
  m.hint.input = input;
  Hint(m, "coupler", "B", hint_b);
  return m;
}

Mechanism FoldingSixBar(double r, double gamma, double e, double fold_direction) {
  Mechanism m;
  m.name = "folding-six-bar";
  const Eigen::Vector2d d0(4 + e * std::cos(fold_direction), e * std::sin(fold_direction));
  m.links = {{"frame", true, {{"A0", {0, 0}}, {"B0", {4, 0}}, {"D0", d0}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {1, 0}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {3.5, 0}}}},
             {"rocker", false, {{"B0", {0, 0}}, {"B", {3, 0}}, {"C", {r * std::cos(gamma), r * std::sin(gamma)}}}},
             {"link5", false, {{"C", {0, 0}}, {"D", {e, 0}}}},
             {"link6", false, {{"D0", {0, 0}}, {"D", {r, 0}}}}};
  m.joints = {Revolute(m, "A0", "frame", "crank"), Revolute(m, "A", "crank", "coupler"), Revolute(m, "B", "coupler", "rocker"),
              Revolute(m, "B0", "frame", "rocker"), Revolute(m, "C", "rocker", "link5"), Revolute(m, "D", "link5", "link6"),
              Revolute(m, "D0", "frame", "link6")};
  m.drive.joint = 0;
  Output psi, chi;
  psi.name = "psi";
  psi.kind = OutputKind::kLinkAngle;
  psi.link = 3;
  chi.name = "chi";
  chi.kind = OutputKind::kLinkAngle;
  chi.link = 5;
  m.outputs = {psi, chi};
  // assembled at phi = 90 deg with B above A0B0 and the second loop a parallelogram
  const Eigen::Vector2d a(0, 1), b0(4, 0), u = (b0 - a).normalized(), n(-u.y(), u.x());
  const double dist = (b0 - a).norm(), along = (3.5 * 3.5 - 3.0 * 3.0 + dist * dist) / (2 * dist);
  const Eigen::Vector2d b = a + along * u + std::sqrt(3.5 * 3.5 - along * along) * n;
  const double psi_at = std::atan2(b.y(), b.x() - 4);
  const Eigen::Vector2d c = b0 + r * Eigen::Vector2d(std::cos(psi_at + gamma), std::sin(psi_at + gamma));
  m.hint.input = M_PI / 2;
  Hint(m, "coupler", "B", b);
  Hint(m, "link6", "D", c + (d0 - b0));
  return m;
}

Mechanism FiveBar() {
  Mechanism m;
  m.name = "five-bar";
  m.links = {{"frame", true, {{"A0", {0, 0}}, {"E0", {4, 0}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {1.5, 0}}}},
             {"l2", false, {{"A", {0, 0}}, {"C", {3, 0}}}},
             {"l3", false, {{"C", {0, 0}}, {"E", {3, 0}}}},
             {"l4", false, {{"E0", {0, 0}}, {"E", {1.5, 0}}}}};
  m.joints = {Revolute(m, "A0", "frame", "crank"), Revolute(m, "A", "crank", "l2"), Revolute(m, "C", "l2", "l3"),
              Revolute(m, "E", "l3", "l4"), Revolute(m, "E0", "frame", "l4")};
  m.drive.joint = 0;
  m.hint.input = M_PI / 2;
  Hint(m, "l2", "C", {2, 3});
  Hint(m, "l4", "E", {4, 1.5});
  return m;
}

Mechanism RedundantParallelogram() {
  Mechanism m = PlainFourBar(1, 3, 1, 3, M_PI / 2, {3, 1});
  m.name = "redundant-parallelogram";
  m.links[0].points.push_back({"E0", {1.5, 0}});
  m.links[2].points.push_back({"E", {1.5, 0}});
  m.links.push_back({"third", false, {{"E0", {0, 0}}, {"E", {1, 0}}}});
  m.joints.push_back(Revolute(m, "E0", "frame", "third"));
  m.joints.push_back(Revolute(m, "E", "coupler", "third"));
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

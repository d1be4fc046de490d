#include "bench_mechanisms.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/build.hpp"

#include <cmath>
#include <string>

namespace koppel::bench {
namespace bench_mechanisms {  // this file's own names, apart from the other benchmarks' in a unity build
namespace {

// seed 003
const double kL1 = 1.0, kL2 = 2.5 * std::sqrt(3.0), kL3 = kL2, kL4 = 4.0, kK = 25.0 / 3.0;
const double kKappa = std::acos(5.0 / 9.0 * std::sqrt(3.0));
// seed 000
const double kCrank = 1.0, kCoupler = 2.6, kOffset = 0.8;
// seed 001
const double kFrame6 = 1.0, kCrank1 = 0.5, kSlideH = 1.83;

}  // namespace
}  // namespace bench_mechanisms

Mechanism SeedFourBar() {
  using namespace bench_mechanisms;
  Mechanism m;
  m.name = "fourbar";
  AddLink(m, "frame", {{"A0", {0, 0}}, {"B0", {kL4, 0}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {kL1, 0}}});
  AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {kL2, 0}}, {"K", {kK * std::cos(kKappa), kK * std::sin(kKappa)}}});
  AddLink(m, "rocker", {{"B0", {0, 0}}, {"B", {kL3, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "coupler");
  Revolute(m, "B", "coupler", "rocker");
  Revolute(m, "B0", "frame", "rocker");
  SetDrive(m, "A0");
  PointOutput(m, "K", "coupler", "K");
  LinkAngleOutput(m, "psi", "rocker");
  TransmissionOutput(m, "mu", "coupler", "B");
  HintInput(m, kPi);
  HintPoint(m, "coupler", "B", {1.5, 3.5});
  return m;
}

Mechanism SeedSliderCrank() {
  using namespace bench_mechanisms;
  Mechanism m;
  m.name = "slider-crank";
  AddLink(m, "frame", {{"A0", {0, -kOffset}}, {"F", {0, 0}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {0, -kCrank}}});
  AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {kCoupler, 0}}});
  AddLink(m, "slider", {{"B", {0, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "coupler");
  Revolute(m, "B", "coupler", "slider");
  Prismatic(m, "S", "frame", "F", "slider", "B", {1, 0});
  SetDrive(m, "A0");
  JointOutput(m, "s", "S");
  TransmissionOutput(m, "mu", "coupler", "B");
  HintPoint(m, "slider", "B", {2, 0});
  return m;
}

Mechanism SeedProportional() {
  using namespace bench_mechanisms;
  Mechanism m;
  m.name = "proportional";
  AddLink(m, "frame", {{"A0", {0, 0}}, {"B0", {kFrame6, 0}}, {"G", {kFrame6 - kSlideH, 0}}}, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {kCrank1, 0}}});
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
  HintPoint(m, "slider", "D", {kFrame6 - kSlideH, 0});
  return m;
}

Mechanism Chain(int loops) {
  using namespace bench_mechanisms;
  Mechanism m;
  m.name = "chain" + std::to_string(loops);
  // the first loop at phi = 0: A = (1, 0), B where |AB| = 3.5 and |B0 B| = 3, above A0B0
  const Eigen::Vector2d a(1, 0), b0(4, 0);
  const double dist = (b0 - a).norm(), along = (3.5 * 3.5 - 3.0 * 3.0 + dist * dist) / (2 * dist);
  const Eigen::Vector2d u = (b0 - a) / dist, n(-u.y(), u.x());
  const Eigen::Vector2d b = a + along * u + std::sqrt(3.5 * 3.5 - along * along) * n;
  const Eigen::Vector2d rocker_direction = (b - b0).normalized();
  PointList frame{{"A0", {0, 0}}};
  for (int i = 0; i < loops; ++i) frame.push_back({"P" + std::to_string(i), {4.0 * (i + 1), 0}});
  AddLink(m, "frame", frame, true);
  AddLink(m, "crank", {{"A0", {0, 0}}, {"A", {1, 0}}});
  AddLink(m, "coupler0", {{"A", {0, 0}}, {"B", {3.5, 0}}});
  AddLink(m, "rocker0", {{"P0", {0, 0}}, {"B", {3, 0}}, {"D", {2.5, 0}}});
  Revolute(m, "A0", "frame", "crank");
  Revolute(m, "A", "crank", "coupler0");
  Revolute(m, "B", "coupler0", "rocker0");
  Revolute(m, "P0", "frame", "rocker0");
  HintPoint(m, "coupler0", "B", b);
  for (int i = 1; i < loops; ++i) {
    const std::string k = std::to_string(i), previous = std::to_string(i - 1);
    AddLink(m, "coupler" + k, {{"D" + previous, {0, 0}}, {"C" + k, {4, 0}}});
    AddLink(m, "rocker" + k, {{"P" + k, {0, 0}}, {"C" + k, {2.5, 0}}, {"D", {2.5, 0}}});
    Revolute(m, "D" + previous, "rocker" + previous, "coupler" + k, "D", "D" + previous);
    Revolute(m, "C" + k, "coupler" + k, "rocker" + k);
    Revolute(m, "P" + k, "frame", "rocker" + k);
    HintPoint(m, "rocker" + k, "C" + k, Eigen::Vector2d(4.0 * (i + 1), 0) + 2.5 * rocker_direction);
  }
  SetDrive(m, "A0");
  LinkAngleOutput(m, "psi", "rocker" + std::to_string(loops - 1));
  return m;
}

FourBarValues SeedFourBarClosedForm(double phi) {
  using namespace bench_mechanisms;
  const double ca = std::cos(phi), sa = std::sin(phi);
  const double ax = kL1 * ca, ay = kL1 * sa;
  // B by circle intersection, left of A -> B0
  const double dx = kL4 - ax, dy = -ay, d2 = dx * dx + dy * dy, d = std::sqrt(d2);
  const double along = (kL2 * kL2 - kL3 * kL3 + d2) / (2 * d), across = std::sqrt(kL2 * kL2 - along * along);
  const double ux = dx / d, uy = dy / d;
  const double bx = ax + along * ux - across * uy, by = ay + along * uy + across * ux;
  const double ct = (bx - ax) / kL2, st = (by - ay) / kL2;      // coupler angle theta
  const double cp = (bx - kL4) / kL3, sp = by / kL3;             // rocker angle psi
  const double sg = st * cp - ct * sp, cg = ct * cp + st * sp;  // gamma = theta - psi
  // first order: the loop's derivative times e^{-i psi}, e^{-i theta}
  const double t1 = -kL1 * (sa * cp - ca * sp) / (kL2 * sg);
  const double p1 = -kL1 * (sa * ct - ca * st) / (kL3 * sg);
  // second order: R = -l1 e^{i phi} - l2 theta'^2 e^{i theta} + l3 psi'^2 e^{i psi}
  const double rx = -kL1 * ca - kL2 * t1 * t1 * ct + kL3 * p1 * p1 * cp;
  const double ry = -kL1 * sa - kL2 * t1 * t1 * st + kL3 * p1 * p1 * sp;
  const double t2 = (rx * cp + ry * sp) / (kL2 * sg);
  const double p2 = (rx * ct + ry * st) / (kL3 * sg);
  // K = A + k e^{i (theta + kappa)}
  const double ck = std::cos(kKappa), sk = std::sin(kKappa);
  const double ex = ct * ck - st * sk, ey = st * ck + ct * sk;
  FourBarValues v;
  v.kx = {ax + kK * ex, -kL1 * sa - kK * t1 * ey, -kL1 * ca - kK * t2 * ey - kK * t1 * t1 * ex};
  v.ky = {ay + kK * ey, kL1 * ca + kK * t1 * ex, -kL1 * sa + kK * t2 * ex - kK * t1 * t1 * ey};
  v.psi = {std::atan2(sp, cp), p1, p2};
  // mu: the acute angle between the coupler and rocker lines
  const double sign = (sg * cg >= 0) ? 1.0 : -1.0;
  v.mu = {std::atan2(std::abs(sg), std::abs(cg)), sign * (t1 - p1), sign * (t2 - p2)};
  return v;
}

FourBarPoints SeedFourBarPositionsClosedForm(double phi) {
  using namespace bench_mechanisms;
  const double ax = kL1 * std::cos(phi), ay = kL1 * std::sin(phi);
  // B by circle intersection, left of A -> B0, as SeedFourBarClosedForm
  const double dx = kL4 - ax, dy = -ay, d2 = dx * dx + dy * dy, d = std::sqrt(d2);
  const double along = (kL2 * kL2 - kL3 * kL3 + d2) / (2 * d), across = std::sqrt(kL2 * kL2 - along * along);
  const double ux = dx / d, uy = dy / d;
  const double bx = ax + along * ux - across * uy, by = ay + along * uy + across * ux;
  // K = A + k e^{i kappa} turned by the coupler's direction (B - A) / l2
  const double ct = (bx - ax) / kL2, st = (by - ay) / kL2;
  const double kx = kK * std::cos(kKappa), ky = kK * std::sin(kKappa);
  return {bx, by, ax + ct * kx - st * ky, ay + st * kx + ct * ky};
}

SliderCrankValues SeedSliderCrankClosedForm(double phi) {
  using namespace bench_mechanisms;
  const double sa = std::sin(phi), ca = std::cos(phi);
  const double sp = (kOffset + kCrank * ca) / kCoupler, cp = std::sqrt(1 - sp * sp);  // coupler angle psi
  const double p1 = -kCrank * sa / (kCoupler * cp);
  const double p2 = (-kCrank * ca + kCoupler * sp * p1 * p1) / (kCoupler * cp);
  SliderCrankValues v;
  v.s = {kCrank * sa + kCoupler * cp, kCrank * ca - kCoupler * sp * p1, -kCrank * sa - kCoupler * cp * p1 * p1 - kCoupler * sp * p2};
  // mu = 90 deg - |psi|: between the coupler and the normal to the slide line
  const double sign = sp >= 0 ? -1.0 : 1.0;
  v.mu = {std::atan2(cp, std::abs(sp)), sign * p1, sign * p2};
  return v;
}

Jet SeedProportionalClosedForm(double phi) {
  using namespace bench_mechanisms;
  const double lambda = kCrank1 / kFrame6, c = kCrank1 * kSlideH / kFrame6;
  const double sa = std::sin(phi), ca = std::cos(phi), d = 1 - lambda * ca;
  return {c * sa / d, c * (ca - lambda) / (d * d), -c * sa * (1 - 2 * lambda * lambda + lambda * ca) / (d * d * d)};
}

}  // namespace koppel::bench

#include "support/closed_forms.hpp"

#include <algorithm>
#include <cmath>

namespace koppel::test {

SliderCrankValues SliderCrank(double l1, double l2, double e, double phi) {
  const double lambda = l1 / l2, eps = e / l2;
  const double sin_psi = -lambda * std::cos(phi) - eps;
  const double cos_psi = std::sqrt(1.0 - sin_psi * sin_psi);
  const double psi = std::atan2(sin_psi, cos_psi);
  SliderCrankValues v;
  v.s = l1 * (std::sin(phi) + cos_psi / lambda);
  v.s1 = l1 * std::cos(phi + psi) / cos_psi;
  v.s2 = -l1 * (std::sin(phi + psi) / cos_psi + lambda * std::pow(std::sin(phi), 2) / std::pow(cos_psi, 3));
  v.mu = M_PI / 2 - std::abs(psi);
  return v;
}

double SliderCrankPhiA(double l1, double l2, double e) { return M_PI / 2 + std::asin((e / l2) / (1 + l1 / l2)); }
double SliderCrankPhiI(double l1, double l2, double e) { return 3 * M_PI / 2 + std::asin((e / l2) / (1 - l1 / l2)); }

double ProportionalS(double l6, double l1, double h, double phi) {
  const double lambda = l1 / l6;
  return l1 * h / l6 * std::sin(phi) / (1 - lambda * std::cos(phi));
}

ProportionalValues Proportional(double l6, double l1, double h, double phi) {
  const double lambda = l1 / l6, c = l1 * h / l6, d = 1 - lambda * std::cos(phi);
  return {c * std::sin(phi) / d, c * (std::cos(phi) - lambda) / (d * d),
          -c * std::sin(phi) * (1 - 2 * lambda * lambda + lambda * std::cos(phi)) / (d * d * d)};
}

Eigen::Vector2d FourBarCouplerPoint(double l1, double l2, double l3, double l4, double k, double kappa, double phi, int side) {
  const Eigen::Vector2d a(l1 * std::cos(phi), l1 * std::sin(phi)), b0(l4, 0.0);
  const Eigen::Vector2d ab0 = b0 - a;
  const double d = ab0.norm();
  const double along = (l2 * l2 - l3 * l3 + d * d) / (2 * d);
  const double across = std::sqrt(l2 * l2 - along * along);
  const Eigen::Vector2d u = ab0 / d, n(-u.y(), u.x());
  const Eigen::Vector2d b = a + along * u + side * across * n;
  const Eigen::Vector2d w = (b - a).normalized();
  const Eigen::Vector2d turned(std::cos(kappa) * w.x() - std::sin(kappa) * w.y(), std::sin(kappa) * w.x() + std::cos(kappa) * w.y());
  return a + k * turned;
}

std::optional<RockerValues> FourBarRocker(double a, double b, double c, double d, double phi, int side) {
  const Eigen::Vector2d pa(a * std::cos(phi), a * std::sin(phi)), b0(d, 0.0);
  const Eigen::Vector2d ab0 = b0 - pa;
  const double dist = ab0.norm();
  if (dist > b + c || dist < std::abs(b - c) || dist == 0.0) return std::nullopt;
  const double along = (b * b - c * c + dist * dist) / (2 * dist);
  const double across = std::sqrt(std::max(0.0, b * b - along * along));
  const Eigen::Vector2d u = ab0 / dist, n(-u.y(), u.x());
  const Eigen::Vector2d pb = pa + along * u + side * across * n;
  const double psi = std::atan2(pb.y() - b0.y(), pb.x() - b0.x());
  const double theta = std::atan2(pb.y() - pa.y(), pb.x() - pa.x());
  return RockerValues{psi, a * std::sin(phi - theta) / (c * std::sin(psi - theta)), pb};
}

std::vector<double> FourBarLimits(double a, double b, double c, double d) {
  std::vector<double> limits;
  for (double r : {b + c, std::abs(b - c)}) {
    const double x = (a * a + d * d - r * r) / (2 * a * d);
    if (std::abs(x) >= 1) continue;
    const double phi = std::acos(x);
    limits.push_back(phi);
    limits.push_back(2 * M_PI - phi);
  }
  return limits;
}

std::optional<SlideValues> SliderCrankBranch(double l1, double l2, double e, double phi, int side) {
  const double ax = l1 * std::sin(phi), ay = -e - l1 * std::cos(phi);
  const double root2 = l2 * l2 - ay * ay;
  if (root2 <= 0) return std::nullopt;
  const double root = std::sqrt(root2);
  return SlideValues{ax + side * root, l1 * std::cos(phi) - side * ay * l1 * std::sin(phi) / root};
}

std::vector<double> SliderCrankLimits(double l1, double l2, double e) {
  std::vector<double> limits;
  for (double ay : {l2, -l2}) {
    const double x = (-e - ay) / l1;  // cos phi
    if (std::abs(x) >= 1) continue;
    const double phi = std::acos(x);
    limits.push_back(phi);
    limits.push_back(2 * M_PI - phi);
  }
  return limits;
}

namespace {

// phi and 2 pi - phi where cos phi = x; none outside (-1, 1)
std::vector<double> BothCrankAngles(double x) {
  if (!(std::abs(x) < 1)) return {};
  const double phi = std::acos(x);
  return {phi, 2 * M_PI - phi};
}

}  // namespace

std::vector<double> SliderCrankMuFolds(double l1, double e) { return BothCrankAngles(-e / l1); }

double CrankRockerMu(double a, double b, double c, double d, double phi) {
  const double e2 = a * a + d * d - 2 * a * d * std::cos(phi);
  const double gamma = std::acos((b * b + c * c - e2) / (2 * b * c));
  return std::min(gamma, M_PI - gamma);
}

std::vector<double> CrankRockerMuFolds(double a, double b, double c, double d) {
  return BothCrankAngles((a * a + d * d - b * b - c * c) / (2 * a * d));
}

CrankRockerDeadCentre CrankRockerExtended(double a, double b, double c, double d) {
  const double r = a + b;
  return {std::acos((r * r + d * d - c * c) / (2 * r * d)), M_PI - std::acos((c * c + d * d - r * r) / (2 * c * d))};
}

CrankRockerDeadCentre CrankRockerFolded(double a, double b, double c, double d) {
  const double r = b - a;
  return {M_PI + std::acos((r * r + d * d - c * c) / (2 * r * d)), M_PI - std::acos((c * c + d * d - r * r) / (2 * c * d))};
}

}  // namespace koppel::test

#include "koppel/synthesis/mzc_synthesis.hpp"

#include "koppel/analysis/coupler_curve.hpp"
#include "koppel/core/build.hpp"
#include "koppel/solver/sweep.hpp"

#include <cmath>

namespace koppel {

MzcDesign MzcFromLambda(double lambda, double D) {
  MzcDesign d;
  d.lambda = lambda;
  d.D = D;
  if (!(lambda >= 0.5 && lambda <= 1.5) || !(D > 0)) {
    d.status = DesignStatus::kInvalidRequest;
    d.message = "needs 0.5 <= lambda <= 1.5 and D > 0";
    return d;
  }
  const double s2 = (1 + 2 * lambda) / 4;  // six-point condition
  if (s2 >= 1 || lambda - s2 <= 0) {
    d.status = DesignStatus::kNoDesign;
    d.message = "lambda = " + std::to_string(lambda) + " gives no six-point linkage (lambda - sin^2 phi0 must be > 0)";
    return d;
  }
  d.phi0 = std::asin(std::sqrt(s2));
  const double s = std::sin(d.phi0), c = std::cos(d.phi0);
  d.l1 = d.l3 = lambda * lambda * D / (s * (lambda - s2));
  d.l2 = 2 * lambda * D * c / s;
  d.l4 = 2 * lambda * D * c * s / (lambda - s2);
  d.k = D / std::sqrt(1 + 2 * lambda);
  d.kappa = std::atan((1 - lambda) / lambda * std::sqrt((1 + 2 * lambda) / (3 - 2 * lambda)));
  // crossed symmetric position: A' = (l2/2, H), B' = (-l2/2, H) with |A0'A'| = l1
  const double span = 0.5 * (d.l2 + d.l4);
  if (d.l1 <= span) {
    d.status = DesignStatus::kNoDesign;
    d.message = "the rockers are too short for the crossed position";
    return d;
  }
  const double height = std::sqrt(d.l1 * d.l1 - span * span);
  d.pole_height = height * (0.5 * d.l4) / span;  // where A0'A' crosses the symmetry axis
  d.status = DesignStatus::kOk;
  return d;
}

std::string MzcDesign::Brief() const {
  return std::string(ToString(status)) + (ok() ? ": l1 = " + std::to_string(l1) + ", l2 = " + std::to_string(l2) + ", l4 = " + std::to_string(l4)
                                              : ": " + message);
}

Expected<double> LambdaFromKappa(double kappa) {
  // f(lambda) = lambda^2 (3 - 2 lambda) - cos^2 kappa rises on [0, 1] from -cos^2 to 1 - cos^2:
  // the root in (0.5, 1] belongs to kappa in [0, kappa(0.5)); beyond 1, kappa turns negative.
  const double target = std::pow(std::cos(kappa), 2);
  auto f = [&](double l) { return l * l * (3 - 2 * l) - target; };
  double lo = 0.5, hi = 1.0;
  if (f(lo) > 0 || f(hi) < 0) return Expected<double>::Error("no lambda in [0.5, 1] for this kappa");
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Mechanism MzcMechanism(const MzcDesign& d) {
  Mechanism m;
  m.name = "mzc-straight-line";
  const double span = 0.5 * (d.l2 + d.l4), height = std::sqrt(d.l1 * d.l1 - span * span);
  const Eigen::Vector2d a0(-0.5 * d.l4, 0), b0(0.5 * d.l4, 0), a(0.5 * d.l2, height), b(-0.5 * d.l2, height);
  // K: the inflection pole W, a diameter D from the velocity pole P (where the rocker lines
  // cross on the symmetry axis) along the pole normal, away from the frame. A'K = k' follows.
  const Eigen::Vector2d k(0, d.pole_height + d.D);
  auto along = [](const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Eigen::Vector2d& p) {
    const Eigen::Vector2d u = (to - from).normalized(), n(-u.y(), u.x());
    return Eigen::Vector2d((p - from).dot(u), (p - from).dot(n));
  };
  AddLink(m, "frame", {{"A0", a0}, {"B0", b0}}, true);
  AddLink(m, "rocker1", {{"A0", {0, 0}}, {"A", {d.l1, 0}}});
  AddLink(m, "coupler", {{"A", {0, 0}}, {"B", {d.l2, 0}}, {"K", along(a, b, k)}});
  AddLink(m, "rocker2", {{"B0", {0, 0}}, {"B", {d.l3, 0}}});
  Revolute(m, "A0", "frame", "rocker1");
  Revolute(m, "A", "rocker1", "coupler");
  Revolute(m, "B", "coupler", "rocker2");
  Revolute(m, "B0", "frame", "rocker2");
  SetDrive(m, "A0");
  PointOutput(m, "K", "coupler", "K");
  HintInput(m, std::atan2(a.y() - a0.y(), a.x() - a0.x()));
  HintPoint(m, "coupler", "A", a);
  HintPoint(m, "coupler", "B", b);
  HintPoint(m, "rocker2", "B", b);
  HintPoint(m, "rocker1", "A", a);
  return m;
}

int TangentContactOrder(const Mechanism& m, const PointRef& point, double at, double tolerance) {
  const Mechanism traced = WithPointOutput(m, point);
  SweepOptions here;
  here.from = here.to = at;
  here.order = kMaxOrder;
  const SweepResult r = Sweep(traced, here);
  if (!r.complete()) return -1;
  // columns: x, x', ..., x^(8), y, y', ..., y^(8); normal component of each derivative
  const int n = kMaxOrder + 1;
  const Eigen::Vector2d tangent(r.outputs(0, 1), r.outputs(0, n + 1));
  if (tangent.norm() == 0) return -1;
  const Eigen::Vector2d normal = Eigen::Vector2d(-tangent.y(), tangent.x()).normalized();
  const double scale = tangent.norm();
  for (int k = 2; k <= kMaxOrder; ++k) {
    const double across = normal.dot(Eigen::Vector2d(r.outputs(0, k), r.outputs(0, n + k)));
    // relative to |K'|^k so that the measure does not depend on the input's scale
    if (std::abs(across) > tolerance * std::pow(scale, k)) return k;
  }
  return kMaxOrder + 1;
}

}  // namespace koppel

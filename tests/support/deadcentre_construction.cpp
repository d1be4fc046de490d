#include "support/deadcentre_construction.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace koppel::test {
namespace {

using Eigen::Vector2d;

Vector2d Direction(double angle) { return {std::cos(angle), std::sin(angle)}; }
double Cross(const Vector2d& a, const Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// p + t u = q + w v
Vector2d LineIntersection(const Vector2d& p, const Vector2d& u, const Vector2d& q, const Vector2d& v) {
  return p + u * (Cross(q - p, v) / Cross(u, v));
}

// The intersection of the circle (centre, radius) with the line through p along u that is
// farther from `known` (the other one is `known` itself).
Vector2d OtherOnLine(const Vector2d& centre, double radius, const Vector2d& p, Vector2d u, const Vector2d& known) {
  u.normalize();
  const Vector2d f = p - centre;
  const double b = f.dot(u), c = f.squaredNorm() - radius * radius, root = std::sqrt(std::max(b * b - c, 0.0));
  const Vector2d x1 = p + (-b + root) * u, x2 = p + (-b - root) * u;
  return (x1 - known).norm() > (x2 - known).norm() ? x1 : x2;
}

}  // namespace

DocumentConstruction Construct(double phi0, double psi0, int s, double d) {
  const double pi = std::acos(-1.0);
  DocumentConstruction c;
  const Vector2d a0(0, 0), b0(d, 0);
  c.pole = LineIntersection(a0, Direction(phi0 / 2), b0, Direction(s * psi0 / 2));
  c.m_a = c.pole / 2;
  // M_b on B0P and on the perpendicular bisector of A0P (equidistant from A0 and P)
  c.m_b = LineIntersection(b0, c.pole - b0, c.m_a, Vector2d(-c.pole.y(), c.pole.x()));
  c.r_b = c.m_b.norm();
  // L: the circle about P through A0 meets k_b again at A0's mirror image in the line P M_b
  const Vector2d axis = (c.m_b - c.pole).normalized();
  c.l = c.pole + 2 * (-c.pole).dot(axis) * axis - (-c.pole);
  if (std::abs(phi0 - pi) < 1e-12) c.e = b0;
  else if (phi0 < pi) c.e = PointEOnLineLB0(c, d);
  else c.e = OtherOnLine(c.m_b, c.r_b, a0, Vector2d(1, 0), a0);
  return c;
}

Vector2d PointEOnLineLB0(const DocumentConstruction& c, double d) { return OtherOnLine(c.m_b, c.r_b, c.l, Vector2d(d, 0) - c.l, c.l); }

ConstructedDesign DesignOnRay(const DocumentConstruction& c, double phi_a, double d) {
  const Vector2d u = Direction(phi_a);
  ConstructedDesign r;
  const double rho_a = 2 * c.m_b.dot(u);  // chord of k_b from A0 along u
  r.l1 = c.pole.dot(u);                   // A_a: the foot of the perpendicular from P (Thales on A0P)
  r.l2 = rho_a - r.l1;
  r.b_a = rho_a * u;
  r.l3 = (r.b_a - Vector2d(d, 0)).norm();
  return r;
}

std::optional<FourBarTurn> TurnFourBar(double l1, double l2, double l3, double d, double phi_a, const Vector2d& b_a, int samples) {
  const double pi = std::acos(-1.0);
  const Vector2d b0(d, 0);
  // the branch: the side of B against the line A -> B0, taken in the extended dead centre
  const Vector2d a_start = l1 * Direction(phi_a);
  const double side = Cross(b0 - a_start, b_a - a_start) > 0 ? 1.0 : -1.0;
  // the rocker angle at crank angle phi by circle intersection, nullopt where it does not assemble
  auto rocker = [&](double phi) -> std::optional<double> {
    const Vector2d a = l1 * Direction(phi), ab0 = b0 - a;
    const double r = ab0.norm(), along = (l2 * l2 - l3 * l3 + r * r) / (2 * r), h2 = l2 * l2 - along * along;
    if (h2 < 0) return std::nullopt;
    const Vector2d n = ab0 / r, b = a + along * n + side * std::sqrt(h2) * Vector2d(-n.y(), n.x());
    return std::atan2(b.y() - b0.y(), b.x() - b0.x());
  };
  std::vector<double> psi(samples), phi(samples);
  for (int k = 0; k < samples; ++k) {
    phi[k] = phi_a + 2 * pi * k / samples;
    const std::optional<double> p = rocker(phi[k]);
    if (!p) return std::nullopt;
    psi[k] = *p;
  }
  FourBarTurn t;
  // mu is extreme with the crank along the frame line, |AB0| = d -+ l1 (law of cosines)
  t.mu_min = pi;
  for (const double r : {d - l1, d + l1}) {
    const double mu = std::acos(std::clamp((l2 * l2 + l3 * l3 - r * r) / (2 * l2 * l3), -1.0, 1.0));
    t.mu_min = std::min(t.mu_min, std::min(mu, pi - mu));
  }
  // the rocker's extremes: the best samples (its angle relative to the first sample, which a
  // rocker never turns half a turn away from), then golden section between their neighbours
  auto relative = [&](double angle) { return std::remainder(angle - psi[0], 2 * pi); };
  int kmax = 0, kmin = 0;
  for (int k = 1; k < samples; ++k) {
    if (relative(psi[k]) > relative(psi[kmax])) kmax = k;
    if (relative(psi[k]) < relative(psi[kmin])) kmin = k;
  }
  auto refine = [&](int k, double sign, double* value, double* at) {
    const double h = 2 * pi / samples, g = 0.5 * (std::sqrt(5.0) - 1);
    auto f = [&](double x) { return sign * relative(rocker(x).value_or(psi[k])); };
    double a = phi[k] - h, b = phi[k] + h;
    while (b - a > 1e-13) {
      const double c = b - g * (b - a), e = a + g * (b - a);
      if (f(c) >= f(e)) b = e;
      else a = c;
    }
    *at = 0.5 * (a + b);
    *value = psi[0] + sign * f(*at);
  };
  refine(kmax, 1.0, &t.psi_max, &t.phi_at_max);
  refine(kmin, -1.0, &t.psi_min, &t.phi_at_min);
  return t;
}

}  // namespace koppel::test

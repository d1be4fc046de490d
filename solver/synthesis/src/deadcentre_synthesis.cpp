#include "koppel/synthesis/deadcentre_synthesis.hpp"

#include <cmath>
#include <complex>
#include <functional>

namespace koppel {
namespace {

using Complex = std::complex<double>;
constexpr double kPi = 3.14159265358979323846;

// Transmission angle folded to [0, pi/2] from the law of cosines in triangle A B B0, with
// a0b the distance A B0.
double FoldedMu(double l2, double l3, double ab0) {
  const double c = (l2 * l2 + l3 * l3 - ab0 * ab0) / (2 * l2 * l3);
  const double mu = std::acos(std::clamp(c, -1.0, 1.0));
  return std::min(mu, kPi - mu);
}

// Maximises f over [lo, hi]: a scan at `samples` points, then golden section around the best.
double Maximise(const std::function<double(double)>& f, double lo, double hi, int samples) {
  double best_x = lo, best = -1e300;
  for (int i = 0; i <= samples; ++i) {
    const double x = lo + (hi - lo) * i / samples;
    const double v = f(x);
    if (v > best) {
      best = v;
      best_x = x;
    }
  }
  const double h = (hi - lo) / samples;
  double a = std::max(lo, best_x - h), b = std::min(hi, best_x + h);
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  for (int it = 0; it < 200 && b - a > 1e-12; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (f(c) >= f(d)) b = d; else a = c;
  }
  const double x = 0.5 * (a + b);
  return f(x) >= best ? x : best_x;
}

}  // namespace

CrankRockerDesign CrankRockerFromDeadCentres(double phi0, double psi0, double beta, double d) {
  CrankRockerDesign r;
  r.phi0 = phi0;
  r.psi0 = psi0;
  r.beta = beta;
  r.l4 = d;
  // B_a on the ray at beta, B_i on the ray at beta - phi0 + pi (the crank points away from B_i
  // in the folded dead centre); B_a - B0 = R(-psi0) (B_i - B0). Linear in the two distances.
  const Complex ua = std::polar(1.0, beta), ui = std::polar(1.0, beta - phi0 + kPi), rot = std::polar(1.0, -psi0);
  const Complex b0(d, 0.0), rhs = b0 - rot * b0, c2 = -rot * ui;
  const double det = ua.real() * c2.imag() - ua.imag() * c2.real();
  if (std::abs(det) < 1e-14) {
    r.message = "the dead-centre rays are parallel: no solution for this beta";
    return r;
  }
  const double rho_a = (rhs.real() * c2.imag() - rhs.imag() * c2.real()) / det;
  const double rho_i = (ua.real() * rhs.imag() - ua.imag() * rhs.real()) / det;
  r.l1 = 0.5 * (rho_a - rho_i);
  r.l2 = 0.5 * (rho_a + rho_i);
  r.l3 = std::abs(rho_a * ua - b0);
  if (!(rho_i > 0 && r.l1 > 0)) {
    r.message = "beta lies outside the arc LE: B_a does not give a crank-rocker";
    return r;
  }
  // a crank-rocker needs the crank shortest and Grashof's condition
  const double longest = std::max({r.l2, r.l3, r.l4});
  if (r.l1 > std::min({r.l2, r.l3, r.l4}) || r.l1 + longest > r.l2 + r.l3 + r.l4 - longest) {
    r.message = "the dimensions do not make a crank-rocker (Grashof)";
    return r;
  }
  // mu is extreme where the crank lies along the frame line (A B0 = d - l1 and d + l1)
  const double mu_0 = FoldedMu(r.l2, r.l3, d - r.l1), mu_pi = FoldedMu(r.l2, r.l3, d + r.l1);
  r.mu_min = std::min(mu_0, mu_pi);
  r.mu_min_at = mu_0 <= mu_pi ? 0.0 : kPi;
  r.ok = true;
  return r;
}

CrankRockerDesign BestCrankRocker(double phi0, double psi0, double d) {
  auto score = [&](double beta) {
    const CrankRockerDesign r = CrankRockerFromDeadCentres(phi0, psi0, beta, d);
    return r.ok ? r.mu_min : -1.0;
  };
  const double beta = Maximise(score, 1e-6, kPi - 1e-6, 1800);
  CrankRockerDesign r = CrankRockerFromDeadCentres(phi0, psi0, beta, d);
  if (!r.ok) r.message = "no beta gives a crank-rocker with these dead-centre angles";
  return r;
}

SliderCrankDesign SliderCrankFromDeadCentres(double phi0, double stroke, double e) {
  SliderCrankDesign r;
  r.phi0 = phi0;
  r.stroke = stroke;
  r.e = e;
  const double theta = std::abs(phi0 - kPi);  // angle between the rays A0B_a and A0B_i
  if (stroke <= 0 || e < 0) {
    r.message = "the stroke must be positive and the offset not negative";
    return r;
  }
  // B_i = (x, e), B_a = (x + s0, e). B stays on one side of A (the coupler never turns past the
  // normal to the slide), and in the folded dead centre B_i - A = l2 u_i, so x > 0; there the
  // angle between the rays falls monotonically from pi/2 - atan(e/s0) to 0: bisection.
  auto gap = [&](double x) { return std::atan2(e, x) - std::atan2(e, x + stroke) - theta; };
  double lo = 0.0, hi = 1e6 * stroke;
  if (e == 0.0 || gap(lo) < 0) {
    r.message = e == 0.0 ? "without offset the dead centres are 180 deg apart: phi0 must be 180 deg"
                         : "the offset is too large for this phi0 and stroke";
    if (e == 0.0 && std::abs(theta) < 1e-12) {
      r.l1 = stroke / 2;
      r.message = "choose the coupler freely: e = 0 fixes only l1 = s0/2";
    }
    return r;
  }
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (gap(mid) > 0 ? lo : hi) = mid;
  }
  const double x = 0.5 * (lo + hi);
  const double rho_i = std::hypot(x, e), rho_a = std::hypot(x + stroke, e);
  r.l1 = 0.5 * (rho_a - rho_i);
  r.l2 = 0.5 * (rho_a + rho_i);
  r.beta = std::atan2(e, x + stroke);
  if ((r.l1 + e) / r.l2 >= 1) {
    r.message = "the crank cannot turn fully (l2 - l1 <= e)";
    return r;
  }
  // seed 000: mu = 90 deg - |psi|, sin|psi| = |lambda cos phi + eps|, smallest at phi = 0
  r.mu_min = kPi / 2 - std::asin((r.l1 + e) / r.l2);
  r.mu_min_at = 0.0;
  r.ok = true;
  return r;
}

SliderCrankDesign BestSliderCrank(double phi0, double stroke) {
  auto score = [&](double e) {
    const SliderCrankDesign r = SliderCrankFromDeadCentres(phi0, stroke, e);
    return r.ok ? r.mu_min : -1.0;
  };
  const double e = Maximise(score, 1e-9 * stroke, 2 * stroke, 4000);
  SliderCrankDesign r = SliderCrankFromDeadCentres(phi0, stroke, e);
  if (!r.ok) r.message = "no offset gives a slider-crank with these dead centres";
  return r;
}

SliderCrankDesign SliderCrankFromBeta(double phi0, double stroke, double beta) {
  const double theta = std::abs(phi0 - kPi);
  const double denominator = 1 / std::tan(beta) - 1 / std::tan(beta + theta);
  if (!(beta > 0) || !(beta + theta < kPi / 2) || !(denominator > 0)) {
    SliderCrankDesign r;
    r.phi0 = phi0;
    r.stroke = stroke;
    r.beta = beta;
    r.message = "beta must be positive and beta + |phi0 - 180 deg| below 90 deg";
    return r;
  }
  return SliderCrankFromDeadCentres(phi0, stroke, stroke / denominator);
}

Mechanism CrankRockerMechanism(const CrankRockerDesign& d) {
  Mechanism m;
  m.name = "crank-rocker";
  m.links = {{"frame", true, {{"A0", {0, 0}}, {"B0", {d.l4, 0}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {d.l1, 0}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {d.l2, 0}}}},
             {"rocker", false, {{"B0", {0, 0}}, {"B", {d.l3, 0}}}}};
  m.joints = {PinJoint(m, "A0", 0, 1), PinJoint(m, "A", 1, 2), PinJoint(m, "B", 2, 3), PinJoint(m, "B0", 0, 3)};
  m.drive.joint = 0;
  Output psi;
  psi.name = "psi";
  psi.kind = OutputKind::kLinkAngle;
  psi.link = 3;
  Output mu;
  mu.name = "mu";
  mu.kind = OutputKind::kTransmissionAngle;
  mu.link = 2;
  mu.joint = 2;
  m.outputs = {psi, mu};
  // assemble in the extended dead centre: B_a on the ray at beta
  m.hint.input = d.beta;
  const Eigen::Vector2d ba = (d.l1 + d.l2) * Eigen::Vector2d(std::cos(d.beta), std::sin(d.beta));
  m.hint.points = {{{2, 1}, ba}, {{3, 1}, ba}};
  return m;
}

Mechanism SliderCrankMechanism(const SliderCrankDesign& d) {
  Mechanism m;
  m.name = "slider-crank";
  m.links = {{"frame", true, {{"A0", {0, -d.e}}, {"F", {0, 0}}}},
             {"crank", false, {{"A0", {0, 0}}, {"A", {0, -d.l1}}}},
             {"coupler", false, {{"A", {0, 0}}, {"B", {d.l2, 0}}}},
             {"slider", false, {{"B", {0, 0}}}}};
  m.joints = {PinJoint(m, "A0", 0, 1), PinJoint(m, "A", 1, 2), PinJoint(m, "B", 2, 3)};
  Joint s;
  s.name = "S";
  s.type = JointType::kPrismatic;
  s.link_a = 0;
  s.link_b = 3;
  s.point_a = 1;
  s.point_b = 0;
  m.joints.push_back(s);
  m.drive.joint = 0;
  Output out;
  out.name = "s";
  out.kind = OutputKind::kJoint;
  out.joint = 3;
  Output mu;
  mu.name = "mu";
  mu.kind = OutputKind::kTransmissionAngle;
  mu.link = 2;
  mu.joint = 2;
  m.outputs = {out, mu};
  m.hint.input = 0;
  m.hint.points = {{{3, 0}, {std::sqrt(std::max(d.l2 * d.l2 - std::pow(d.e + d.l1, 2), 0.0)), 0.0}}};
  return m;
}

}  // namespace koppel

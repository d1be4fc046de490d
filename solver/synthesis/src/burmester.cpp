#include "koppel/synthesis/burmester.hpp"

#include "koppel/core/angles.hpp"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <functional>

namespace koppel {
namespace {

// A dyad meets the poses when its circle point's distance from the centre point varies by at
// most this, relative to the poses' size: the 1e-9, far above the ~1e-14 of the solves.
constexpr double kDyadTolerance = 1e-9;

Eigen::Matrix2d Rotation(double angle) {
  Eigen::Matrix2d r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return r;
}

// The poses moved to their centroid, scaled to size 1 and turned by `turn`, so that every
// polynomial below has coefficients of order one; Back() undoes it for a point.
struct Normalised {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  double scale = 1, turn = 0;
  std::vector<Pose> poses;
  Eigen::Vector2d Back(const Eigen::Vector2d& x) const { return centroid + scale * (Rotation(-turn) * x); }
  Eigen::Vector2d To(const Eigen::Vector2d& x) const { return Rotation(turn) * (x - centroid) / scale; }
};

Normalised Normalise(const std::vector<Pose>& poses, double turn) {
  Normalised n;
  for (const Pose& p : poses) n.centroid += p.point / static_cast<double>(poses.size());
  n.scale = PoseScale(poses);
  n.turn = turn;
  for (const Pose& p : poses) n.poses.push_back({n.To(p.point), p.angle + turn});
  return n;
}

// The condition of pose j against the first one, |A_j - M|^2 - |A_1 - M|^2 = 0 with
// A_j = R_j A + D_j, written both ways round:
//   for fixed M:  g(M) . A = h(M),  g = 2 (R^T D + (I - R^T) M),  h = 2 D.M - |D|^2;
//   for fixed A:  k(A) . M = l(A),  k = 2 ((I - R) A - D),         l = -(2 (R A).D + |D|^2).
struct Condition {
  Eigen::Matrix2d r;
  Eigen::Vector2d d;
  Eigen::Vector2d G(const Eigen::Vector2d& m) const { return 2 * (r.transpose() * d + (Eigen::Matrix2d::Identity() - r.transpose()) * m); }
  double H(const Eigen::Vector2d& m) const { return 2 * d.dot(m) - d.squaredNorm(); }
  Eigen::Vector2d K(const Eigen::Vector2d& a) const { return 2 * ((Eigen::Matrix2d::Identity() - r) * a - d); }
  double L(const Eigen::Vector2d& a) const { return -(2 * (r * a).dot(d) + d.squaredNorm()); }
  double Residual(const Eigen::Vector2d& m, const Eigen::Vector2d& a) const { return G(m).dot(a) - H(m); }
};

std::vector<Condition> Conditions(const std::vector<Pose>& poses) {
  std::vector<Condition> c;
  for (size_t j = 1; j < poses.size(); ++j) {
    Condition k;
    k.r = Rotation(poses[j].angle - poses[0].angle);
    k.d = poses[j].point - k.r * poses[0].point;
    c.push_back(k);
  }
  return c;
}

// Polynomials in one variable, coefficients from degree 0 up.
using Poly = std::vector<double>;

Poly Mul(const Poly& a, const Poly& b) {
  Poly c(a.size() + b.size() - 1, 0.0);
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}
Poly Add(Poly a, const Poly& b, double sign = 1) {
  a.resize(std::max(a.size(), b.size()), 0.0);
  for (size_t i = 0; i < b.size(); ++i) a[i] += sign * b[i];
  return a;
}

// The roots of a polynomial as eigenvalues of its companion matrix, after dropping leading
// coefficients below `negligible` of the largest (the degree a generic problem does not reach).
std::vector<std::complex<double>> Roots(Poly p, double negligible = 1e-10) {
  double largest = 0;
  for (double c : p) largest = std::max(largest, std::abs(c));
  while (!p.empty() && std::abs(p.back()) <= negligible * largest) p.pop_back();
  const int n = static_cast<int>(p.size()) - 1;
  if (n < 1) return {};
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) companion(0, i) = -p[n - 1 - i] / p[n];
  for (int i = 1; i < n; ++i) companion(i, i - 1) = 1;
  const Eigen::EigenSolver<Eigen::MatrixXd> eigen(companion, false);
  std::vector<std::complex<double>> roots;
  for (int i = 0; i < n; ++i) roots.push_back(eigen.eigenvalues()[i]);
  return roots;
}

// 3x3 determinant of polynomial entries.
Poly Det3(const std::array<std::array<Poly, 3>, 3>& e) {
  Poly det{0.0};
  for (int c = 0; c < 3; ++c) {
    const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
    det = Add(det, Mul(e[0][c], Add(Mul(e[1][c1], e[2][c2]), Mul(e[1][c2], e[2][c1]), -1)));
  }
  return det;
}

// The centre-point condition of three pose pairs along the line M = base + t dir: the
// determinant of [g_j | h_j], a cubic in t.
Poly LineDeterminant(const std::vector<Condition>& c, const std::array<int, 3>& rows, const Eigen::Vector2d& base, const Eigen::Vector2d& dir) {
  std::array<std::array<Poly, 3>, 3> e;
  for (int i = 0; i < 3; ++i) {
    const Condition& k = c[rows[i]];
    const Eigen::Vector2d g0 = k.G(base), g1 = k.G(base + dir) - g0;
    const double h0 = k.H(base), h1 = k.H(base + dir) - h0;
    e[i] = {Poly{g0.x(), g1.x()}, Poly{g0.y(), g1.y()}, Poly{h0, h1}};
  }
  return Det3(e);
}

// The circle point of centre point m: least squares over every condition.
Eigen::Vector2d CirclePointOf(const std::vector<Condition>& c, const Eigen::Vector2d& m) {
  Eigen::MatrixXd a(c.size(), 2);
  Eigen::VectorXd rhs(c.size());
  for (size_t j = 0; j < c.size(); ++j) {
    a.row(j) = c[j].G(m).transpose();
    rhs[j] = c[j].H(m);
  }
  return a.colPivHouseholderQr().solve(rhs);
}

// The pole of the pair of poses with the largest rotation between them; false for translations only.
bool LargestRotationPole(const std::vector<Pose>& poses, Eigen::Vector2d* pole) {
  double best = 0;
  for (size_t i = 0; i < poses.size(); ++i) {
    for (size_t j = i + 1; j < poses.size(); ++j) {
      const double s = std::abs(std::sin((poses[j].angle - poses[i].angle) / 2));
      if (s <= best) continue;
      best = s;
      // the fixed point of the motion i -> j: (I - R) P = P_j - R P_i
      const Eigen::Matrix2d r = Rotation(poses[j].angle - poses[i].angle);
      *pole = (Eigen::Matrix2d::Identity() - r).inverse() * (poses[j].point - r * poses[i].point);
    }
  }
  return best > 1e-6;
}

// Bivariate cubics in (x, y): coefficient [i][j] of x^i y^j.
using Bi = std::array<std::array<double, 4>, 4>;
Bi BiMul(const Bi& a, const Bi& b) {
  Bi c{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; i + j < 4; ++j)
      for (int k = 0; i + k < 4; ++k)
        for (int l = 0; j + l < 4 && i + k + j + l < 4; ++l) c[i + k][j + l] += a[i][j] * b[k][l];
  return c;
}
Bi BiAdd(Bi a, const Bi& b, double sign = 1) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) a[i][j] += sign * b[i][j];
  return a;
}
Bi Linear(double c, double cx, double cy) {
  Bi b{};
  b[0][0] = c;
  b[1][0] = cx;
  b[0][1] = cy;
  return b;
}

// The centre-point curve of the conditions `rows` as a bivariate cubic.
Bi CentreCubic(const std::vector<Condition>& c, const std::array<int, 3>& rows) {
  std::array<std::array<Bi, 3>, 3> e;
  const Eigen::Vector2d ex(1, 0), ey(0, 1), o(0, 0);
  for (int i = 0; i < 3; ++i) {
    const Condition& k = c[rows[i]];
    const Eigen::Vector2d g0 = k.G(o), gx = k.G(ex) - g0, gy = k.G(ey) - g0;
    const double h0 = k.H(o), hx = k.H(ex) - h0, hy = k.H(ey) - h0;
    e[i] = {Linear(g0.x(), gx.x(), gy.x()), Linear(g0.y(), gx.y(), gy.y()), Linear(h0, hx, hy)};
  }
  Bi det{};
  for (int col = 0; col < 3; ++col) {
    const int c1 = (col + 1) % 3, c2 = (col + 2) % 3;
    det = BiAdd(det, BiMul(e[0][col], BiAdd(BiMul(e[1][c1], e[2][c2]), BiMul(e[1][c2], e[2][c1]), -1)));
  }
  return det;
}

// The cubic at x as a polynomial in y.
Poly InY(const Bi& b, double x) {
  Poly p(4, 0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; i + j < 4; ++j) p[j] += b[i][j] * std::pow(x, i);
  return p;
}
// Sylvester resultant in y of two cubics at x.
double ResultantAt(const Bi& c1, const Bi& c2, double x) {
  const Poly a = InY(c1, x), b = InY(c2, x);
  Eigen::Matrix<double, 6, 6> s = Eigen::Matrix<double, 6, 6>::Zero();
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 4; ++k) {
      s(r, r + k) = a[3 - k];
      s(r + 3, r + k) = b[3 - k];
    }
  }
  return s.determinant();
}

// Newton on every condition in (M, A); true when it converges.
bool PolishDyad(const std::vector<Condition>& c, Eigen::Vector2d* m, Eigen::Vector2d* a) {
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::MatrixXd jac(c.size(), 4);
    Eigen::VectorXd f(c.size());
    for (size_t j = 0; j < c.size(); ++j) {
      f[j] = c[j].Residual(*m, *a);
      jac.block<1, 2>(j, 0) = c[j].K(*a).transpose();  // d/dM
      jac.block<1, 2>(j, 2) = c[j].G(*m).transpose();  // d/dA
    }
    if (f.lpNorm<Eigen::Infinity>() < 1e-15) return true;
    const Eigen::VectorXd step = jac.colPivHouseholderQr().solve(-f);
    if (!step.allFinite()) return false;
    *m += step.head<2>();
    *a += step.tail<2>();
    if (m->norm() > 1e6 || a->norm() > 1e6) return false;
    if (step.norm() < 1e-15) return true;
  }
  Eigen::VectorXd f(c.size());
  for (size_t j = 0; j < c.size(); ++j) f[j] = c[j].Residual(*m, *a);
  return f.lpNorm<Eigen::Infinity>() < 1e-12;
}

}  // namespace

const char* ToString(BurmesterStatus status) {
  switch (status) {
    case BurmesterStatus::kOk: return "ok";
    case BurmesterStatus::kInvalidRequest: return "invalid request";
    case BurmesterStatus::kNoSolution: return "no solution";
  }
  return "?";
}

Eigen::Vector2d MovePoint(const Pose& from, const Pose& to, const Eigen::Vector2d& global) {
  return to.point + Rotation(to.angle - from.angle) * (global - from.point);
}

double PoseScale(const std::vector<Pose>& poses) {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const Pose& p : poses) centroid += p.point / static_cast<double>(poses.size());
  double scale = 0;
  for (const Pose& p : poses) scale = std::max(scale, (p.point - centroid).norm());
  return scale > 0 ? scale : 1.0;
}

double DyadResidual(const std::vector<Pose>& poses, const Dyad& dyad) {
  const double r1 = (dyad.circle - dyad.centre).norm();
  double worst = 0;
  for (size_t j = 1; j < poses.size(); ++j)
    worst = std::max(worst, std::abs((MovePoint(poses[0], poses[j], dyad.circle) - dyad.centre).norm() - r1));
  return worst;
}

CentrePointResult CentrePoint(const std::vector<Pose>& poses, const Eigen::Vector2d& circle_point) {
  CentrePointResult r;
  if (poses.size() < 3) {
    r.status = BurmesterStatus::kInvalidRequest;
    r.message = "a centre point needs at least three poses";
    return r;
  }
  const Normalised n = Normalise(poses, 0);
  const std::vector<Condition> c = Conditions(n.poses);
  const Eigen::Vector2d a = n.To(circle_point);
  // the circumcentre of the circle point's first three positions
  Eigen::Matrix2d k;
  k << c[0].K(a).transpose(), c[1].K(a).transpose();
  const Eigen::Vector2d l(c[0].L(a), c[1].L(a));
  if (std::abs(k.determinant()) <= 1e-12 * k.row(0).norm() * k.row(1).norm()) {
    r.message = "the circle point's three positions are collinear (its centre point lies at infinity)";
    return r;
  }
  r.dyad = {n.Back(k.inverse() * l), circle_point};
  r.residual = DyadResidual(poses, r.dyad);
  if (r.residual > kDyadTolerance * n.scale) {
    r.message = fmt::format("the circle point is not on the circle-point curve: its distance from the centre point varies by {:.3g}", r.residual);
    return r;
  }
  r.status = BurmesterStatus::kOk;
  return r;
}

CentrePointResult CentrePointTwoPoses(const std::vector<Pose>& poses, const Eigen::Vector2d& circle_point, double crank_turn) {
  CentrePointResult r;
  if (poses.size() != 2 || !(std::abs(std::sin(crank_turn / 2)) > 1e-9)) {
    r.status = BurmesterStatus::kInvalidRequest;
    r.message = "two poses and a crank turn that is not a multiple of 360 deg";
    return r;
  }
  const Eigen::Vector2d a1 = circle_point, a2 = MovePoint(poses[0], poses[1], circle_point);
  const Eigen::Vector2d chord = a2 - a1;
  if (!(chord.norm() > kDyadTolerance * PoseScale(poses))) {
    r.message = "the circle point does not move between the two poses";
    return r;
  }
  // the centre sees the chord under the turn: distance from the midpoint = |chord| / (2 tan(turn/2)),
  // on the left of A1 -> A2 for a counter-clockwise turn
  const Eigen::Vector2d left(-chord.y(), chord.x());
  r.dyad = {0.5 * (a1 + a2) + left / (2 * std::tan(crank_turn / 2)), circle_point};
  r.residual = DyadResidual(poses, r.dyad);
  r.status = BurmesterStatus::kOk;
  return r;
}

namespace {

// Points of the centre-point curve (centre point, circle point; normalised units) on one line
// through the pole.
using PoleLinePoints = std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>;

// The curve's points on the line through the pole at angle beta (normalised units) within reach,
// each polished onto the curve.
PoleLinePoints CentrePointsOnPoleLine(const std::vector<Condition>& c, const Eigen::Vector2d& pole, double beta, double reach) {
  PoleLinePoints points;
  const Eigen::Vector2d dir(std::cos(beta), std::sin(beta));
  // det(t) has the root t = 0 (the pole is on the curve): divide it out
  Poly p = LineDeterminant(c, {0, 1, 2}, pole, dir);
  p.erase(p.begin());
  for (const std::complex<double>& t : Roots(p)) {
    if (std::abs(t.imag()) > 1e-9 * (1 + std::abs(t.real()))) continue;
    const Eigen::Vector2d m = pole + t.real() * dir;
    if (m.norm() > reach) continue;
    Eigen::Vector2d a = CirclePointOf(c, m), mm = m;
    if (!PolishDyad(c, &mm, &a) || (mm - m).norm() > 1e-6 || a.norm() > reach) continue;
    points.push_back({mm, a});
  }
  return points;
}

// The centre-point curve's points on `directions` uniform lines through the pole, refined where
// the curve runs nearly along the lines (the points of neighbouring directions lie far apart, or
// their number changes); by direction.
std::vector<std::pair<double, PoleLinePoints>> SampleCentrePointCurve(const std::vector<Condition>& c, const Eigen::Vector2d& pole,
                                                                      int directions, bool refine, double reach) {
  constexpr double kGap = 0.02;  // of the poses' size
  constexpr int kRefinements = 10;
  auto far_apart = [&](const PoleLinePoints& u, const PoleLinePoints& v) {
    if (u.size() != v.size()) return true;
    for (const auto& x : u) {
      double nearest = 1e300;
      for (const auto& y : v) nearest = std::min(nearest, (x.first - y.first).norm());
      if (nearest > kGap) return true;
    }
    return false;
  };
  auto on_line = [&](double beta) { return CentrePointsOnPoleLine(c, pole, beta, reach); };
  std::vector<std::pair<double, PoleLinePoints>> lines;
  std::function<void(double, const PoleLinePoints&, double, const PoleLinePoints&, int)> bisect =
      [&](double b0, const PoleLinePoints& p0, double b1, const PoleLinePoints& p1, int depth) {
        if (!refine || depth >= kRefinements || !far_apart(p0, p1)) return;
        const double mid = 0.5 * (b0 + b1);
        const PoleLinePoints pm = on_line(mid);
        bisect(b0, p0, mid, pm, depth + 1);
        lines.push_back({mid, pm});
        bisect(mid, pm, b1, p1, depth + 1);
      };
  PoleLinePoints previous = on_line(0);
  for (int i = 0; i < directions; ++i) {
    const double beta = kPi * i / directions, next = kPi * (i + 1) / directions;
    const PoleLinePoints here = previous;
    lines.push_back({beta, here});
    if (i + 1 < directions) {
      previous = on_line(next);
      bisect(beta, here, next, previous, 0);
    }
  }
  std::sort(lines.begin(), lines.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  return lines;
}

}  // namespace

BurmesterCurves CentrePointCurve(const std::vector<Pose>& poses, int directions, bool refine, double reach) {
  BurmesterCurves curves;
  if (poses.size() != 4 || directions < 1) {
    curves.status = BurmesterStatus::kInvalidRequest;
    curves.message = "the Burmester curves need exactly four poses and at least one direction";
    return curves;
  }
  const Normalised n = Normalise(poses, 0);
  const std::vector<Condition> c = Conditions(n.poses);
  Eigen::Vector2d pole;
  if (!LargestRotationPole(n.poses, &pole)) {
    curves.message = "the plane does not turn between the poses (translations only): every centre point lies at infinity";
    return curves;
  }
  curves.base_pole = n.Back(pole);
  for (const auto& [beta, points] : SampleCentrePointCurve(c, pole, directions, refine, reach)) {
    for (const auto& [m, a] : points) {
      const Dyad dyad{n.Back(m), n.Back(a)};
      if (DyadResidual(poses, dyad) > kDyadTolerance * n.scale) continue;
      curves.samples.push_back({dyad, beta});
    }
  }
  curves.status = BurmesterStatus::kOk;
  return curves;
}

BallBurmester BallBurmesterPoints(const std::vector<Pose>& poses) {
  BallBurmester result;
  if (poses.size() != 5) {
    result.status = BurmesterStatus::kInvalidRequest;
    result.message = "the Ball–Burmester points need exactly five poses";
    return result;
  }
  // a turn of no special angle, so that no two intersection points share their x (generic position)
  const Normalised n = Normalise(poses, 0.41421356);
  const std::vector<Condition> c = Conditions(n.poses);
  const Bi c1 = CentreCubic(c, {0, 1, 2}), c2 = CentreCubic(c, {0, 1, 3});
  // the resultant in y is a polynomial of degree <= 9 in x (7 for circular cubics): interpolate
  // it at 10 Chebyshev nodes of [-2, 2] in the basis (x/2)^k
  constexpr int kNodes = 10;
  constexpr double kHalfWidth = 2;
  Eigen::MatrixXd vandermonde(kNodes, kNodes);
  Eigen::VectorXd values(kNodes);
  for (int i = 0; i < kNodes; ++i) {
    const double u = std::cos(kPi * (i + 0.5) / kNodes);
    for (int k = 0; k < kNodes; ++k) vandermonde(i, k) = std::pow(u, k);
    values[i] = ResultantAt(c1, c2, kHalfWidth * u);
  }
  const Eigen::VectorXd coefficients = vandermonde.colPivHouseholderQr().solve(values);
  const Poly resultant(coefficients.data(), coefficients.data() + kNodes);
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> found;  // normalised (M, A)
  for (const std::complex<double>& u : Roots(resultant, 1e-9)) {
    // near-real roots: Newton on the full system decides
    if (std::abs(u.imag()) > 0.05 * (1 + std::abs(u.real()))) continue;
    const double x = kHalfWidth * u.real();
    for (const std::complex<double>& y : Roots(InY(c1, x))) {
      if (std::abs(y.imag()) > 0.05 * (1 + std::abs(y.real()))) continue;
      Eigen::Vector2d m(x, y.real());
      Eigen::Vector2d a = CirclePointOf(c, m);
      if (!PolishDyad(c, &m, &a)) continue;
      const Dyad dyad{n.Back(m), n.Back(a)};
      if (DyadResidual(poses, dyad) > kDyadTolerance * n.scale) continue;
      bool known = false;
      for (const auto& [fm, fa] : found) known = known || ((fm - m).norm() < 1e-7 && (fa - a).norm() < 1e-7);
      if (known) continue;
      found.push_back({m, a});
      result.dyads.push_back(dyad);
    }
  }
  result.status = BurmesterStatus::kOk;
  if (result.dyads.empty()) result.message = "no real Ball–Burmester point: the five poses have no four-bar";
  return result;
}

}  // namespace koppel

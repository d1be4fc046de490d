#include "koppel/analysis/coupler_curve.hpp"

#include "koppel/core/angles.hpp"

#include <algorithm>
#include <cmath>

namespace koppel {
namespace {

// |dK| over one interval: 3-point Gauss–Legendre on the derivative of the cubic Hermite
// interpolant through (p0, h d0) and (p1, h d1), in the interval's own parameter s in [0, 1].
double ArcOfInterval(const Eigen::Vector2d& p0, const Eigen::Vector2d& d0, const Eigen::Vector2d& p1, const Eigen::Vector2d& d1, double h) {
  static const double kNodes[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
  static const double kWeights[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  double arc = 0;
  for (int g = 0; g < 3; ++g) {
    const double s = kNodes[g];
    const Eigen::Vector2d dh = (6 * s * s - 6 * s) * p0 + (3 * s * s - 4 * s + 1) * h * d0 + (-6 * s * s + 6 * s) * p1 +
                               (3 * s * s - 2 * s) * h * d1;
    arc += kWeights[g] * dh.norm();
  }
  return arc;
}

}  // namespace

Mechanism WithPointOutput(const Mechanism& m, const PointRef& point) {
  Mechanism copy = m;
  Output o;
  o.name = "curve";
  o.kind = OutputKind::kPoint;
  o.p = point;
  copy.outputs = {o};
  return copy;
}

CouplerCurve TraceCurve(const Mechanism& m, const PointRef& point, const SweepOptions& range) {
  const Mechanism traced = WithPointOutput(m, point);
  SweepOptions options = range;
  options.order = 2;
  const SweepResult sweep = Sweep(traced, options);
  CouplerCurve curve;
  curve.sweep = EventsOf(sweep);
  curve.message = sweep.message;
  curve.status = sweep.inputs.empty() ? AnalysisStatus::kFailed
                                      : (sweep.complete() ? AnalysisStatus::kComplete : AnalysisStatus::kPartial);
  curve.singular = sweep.singular;
  const int n = static_cast<int>(sweep.inputs.size());
  for (int i = 0; i < n; ++i) {
    // columns: x, x', x'', y, y', y''
    curve.inputs.push_back(sweep.inputs[i]);
    curve.points.emplace_back(sweep.outputs(i, 0), sweep.outputs(i, 3));
    curve.d1.emplace_back(sweep.outputs(i, 1), sweep.outputs(i, 4));
    curve.d2.emplace_back(sweep.outputs(i, 2), sweep.outputs(i, 5));
    const double speed = curve.d1.back().norm();
    const double cross = curve.d1.back().x() * curve.d2.back().y() - curve.d1.back().y() * curve.d2.back().x();
    curve.curvature.push_back(speed > 0 ? cross / (speed * speed * speed) : 0.0);
    curve.arc_length.push_back(i == 0 ? 0.0
                                      : curve.arc_length.back() + ArcOfInterval(curve.points[i - 1], curve.d1[i - 1], curve.points[i],
                                                                                curve.d1[i], curve.inputs[i] - curve.inputs[i - 1]));
  }
  return curve;
}

std::string CouplerCurve::Brief() const {
  return std::string(ToString(status)) + ": " + std::to_string(inputs.size()) + " samples" +
         (arc_length.empty() ? "" : ", arc length " + std::to_string(arc_length.back())) + (message.empty() ? "" : "; " + message);
}

std::string StraightStretch::Brief() const {
  return std::string(ToString(status)) + (ok() ? ": Q_G = " + std::to_string(qg) + " over L = " + std::to_string(length) : ": " + message);
}

int FlattestSample(const CouplerCurve& curve) {
  if (curve.curvature.empty()) return -1;
  int best = 0;
  for (int i = 1; i < static_cast<int>(curve.curvature.size()); ++i) {
    if (std::abs(curve.curvature[i]) < std::abs(curve.curvature[best])) best = i;
  }
  return best;
}

namespace {

// Samples of the curve from reference - below to reference + above, and the tangent frame at
// the reference sample: coordinates along g (u) and across it (v).
struct Frame {
  std::vector<double> inputs, u, v;
  int reference = -1;
  Eigen::Vector2d point, tangent;
  std::string message;
};

Frame FrameAround(const Mechanism& m, const PointRef& point, double reference, double below, double above, double resolution,
                  const ContinuationOptions& continuation) {
  Frame f;
  // trace both ways from the reference so that its sample is exact
  SweepOptions up, down;
  up.continuation = down.continuation = continuation;
  up.from = down.from = reference;
  up.to = reference + above;
  down.to = reference - below;
  up.step = down.step = resolution;
  const CouplerCurve right = TraceCurve(m, point, up), left = TraceCurve(m, point, down);
  // a stretch is measured only where the branch is drivable throughout
  if (right.inputs.empty() || left.inputs.empty() || !right.sweep.complete() || !left.sweep.complete()) {
    f.message = !right.sweep.complete() ? right.sweep.message : left.sweep.message;
    if (f.message.empty()) f.message = "the curve cannot be traced";
    return f;
  }
  std::vector<Eigen::Vector2d> pts;
  for (int i = static_cast<int>(left.inputs.size()) - 1; i > 0; --i) {
    f.inputs.push_back(left.inputs[i]);
    pts.push_back(left.points[i]);
  }
  f.reference = static_cast<int>(f.inputs.size());
  for (size_t i = 0; i < right.inputs.size(); ++i) {
    f.inputs.push_back(right.inputs[i]);
    pts.push_back(right.points[i]);
  }
  f.point = right.points[0];
  if (right.d1[0].norm() == 0) {
    f.message = "the point stands still at the reference input: no tangent";
    return f;
  }
  f.tangent = right.d1[0].normalized();
  const Eigen::Vector2d normal(-f.tangent.y(), f.tangent.x());
  for (const Eigen::Vector2d& p : pts) {
    f.u.push_back((p - f.point).dot(f.tangent));
    f.v.push_back((p - f.point).dot(normal));
  }
  return f;
}

// Seed 003's convention (coupler_curve.hpp): phi_I and phi_A in [0, 2 pi), phi_E = phi_A + phi_G.
void ReportInFullTurn(StraightStretch& s) {
  const double phi_a = WrapToFullTurn(s.phi_a);
  s.phi_e += phi_a - s.phi_a;
  s.phi_a = phi_a;
  s.reference = WrapToFullTurn(s.reference);
}

void Measure(const Frame& f, int a, int e, StraightStretch& s) {
  const auto [u_lo, u_hi] = std::minmax_element(f.u.begin() + a, f.u.begin() + e + 1);
  const auto [v_lo, v_hi] = std::minmax_element(f.v.begin() + a, f.v.begin() + e + 1);
  s.phi_a = f.inputs[a];
  s.phi_e = f.inputs[e];
  s.phi_g = s.phi_e - s.phi_a;
  s.length = *u_hi - *u_lo;
  s.band = *v_hi - *v_lo;
  s.qg = s.length > 0 ? s.band / s.length : 0.0;
}

}  // namespace

bool StretchIsValid(double from, double to, std::string* why) {
  std::string problem;
  if (!std::isfinite(from) || !std::isfinite(to)) problem = "the stretch's ends must be finite";
  else if (!(to > from)) problem = "the stretch must end after its start (a stretch through 0 ends beyond 360 deg: 300:420)";
  else if (to - from > 2 * kPi) problem = "the stretch must not span more than one turn";
  if (why) *why = problem;
  return problem.empty();
}

StraightStretch StretchBand(const Mechanism& m, const PointRef& point, double reference, double from, double to, double resolution,
                            const ContinuationOptions& continuation) {
  StraightStretch s;
  s.reference = reference;
  if (!StretchIsValid(from, to, &s.message)) {
    s.status = AnalysisStatus::kFailed;
    return s;
  }
  // the same stretch a whole number of turns on, around the reference
  const double turns = std::round((reference - 0.5 * (from + to)) / (2 * kPi));
  from += 2 * kPi * turns;
  to += 2 * kPi * turns;
  const Frame f = FrameAround(m, point, reference, std::max(reference - from, resolution), std::max(to - reference, resolution),
                              resolution, continuation);
  if (!f.message.empty()) {
    s.status = AnalysisStatus::kFailed;
    s.message = f.message;
    return s;
  }
  s.reference_point = f.point;
  s.tangent = f.tangent;
  auto index_of = [&](double input) {
    return static_cast<int>(std::min_element(f.inputs.begin(), f.inputs.end(), [&](double a, double b) {
                              return std::abs(a - input) < std::abs(b - input);
                            }) - f.inputs.begin());
  };
  Measure(f, index_of(from), index_of(to), s);
  ReportInFullTurn(s);
  s.status = AnalysisStatus::kComplete;
  return s;
}

StraightStretch LongestStraightStretch(const Mechanism& m, const PointRef& point, double qg, std::optional<double> reference,
                                       double half_range, double resolution, const ContinuationOptions& continuation) {
  StraightStretch best;
  if (!reference) {
    SweepOptions whole;
    whole.continuation = continuation;
    whole.from = -half_range;
    whole.to = half_range;
    whole.step = resolution;
    const CouplerCurve curve = TraceCurve(m, point, whole);
    const int flat = FlattestSample(curve);
    if (flat < 0 || !curve.sweep.complete()) {
      best.status = AnalysisStatus::kFailed;
      best.message = curve.sweep.message.empty() ? "the curve cannot be traced" : curve.sweep.message;
      return best;
    }
    reference = curve.inputs[flat];
  }
  best.reference = *reference;
  const Frame f = FrameAround(m, point, *reference, half_range, half_range, resolution, continuation);
  if (!f.message.empty()) {
    best.status = AnalysisStatus::kFailed;
    best.message = f.message;
    return best;
  }
  best.reference_point = f.point;
  best.tangent = f.tangent;
  const int n = static_cast<int>(f.inputs.size());
  int best_a = -1, best_e = -1;
  for (int a = 0; a <= f.reference; ++a) {
    double u_lo = f.u[a], u_hi = f.u[a], v_lo = f.v[a], v_hi = f.v[a];
    int last = -1;
    for (int e = a; e < n && f.inputs[e] - f.inputs[a] <= 2 * half_range; ++e) {
      u_lo = std::min(u_lo, f.u[e]);
      u_hi = std::max(u_hi, f.u[e]);
      v_lo = std::min(v_lo, f.v[e]);
      v_hi = std::max(v_hi, f.v[e]);
      if (e >= f.reference && u_hi > u_lo && v_hi - v_lo <= qg * (u_hi - u_lo)) last = e;
    }
    if (last >= 0 && (best_a < 0 || f.inputs[last] - f.inputs[a] > f.inputs[best_e] - f.inputs[best_a])) {
      best_a = a;
      best_e = last;
    }
  }
  if (best_a < 0) {
    best.status = AnalysisStatus::kFailed;
    best.message = "no stretch through the reference point meets the tolerance";
    return best;
  }
  Measure(f, best_a, best_e, best);
  ReportInFullTurn(best);
  best.status = AnalysisStatus::kComplete;
  return best;
}

}  // namespace koppel

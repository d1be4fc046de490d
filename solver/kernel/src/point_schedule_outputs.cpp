// The outputs of a compiled walk step (point_schedule.hpp), value and 1st and 2nd derivative with
// respect to the input, from the links' jets. Each case is ConstraintSystem::Output
// (constraints.hpp, the definition and its conventions) differentiated by hand: the general
// kernel evaluates the same expressions on Taylor series, at several times the cost per row. The
// point-schedule tests compare the two on every output kind.
#include "koppel/solver/constraints.hpp"
#include "koppel/solver/point_schedule.hpp"

#include "point_schedule_parts.hpp"

#include <cmath>

namespace koppel {
namespace point_outputs {  // this file's own names, apart from point_schedule.cpp's in a unity build
using point_schedule_parts::Cross;

// A scalar and its 1st and 2nd derivatives.
struct ScalarJet {
  double v = 0.0, d1 = 0.0, d2 = 0.0;
};

// a . b and a x b (the z of the cross product) of two point jets, with their derivatives
template <class V>
ScalarJet Dot(const V a[3], const V b[3]) {
  return {a[0].dot(b[0]), a[1].dot(b[0]) + a[0].dot(b[1]), a[2].dot(b[0]) + 2.0 * a[1].dot(b[1]) + a[0].dot(b[2])};
}
template <class V>
ScalarJet CrossJet(const V a[3], const V b[3]) {
  return {Cross(a[0], b[0]), Cross(a[1], b[0]) + Cross(a[0], b[1]), Cross(a[2], b[0]) + 2.0 * Cross(a[1], b[1]) + Cross(a[0], b[2])};
}
// atan2(y, x) and its derivatives: theta' = (x y' - y x') / r^2, differentiated once more
ScalarJet Atan2Jet(const ScalarJet& y, const ScalarJet& x) {
  const double per_r2 = 1.0 / (x.v * x.v + y.v * y.v);
  const double w = x.v * y.d1 - y.v * x.d1;
  const double t1 = w * per_r2;
  const double t2 = (x.v * y.d2 - y.v * x.d2 - 2.0 * (x.v * x.d1 + y.v * y.d1) * t1) * per_r2;
  return {std::atan2(y.v, x.v), t1, t2};
}
// |x| as ConstraintSystem's Abs: the sign of the value flips every derivative
ScalarJet AbsJet(const ScalarJet& x) { return x.v < 0.0 ? ScalarJet{-x.v, -x.d1, -x.d2} : x; }

}  // namespace point_outputs

void PointSchedule::DirectionJet(int link, const Eigen::Vector2d& local, Eigen::Vector2d u[3]) const {
  if (link == frame_) {  // at rest
    u[0] = local;
    u[1].setZero();
    u[2].setZero();
    return;
  }
  const LinkJet& l = now_[link];
  u[0] = point_schedule_parts::Turned(l.c, l.s, local);
  const Eigen::Vector2d turned = point_schedule_parts::Perp(u[0]);
  u[1] = l.theta[1] * turned;
  u[2] = l.theta[2] * turned - l.theta[1] * l.theta[1] * u[0];
}

void PointSchedule::TransmissionLines(int output, Eigen::Vector2d coupler[3], Eigen::Vector2d motion[3]) const {
  const Mechanism& m = mechanism_;
  const TransmissionGeometry& g = system_.transmission(output);
  auto point = [&](const PointRef& r) { return GlobalPoint(r.link, m.links[r.link].points[r.point].local); };
  const PointJet a = point(g.coupler_from), b = point(g.coupler_to);
  for (int k = 0; k < 3; ++k) coupler[k] = b.p[k] - a.p[k];
  if (g.slide_joint >= 0) {
    // the slide's direction turns with its guide
    const Joint& j = m.joints[g.slide_joint];
    DirectionJet(j.link_a, j.axis, motion);
    return;
  }
  // the output point's direction of motion about the pivot: (b - pivot) turned by +90 deg
  const PointJet pivot = point(g.pivot);
  for (int k = 0; k < 3; ++k) motion[k] = Eigen::Vector2d(-(b.p[k].y() - pivot.p[k].y()), b.p[k].x() - pivot.p[k].x());
}

// long: one case per output kind, in the order and with the conventions of ConstraintSystem::Output
[[gnu::flatten]] void PointSchedule::OutputDerivatives(int order, double* out) const {
  using namespace point_outputs;
  const Mechanism& m = mechanism_;
  int column = 0;
  auto write = [&](const ScalarJet& y) {
    out[column++] = y.v;
    if (order >= 1) out[column++] = y.d1;
    if (order >= 2) out[column++] = y.d2;
  };
  auto point = [&](const PointRef& r) { return GlobalPoint(r.link, m.links[r.link].points[r.point].local); };
  auto angle = [&](int link) { return ScalarJet{Angle(link), now_[link].theta[1], now_[link].theta[2]}; };
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
    const Output& output = m.outputs[o];
    switch (output.kind) {
      case OutputKind::kJoint: {
        const Joint& j = m.joints[output.joint];
        if (j.type == JointType::kRevolute) {
          const ScalarJet a = angle(j.link_a), b = angle(j.link_b);
          write({b.v - a.v - output.offset, b.d1 - a.d1, b.d2 - a.d2});
          break;
        }
        // the displacement along link_a's axis: u . (pb - pa)
        const PointJet pa = point({j.link_a, j.point_a}), pb = point({j.link_b, j.point_b});
        Eigen::Vector2d u[3], d[3];
        DirectionJet(j.link_a, j.axis, u);
        for (int k = 0; k < 3; ++k) d[k] = pb.p[k] - pa.p[k];
        write(Dot(u, d));
        break;
      }
      case OutputKind::kLinkAngle: {
        ScalarJet a = angle(output.link);
        a.v -= output.offset;
        write(a);
        break;
      }
      case OutputKind::kPoint: {
        const PointJet p = point(output.p);
        write({p.p[0].x(), p.p[1].x(), p.p[2].x()});
        write({p.p[0].y(), p.p[1].y(), p.p[2].y()});
        break;
      }
      case OutputKind::kDistance:
      case OutputKind::kDirection: {
        const PointJet p = point(output.p), q = point(output.q);
        Eigen::Vector2d d[3];
        for (int k = 0; k < 3; ++k) d[k] = q.p[k] - p.p[k];
        if (output.kind == OutputKind::kDirection) {
          ScalarJet a = Atan2Jet({d[0].y(), d[1].y(), d[2].y()}, {d[0].x(), d[1].x(), d[2].x()});
          a.v -= output.offset;
          write(a);
          break;
        }
        // |d|' = d . d' / |d|, |d|'' = (d' . d' + d . d'' - |d|'^2) / |d|
        const double v = d[0].norm(), per_v = 1.0 / v, v1 = d[0].dot(d[1]) * per_v;
        write({v, v1, (d[1].squaredNorm() + d[0].dot(d[2]) - v1 * v1) * per_v});
        break;
      }
      case OutputKind::kTransmissionAngle: {
        Eigen::Vector2d c[3], v[3];
        TransmissionLines(o, c, v);
        write(Atan2Jet(AbsJet(Dot(c, v)), AbsJet(CrossJet(c, v))));
        break;
      }
    }
  }
}

}  // namespace koppel

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
// A scalar and its 1st and 2nd derivatives.
struct ScalarJet {
  double v = 0.0, d1 = 0.0, d2 = 0.0;
};

// A 2-vector jet in scalars ([k][0], [k][1]: x and y of the k-th derivative): the points come
// from PointOf's scalars, and 2-vectors built from them would go through the stack (see PointOf).
using VectorJet = double[3][2];

double Dot(const double a[2], const double b[2]) { return a[0] * b[0] + a[1] * b[1]; }
double Cross(const double a[2], const double b[2]) { return a[0] * b[1] - a[1] * b[0]; }
// a . b and a x b (the z of the cross product) of two vector jets, with their derivatives
ScalarJet DotJet(const VectorJet& a, const VectorJet& b) {
  return {Dot(a[0], b[0]), Dot(a[1], b[0]) + Dot(a[0], b[1]), Dot(a[2], b[0]) + 2.0 * Dot(a[1], b[1]) + Dot(a[0], b[2])};
}
ScalarJet CrossJet(const VectorJet& a, const VectorJet& b) {
  return {Cross(a[0], b[0]), Cross(a[1], b[0]) + Cross(a[0], b[1]), Cross(a[2], b[0]) + 2.0 * Cross(a[1], b[1]) + Cross(a[0], b[2])};
}
// the same with b at rest (a direction on the frame: no derivatives)
ScalarJet DotJet(const VectorJet& a, const double b[2]) { return {Dot(a[0], b), Dot(a[1], b), Dot(a[2], b)}; }
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

[[gnu::always_inline]] inline void PointSchedule::DirectionJet(int link, const Eigen::Vector2d& local, double u[3][2]) const {
  if (link == frame_) {  // at rest
    u[0][0] = local.x();
    u[0][1] = local.y();
    u[1][0] = u[1][1] = u[2][0] = u[2][1] = 0.0;
    return;
  }
  const LinkJet& l = now_[link];
  const double x = l.c * local.x() - l.s * local.y(), y = l.s * local.x() + l.c * local.y();
  const double t1 = l.theta[1], t2 = l.theta[2], t11 = t1 * t1;
  u[0][0] = x;
  u[0][1] = y;
  u[1][0] = -t1 * y;  // theta' perp(u)
  u[1][1] = t1 * x;
  u[2][0] = -t2 * y - t11 * x;  // theta'' perp(u) - theta'^2 u
  u[2][1] = t2 * x - t11 * y;
}

void PointSchedule::CompileOutputs() {
  const Mechanism& m = mechanism_;
  auto local = [&](const PointRef& r) { return m.links[r.link].points[r.point].local; };
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
    const Output& output = m.outputs[o];
    OutputPlan plan;
    plan.kind = output.kind;
    plan.offset = output.offset;
    switch (output.kind) {
      case OutputKind::kJoint: {
        const Joint& j = m.joints[output.joint];
        plan.slide = j.type == JointType::kPrismatic;
        plan.link_p = plan.axis_link = j.link_a;
        plan.link_q = j.link_b;
        plan.p = local({j.link_a, j.point_a});
        plan.q = local({j.link_b, j.point_b});
        plan.axis = j.axis;
        break;
      }
      case OutputKind::kLinkAngle:
        plan.link_p = output.link;
        break;
      case OutputKind::kPoint:
      case OutputKind::kDistance:
      case OutputKind::kDirection:
        plan.link_p = output.p.link;
        plan.p = local(output.p);
        if (output.kind != OutputKind::kPoint) {
          plan.link_q = output.q.link;
          plan.q = local(output.q);
        }
        break;
      case OutputKind::kTransmissionAngle: {
        const TransmissionGeometry& g = system_.transmission(o);
        plan.link_p = g.coupler_from.link;
        plan.p = local(g.coupler_from);
        plan.link_q = g.coupler_to.link;  // the coupler, as link_p (ResolveTransmission)
        plan.q = local(g.coupler_to);
        plan.slide = g.slide_joint >= 0;
        if (plan.slide) {  // (on the frame: its direction at rest)
          const Joint& j = m.joints[g.slide_joint];
          plan.axis_link = j.link_a;
          plan.axis = j.axis;
          // SlideTransmission's premise, which ResolveTransmission holds to
          if (plan.axis_link != frame_) why_not_ = "output '" + output.name + "': a transmission angle on a slide off the frame";
        } else {
          plan.pivot_link = g.pivot.link;
          plan.pivot = local(g.pivot);
        }
        break;
      }
    }
    outputs_.push_back(plan);
  }
}

// mu between the coupler's line and the slide's (on the frame: ResolveTransmission): the angle
// between them, atan2(cross, dot), turns with the coupler, so mu = atan2(|dot|, |cross|) =
// +-theta + const, and its derivatives are the coupler's signed by the quadrant (the general
// formula's (x y' - y x') / r^2 reduces to that exactly: dot' = theta' cross, cross' = -theta' dot).
point_outputs::ScalarJet PointSchedule::SlideTransmission(const OutputPlan& plan) const {
  const LinkJet& coupler = now_[plan.link_p];
  const Eigen::Vector2d line = plan.q - plan.p;
  const double cx = coupler.c * line.x() - coupler.s * line.y(), cy = coupler.s * line.x() + coupler.c * line.y();
  const double dot = cx * plan.axis.x() + cy * plan.axis.y(), cross = cx * plan.axis.y() - cy * plan.axis.x();
  // (as AbsJet: a negative value flips the derivatives, 0 does not)
  const double sign = (dot < 0.0) == (cross < 0.0) ? 1.0 : -1.0;
  return {std::atan2(std::abs(dot), std::abs(cross)), sign * coupler.theta[1], sign * coupler.theta[2]};
}

void PointSchedule::Difference(const PointJet& q, const PointJet& p, double d[3][2]) {
  for (int k = 0; k < 3; ++k) {
    d[k][0] = q.p[k].x() - p.p[k].x();
    d[k][1] = q.p[k].y() - p.p[k].y();
  }
}

void PointSchedule::OutputDerivatives(int order, double* out) const {
  if (order <= 0) {
    WriteOutputs<0>(out);
  } else if (order == 1) {
    WriteOutputs<1>(out);
  } else {
    WriteOutputs<2>(out);
  }
}

// (Order a template argument: the columns written per value are fixed in the loop.)
// long: one case per output kind, in the order and with the conventions of ConstraintSystem::Output
template <int Order>
[[gnu::flatten]] void PointSchedule::WriteOutputs(double* out) const {
  using namespace point_outputs;
  auto write = [&](const ScalarJet& y) {
    *out++ = y.v;
    if constexpr (Order >= 1) *out++ = y.d1;
    if constexpr (Order >= 2) *out++ = y.d2;
  };
  auto angle = [&](int link) { return ScalarJet{Angle(link), now_[link].theta[1], now_[link].theta[2]}; };
  for (const OutputPlan& plan : outputs_) {
    switch (plan.kind) {
      case OutputKind::kJoint: {
        if (!plan.slide) {
          const ScalarJet a = angle(plan.link_p), b = angle(plan.link_q);
          write({b.v - a.v - plan.offset, b.d1 - a.d1, b.d2 - a.d2});
          break;
        }
        // the displacement along link_a's axis: u . (pb - pa)
        VectorJet u, d;
        Difference(GlobalPoint(plan.link_q, plan.q), GlobalPoint(plan.link_p, plan.p), d);
        if (plan.axis_link == frame_) {
          const double axis[2] = {plan.axis.x(), plan.axis.y()};
          write(DotJet(d, axis));
          break;
        }
        DirectionJet(plan.axis_link, plan.axis, u);
        write(DotJet(u, d));
        break;
      }
      case OutputKind::kLinkAngle: {
        ScalarJet a = angle(plan.link_p);
        a.v -= plan.offset;
        write(a);
        break;
      }
      case OutputKind::kPoint: {
        const PointJet p = GlobalPoint(plan.link_p, plan.p);
        write({p.p[0].x(), p.p[1].x(), p.p[2].x()});
        write({p.p[0].y(), p.p[1].y(), p.p[2].y()});
        break;
      }
      case OutputKind::kDistance:
      case OutputKind::kDirection: {
        VectorJet d;
        Difference(GlobalPoint(plan.link_q, plan.q), GlobalPoint(plan.link_p, plan.p), d);
        if (plan.kind == OutputKind::kDirection) {
          ScalarJet a = Atan2Jet({d[0][1], d[1][1], d[2][1]}, {d[0][0], d[1][0], d[2][0]});
          a.v -= plan.offset;
          write(a);
          break;
        }
        // |d|' = d . d' / |d|, |d|'' = (d' . d' + d . d'' - |d|'^2) / |d|
        const double v = std::sqrt(Dot(d[0], d[0])), per_v = 1.0 / v, v1 = Dot(d[0], d[1]) * per_v;
        write({v, v1, (Dot(d[1], d[1]) + Dot(d[0], d[2]) - v1 * v1) * per_v});
        break;
      }
      case OutputKind::kTransmissionAngle: {
        if (plan.slide) {
          write(SlideTransmission(plan));
          break;
        }
        // the coupler's line (both points on the coupler: q - p turned with it), and the output
        // point's direction of motion about the pivot: (q - pivot) turned by +90 deg
        VectorJet c, b, v;
        DirectionJet(plan.link_p, plan.q - plan.p, c);
        Difference(GlobalPoint(plan.link_q, plan.q), GlobalPoint(plan.pivot_link, plan.pivot), b);
        for (int k = 0; k < 3; ++k) {
          v[k][0] = -b[k][1];
          v[k][1] = b[k][0];
        }
        write(Atan2Jet(AbsJet(DotJet(c, v)), AbsJet(CrossJet(c, v))));
        break;
      }
    }
  }
}

}  // namespace koppel

// The position problem of a mechanism as equations F(q, input) = 0 over all moving links at once.
//
// Coordinates q: three per moving link, (x, y, theta) of its body frame in the global frame, in
// link order (the frame link has none). Equations, in joint order:
//   R joint: 2 rows, p_a - p_b = 0 (the two joint points coincide);
//   P joint: 2 rows, n_a . (p_b - p_a) = 0 (block point on the slide line, n_a the line's normal)
//            and L * wrap(theta_b - theta_a - angle) = 0 (no relative rotation);
//   drive:   1 row (last), L * wrap(theta_b - theta_a - zero - input) for an R drive, or
//            s - zero - input for a P drive.
// L is the mechanism's length scale: it gives rotation rows the unit and size of the position
// rows, so the Jacobian stays well scaled. The angle rows use a wrap-safe difference, so a
// full turn of the crank never shows up as a residual of 2 pi.
//
// Residuals and outputs are templates on the scalar (double, Taylor<N>, or an autodiff jet), so
// the same code gives positions and exact transfer functions of any order; the Jacobian dF/dq is
// written out analytically (constraints.cpp) and checked against finite differences in the tests.
#pragma once

#include "koppel/core/expected.hpp"
#include "koppel/core/mechanism.hpp"
#include "koppel/core/transmission.hpp"  // TransmissionGeometry
#include "koppel/solver/taylor.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace koppel {

class ConstraintSystem {
 public:
  // Precondition: CheckConsistency(mechanism) is empty. Keeps a reference: the mechanism must
  // outlive the system and not change while it is used (the joints' geometry and the Jacobian's
  // pattern are taken at construction; a changed mechanism needs a new system).
  explicit ConstraintSystem(const Mechanism& mechanism);

  const Mechanism& mechanism() const { return mechanism_; }
  int NumCoordinates() const { return num_coordinates_; }
  int NumEquations() const { return num_equations_; }  // constraint rows + 1 drive row
  int DriveRow() const { return num_equations_ - 1; }
  int CoordinateOf(int link) const { return coordinate_[link]; }  // -1 for the frame
  // Where transmission-angle output `output` is measured (default-constructed for other outputs).
  const TransmissionGeometry& transmission(int output) const { return transmission_[output]; }
  int FirstRowOf(int joint) const { return 2 * joint; }
  double length_scale() const { return length_scale_; }
  // Problems found while resolving outputs (e.g. a transmission angle without a coupler).
  const std::vector<std::string>& problems() const { return problems_; }

  template <class T> void Residuals(const T* q, const T& input, T* r) const;

  // dF/dq at q, analytic. J must be NumEquations() x NumCoordinates(); dF/dinput is -1 in the
  // drive row (times L for an R drive) and 0 elsewhere, see InputColumn().
  void Jacobian(const double* q, Eigen::Ref<Eigen::MatrixXd> jacobian) const;
  double InputColumn() const { return mechanism_.InputIsAngle() ? -length_scale_ : -1.0; }

  // The entries of dF/dq that can be non-zero, fixed by the joints (the same at every pose):
  // entry e sits at (pattern_rows()[e], pattern_cols()[e]), no two at one place.
  const std::vector<int>& pattern_rows() const { return pattern_rows_; }
  const std::vector<int>& pattern_cols() const { return pattern_cols_; }
  int TrigSize() const { return 2 * static_cast<int>(mechanism_.links.size()); }

  // The Newton loop's evaluation: F(q, input) into `residual` and dF/dq's entries in pattern
  // order into `jacobian_values`, in one pass with cos and sin of each link angle computed once
  // (into `trig`, TrigSize() numbers: cos, sin per link; 1, 0 for the frame). The same equations
  // as Residuals and Jacobian (constraints_test checks both).
  void Evaluate(const double* q, double input, double* residual, double* jacobian_values, double* trig) const;

  // The Taylor coefficients of q(input) order by order, each from J q_k = -[F]_k, without
  // evaluating the residuals in series arithmetic: `q_series` holds q's coefficients column by
  // column (NumCoordinates() rows), `trig_series` those of each link's cos and sin (TrigSize()
  // rows; column 0 is `trig` of Evaluate at the pose). For k = 1, 2, ...:
  //   TrigSeriesPartial(k): coefficient k of cos and sin with theta's coefficient k taken as zero
  //     (the recurrences s' = c theta', c' = -s theta');
  //   SeriesResidual(k): coefficient k of F(q(t), input + t) with q's coefficient k taken as zero,
  //     from q's columns 0..k-1 and the trig columns 0..k;
  //   (the caller solves for q's column k), TrigSeriesComplete(k): adds theta_k's part.
  // The same numbers as Residuals on Taylor<N> (constraints_test), with no heap allocation.
  void TrigSeriesPartial(int k, const double* q_series, double* trig_series) const;
  void SeriesResidual(int k, const double* q_series, const double* trig_series, double* residual) const;
  void TrigSeriesComplete(int k, const double* q_series, double* trig_series) const;

  // Value of one output component (0 = x, 1 = y for points), in radians / lengths, offset applied.
  // `trig`, when given, holds cos and sin of every link angle at q (TrigSize() numbers, as
  // Evaluate lays them out), computed once for many outputs.
  template <class T> T Output(int output, int component, const T* q, const T* trig = nullptr) const;

  // Global position of a link point.
  template <class T> void GlobalPoint(const PointRef& ref, const T* q, T* xy, const T* trig = nullptr) const;
  template <class T> T LinkAngle(int link, const T* q) const;

 private:
  template <class T> T JointValue(int joint, const T* q, const T* trig = nullptr) const;
  template <class T> void LinkSinCos(int link, const T* q, const T* trig, T& s, T& c) const;

  // A joint as the hot loops read it: coordinate indices (-1 for the frame) and local geometry.
  struct JointRecord {
    bool revolute = true;
    int link_a = 0, link_b = 0;
    int ia = -1, ib = -1;
    Eigen::Vector2d pa = Eigen::Vector2d::Zero(), pb = Eigen::Vector2d::Zero();
    Eigen::Vector2d axis = Eigen::Vector2d::UnitX();  // P: the slide direction on link a
    double angle = 0.0;
  };
  // Rows of joint k (and of the drive) with their Jacobian entries, emitted in one fixed order.
  template <class Sink> void EvaluateRows(const double* q, double input, const double* trig, double* residual, Sink&& sink) const;
  // The series coefficient k of w(theta_a) . (p_b - p_a), w fixed in link a (a P joint's normal
  // or a P drive's axis), with q's coefficient k taken as zero.
  double LineSeries(int k, const JointRecord& j, const Eigen::Vector2d& w_local, const double* q_series,
                    const double* trig_series) const;

  const Mechanism& mechanism_;
  std::vector<JointRecord> records_;
  JointRecord drive_;
  std::vector<int> pattern_rows_, pattern_cols_;
  std::vector<int> coordinate_;
  std::vector<TransmissionGeometry> transmission_;  // per output; default-constructed if unused
  std::vector<std::string> problems_;
  int num_coordinates_ = 0;
  int num_equations_ = 0;
  double length_scale_ = 1.0;
};

// ---- template definitions ---------------------------------------------------------------

template <class T>
T ConstraintSystem::LinkAngle(int link, const T* q) const {
  const int i = coordinate_[link];
  return i < 0 ? T(0.0) : q[i + 2];
}

template <class T>
void ConstraintSystem::LinkSinCos(int link, const T* q, const T* trig, T& s, T& c) const {
  if (trig) {
    c = trig[2 * link];
    s = trig[2 * link + 1];
  } else {
    SinCos(LinkAngle(link, q), s, c);
  }
}

template <class T>
void ConstraintSystem::GlobalPoint(const PointRef& ref, const T* q, T* xy, const T* trig) const {
  const Eigen::Vector2d& p = mechanism_.links[ref.link].points[ref.point].local;
  const int i = coordinate_[ref.link];
  if (i < 0) {
    xy[0] = T(p.x());
    xy[1] = T(p.y());
    return;
  }
  T s, c;
  LinkSinCos(ref.link, q, trig, s, c);
  xy[0] = q[i] + c * p.x() - s * p.y();
  xy[1] = q[i + 1] + s * p.x() + c * p.y();
}

template <class T>
T ConstraintSystem::JointValue(int joint, const T* q, const T* trig) const {
  const Joint& j = mechanism_.joints[joint];
  if (j.type == JointType::kRevolute) return LinkAngle(j.link_b, q) - LinkAngle(j.link_a, q);
  T pa[2], pb[2], s, c;
  GlobalPoint({j.link_a, j.point_a}, q, pa, trig);
  GlobalPoint({j.link_b, j.point_b}, q, pb, trig);
  LinkSinCos(j.link_a, q, trig, s, c);
  const T ux = c * j.axis.x() - s * j.axis.y();
  const T uy = s * j.axis.x() + c * j.axis.y();
  return ux * (pb[0] - pa[0]) + uy * (pb[1] - pa[1]);
}

template <class T>
void ConstraintSystem::Residuals(const T* q, const T& input, T* r) const {
  const double scale = length_scale_;
  for (int k = 0; k < static_cast<int>(mechanism_.joints.size()); ++k) {
    const Joint& j = mechanism_.joints[k];
    T pa[2], pb[2];
    GlobalPoint({j.link_a, j.point_a}, q, pa);
    GlobalPoint({j.link_b, j.point_b}, q, pb);
    T* row = r + FirstRowOf(k);
    if (j.type == JointType::kRevolute) {
      row[0] = pa[0] - pb[0];
      row[1] = pa[1] - pb[1];
    } else {
      T s, c;
      const T theta_a = LinkAngle(j.link_a, q);
      SinCos(theta_a, s, c);
      // normal of the slide line: the axis turned by +90 degrees
      const T nx = -(s * j.axis.x() + c * j.axis.y());
      const T ny = c * j.axis.x() - s * j.axis.y();
      row[0] = nx * (pb[0] - pa[0]) + ny * (pb[1] - pa[1]);
      row[1] = WrapAngle(LinkAngle(j.link_b, q) - theta_a - j.angle) * scale;
    }
  }
  const Drive& d = mechanism_.drive;
  const T value = JointValue(d.joint, q);
  r[DriveRow()] = mechanism_.InputIsAngle() ? WrapAngle(value - d.zero - input) * scale : value - d.zero - input;
}

namespace detail {
template <class T> T Abs(const T& x) { return Value(x) < 0.0 ? -x : x; }
}  // namespace detail

template <class T>
T ConstraintSystem::Output(int output, int component, const T* q, const T* trig) const {
  const koppel::Output& o = mechanism_.outputs[output];
  switch (o.kind) {
    case OutputKind::kJoint:
      return mechanism_.joints[o.joint].type == JointType::kRevolute ? JointValue(o.joint, q, trig) - o.offset
                                                                      : JointValue(o.joint, q, trig);
    case OutputKind::kLinkAngle:
      return LinkAngle(o.link, q) - o.offset;
    case OutputKind::kPoint: {
      T xy[2];
      GlobalPoint(o.p, q, xy, trig);
      return xy[component];
    }
    case OutputKind::kDistance:
    case OutputKind::kDirection: {
      T p[2], r[2];
      GlobalPoint(o.p, q, p, trig);
      GlobalPoint(o.q, q, r, trig);
      const T dx = r[0] - p[0], dy = r[1] - p[1];
      using std::atan2;
      using std::sqrt;
      if (o.kind == OutputKind::kDistance) return sqrt(dx * dx + dy * dy);
      return atan2(dy, dx) - o.offset;
    }
    case OutputKind::kTransmissionAngle: {
      const TransmissionGeometry& g = transmission_[output];
      T a[2], b[2];
      GlobalPoint(g.coupler_from, q, a, trig);
      GlobalPoint(g.coupler_to, q, b, trig);
      const T cx = b[0] - a[0], cy = b[1] - a[1];
      T vx, vy;  // direction of motion of the output joint point
      if (g.slide_joint >= 0) {
        const Joint& j = mechanism_.joints[g.slide_joint];
        T s, c;
        LinkSinCos(j.link_a, q, trig, s, c);
        vx = c * j.axis.x() - s * j.axis.y();
        vy = s * j.axis.x() + c * j.axis.y();
      } else {
        T o_xy[2];
        GlobalPoint(g.pivot, q, o_xy, trig);
        vx = -(b[1] - o_xy[1]);
        vy = b[0] - o_xy[0];
      }
      // mu = 90 deg minus the acute angle between the coupler and the direction of motion
      using std::atan2;
      return atan2(detail::Abs(cx * vx + cy * vy), detail::Abs(cx * vy - cy * vx));
    }
  }
  return T(0.0);
}

}  // namespace koppel

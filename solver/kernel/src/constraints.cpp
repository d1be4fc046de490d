#include "koppel/solver/constraints.hpp"

#include "koppel/core/plane.hpp"

#include <cmath>
#include <type_traits>

namespace koppel {
ConstraintSystem::ConstraintSystem(const Mechanism& mechanism)
    : mechanism_(mechanism), length_scale_(LengthScale(mechanism)) {
  coordinate_.assign(mechanism.links.size(), -1);
  for (int i = 0; i < static_cast<int>(mechanism.links.size()); ++i) {
    if (!mechanism.links[i].is_frame) {
      coordinate_[i] = num_coordinates_;
      num_coordinates_ += 3;
    }
  }
  num_equations_ = 2 * static_cast<int>(mechanism.joints.size()) + 1;
  for (const Joint& j : mechanism.joints) {
    JointRecord r;
    r.revolute = j.type == JointType::kRevolute;
    r.link_a = j.link_a;
    r.link_b = j.link_b;
    r.ia = coordinate_[j.link_a];
    r.ib = coordinate_[j.link_b];
    r.pa = mechanism.links[j.link_a].points[j.point_a].local;
    r.pb = mechanism.links[j.link_b].points[j.point_b].local;
    r.axis = j.axis;
    r.angle = j.angle;
    records_.push_back(r);
  }
  if (!records_.empty()) drive_ = records_[mechanism.drive.joint];
  // the pattern: the entries the rows emit, recorded once at an arbitrary pose
  const std::vector<double> q(num_coordinates_, 0.0);
  std::vector<double> trig(TrigSize(), 0.0), residual(num_equations_);
  for (size_t l = 0; l < mechanism.links.size(); ++l) trig[2 * l] = 1.0;
  EvaluateRows(q.data(), 0.0, trig.data(), residual.data(), [&](int row, int col, double) {
    pattern_rows_.push_back(row);
    pattern_cols_.push_back(col);
  });
  transmission_.resize(mechanism.outputs.size());
  for (int k = 0; k < static_cast<int>(mechanism.outputs.size()); ++k) {
    const koppel::Output& o = mechanism.outputs[k];
    if (o.kind != OutputKind::kTransmissionAngle) continue;
    const Expected<TransmissionGeometry> geometry = ResolveTransmission(mechanism, o);
    if (geometry) {
      transmission_[k] = *geometry;
    } else {
      problems_.push_back("output '" + o.name + "': " + geometry.error());
    }
  }
}

namespace {

// The rows of joint records at a pose q (trig: cos and sin of each link's angle), each Jacobian
// entry handed to sink(row, column, value). Record is ConstraintSystem's JointRecord.
template <class Record, class Sink>
class JointRowWriter {
 public:
  JointRowWriter(const double* q, const double* trig, double scale, Sink& sink) : q_(q), trig_(trig), scale_(scale), sink_(sink) {}

  // R(theta) p for a point p of `link`, and the origin and angle of a link by its coordinates
  Eigen::Vector2d Arm(int link, const Eigen::Vector2d& p) const {
    const double c = trig_[2 * link], s = trig_[2 * link + 1];
    return Eigen::Vector2d(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  }
  Eigen::Vector2d Origin(int i) const { return i < 0 ? Eigen::Vector2d::Zero().eval() : Eigen::Vector2d(q_[i], q_[i + 1]); }
  double Theta(int i) const { return i < 0 ? 0.0 : q_[i + 2]; }

  // Row w(theta_a) . (p_b - p_a) where w is a direction fixed in link a (normal or axis).
  double LineRow(int row, const Record& j, const Eigen::Vector2d& w_local) {
    const Eigen::Vector2d w = Arm(j.link_a, w_local), arm_a = Arm(j.link_a, j.pa), arm_b = Arm(j.link_b, j.pb);
    const Eigen::Vector2d d = Origin(j.ib) + arm_b - Origin(j.ia) - arm_a;
    if (j.ia >= 0) {
      sink_(row, j.ia, -w.x());
      sink_(row, j.ia + 1, -w.y());
      sink_(row, j.ia + 2, Perp(w).dot(d) - w.dot(Perp(arm_a)));
    }
    if (j.ib >= 0) {
      sink_(row, j.ib, w.x());
      sink_(row, j.ib + 1, w.y());
      sink_(row, j.ib + 2, w.dot(Perp(arm_b)));
    }
    return w.dot(d);
  }
  // The Jacobian of a row (theta_b - theta_a) * L.
  void AngleRow(int row, const Record& j) {
    if (j.ia >= 0) sink_(row, j.ia + 2, -scale_);
    if (j.ib >= 0) sink_(row, j.ib + 2, scale_);
  }
  // The two rows p_a - p_b = 0 of a revolute joint.
  void RevoluteRows(int row, const Record& j, double* r) {
    const Eigen::Vector2d arm_a = Arm(j.link_a, j.pa), arm_b = Arm(j.link_b, j.pb);
    const Eigen::Vector2d gap = Origin(j.ia) + arm_a - Origin(j.ib) - arm_b;
    r[row] = gap.x();
    r[row + 1] = gap.y();
    // d/dtheta of R(theta) p is the arm turned by +90 degrees
    if (j.ia >= 0) {
      sink_(row, j.ia, 1.0);
      sink_(row + 1, j.ia + 1, 1.0);
      sink_(row, j.ia + 2, -arm_a.y());
      sink_(row + 1, j.ia + 2, arm_a.x());
    }
    if (j.ib >= 0) {
      sink_(row, j.ib, -1.0);
      sink_(row + 1, j.ib + 1, -1.0);
      sink_(row, j.ib + 2, arm_b.y());
      sink_(row + 1, j.ib + 2, -arm_b.x());
    }
  }

 private:
  const double* q_;
  const double* trig_;
  const double scale_;
  Sink& sink_;
};

}  // namespace

template <class Sink>
void ConstraintSystem::EvaluateRows(const double* q, double input, const double* trig, double* r, Sink&& sink) const {
  const double scale = length_scale_;
  JointRowWriter<JointRecord, std::remove_reference_t<Sink>> rows(q, trig, scale, sink);
  for (int k = 0; k < static_cast<int>(records_.size()); ++k) {
    const JointRecord& j = records_[k];
    const int row = FirstRowOf(k);
    if (j.revolute) {
      rows.RevoluteRows(row, j, r);
    } else {
      r[row] = rows.LineRow(row, j, Perp(j.axis));
      r[row + 1] = WrapAngle(rows.Theta(j.ib) - rows.Theta(j.ia) - j.angle) * scale;
      rows.AngleRow(row + 1, j);
    }
  }
  const Drive& d = mechanism_.drive;
  if (drive_.revolute) {
    r[DriveRow()] = WrapAngle(rows.Theta(drive_.ib) - rows.Theta(drive_.ia) - d.zero - input) * scale;
    rows.AngleRow(DriveRow(), drive_);
  } else {
    r[DriveRow()] = rows.LineRow(DriveRow(), drive_, drive_.axis) - d.zero - input;
  }
}

void ConstraintSystem::Evaluate(const double* q, double input, double* residual, double* jacobian_values, double* trig) const {
  for (int l = 0; l < static_cast<int>(coordinate_.size()); ++l) {
    const int i = coordinate_[l];
    if (i < 0) {
      trig[2 * l] = 1.0;
      trig[2 * l + 1] = 0.0;
    } else {
      SinCos(q[i + 2], trig[2 * l + 1], trig[2 * l]);
    }
  }
  double* value = jacobian_values;
  EvaluateRows(q, input, trig, residual, [&value](int, int, double v) { *value++ = v; });
}

void ConstraintSystem::Jacobian(const double* q, Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  std::vector<double> trig(TrigSize()), residual(num_equations_), values(pattern_rows_.size());
  Evaluate(q, 0.0, residual.data(), values.data(), trig.data());
  for (size_t e = 0; e < values.size(); ++e) jac(pattern_rows_[e], pattern_cols_[e]) = values[e];
}

void ConstraintSystem::TrigSeriesPartial(int k, const double* q_series, double* trig_series) const {
  const int n = num_coordinates_, t = TrigSize();
  for (int l = 0; l < static_cast<int>(coordinate_.size()); ++l) {
    double* c = trig_series + 2 * l;  // c[t * j] = cos coefficient j, c[t * j + 1] = sin
    const int i = coordinate_[l];
    double cos_k = 0.0, sin_k = 0.0;
    if (i >= 0) {
      for (int j = 1; j < k; ++j) {
        const double theta_j = j * q_series[i + 2 + n * j];
        sin_k += theta_j * c[t * (k - j)];
        cos_k -= theta_j * c[t * (k - j) + 1];
      }
    }
    c[t * k] = cos_k / k;
    c[t * k + 1] = sin_k / k;
  }
}

void ConstraintSystem::TrigSeriesComplete(int k, const double* q_series, double* trig_series) const {
  const int n = num_coordinates_, t = TrigSize();
  for (int l = 0; l < static_cast<int>(coordinate_.size()); ++l) {
    const int i = coordinate_[l];
    if (i < 0) continue;
    double* c = trig_series + 2 * l;
    const double theta_k = q_series[i + 2 + n * k];
    c[t * k] -= theta_k * c[1];
    c[t * k + 1] += theta_k * c[0];
  }
}

double ConstraintSystem::LineSeries(int k, const JointRecord& j, const Eigen::Vector2d& w_local, const double* q_series,
                                    const double* trig_series) const {
  const int n = num_coordinates_, t = TrigSize();
  // coefficient m of R(theta) p for link `link`, and of a link's origin (zero at m = k)
  auto arm = [&](int link, const Eigen::Vector2d& p, int m) {
    const double c = trig_series[2 * link + t * m], s = trig_series[2 * link + 1 + t * m];
    return Eigen::Vector2d(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  };
  auto origin = [&](int i, int m) {
    return i < 0 || m == k ? Eigen::Vector2d::Zero().eval() : Eigen::Vector2d(q_series[i + n * m], q_series[i + 1 + n * m]);
  };
  double sum = 0.0;
  for (int m = 0; m <= k; ++m) {
    const Eigen::Vector2d d = origin(j.ib, k - m) + arm(j.link_b, j.pb, k - m) - origin(j.ia, k - m) - arm(j.link_a, j.pa, k - m);
    sum += arm(j.link_a, w_local, m).dot(d);
  }
  return sum;
}

void ConstraintSystem::SeriesResidual(int k, const double* q_series, const double* trig_series, double* r) const {
  const int t = TrigSize();
  auto arm = [&](int link, const Eigen::Vector2d& p) {
    const double c = trig_series[2 * link + t * k], s = trig_series[2 * link + 1 + t * k];
    return Eigen::Vector2d(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  };
  for (int jk = 0; jk < static_cast<int>(records_.size()); ++jk) {
    const JointRecord& j = records_[jk];
    const int row = FirstRowOf(jk);
    if (j.revolute) {
      // the origins' coefficient k is zero: only the arms turn
      const Eigen::Vector2d gap = arm(j.link_a, j.pa) - arm(j.link_b, j.pb);
      r[row] = gap.x();
      r[row + 1] = gap.y();
    } else {
      r[row] = LineSeries(k, j, Perp(j.axis), q_series, trig_series);
      r[row + 1] = 0.0;  // linear in the angles
    }
  }
  // the input's coefficient 1 is 1
  if (drive_.revolute) {
    r[DriveRow()] = k == 1 ? -length_scale_ : 0.0;
  } else {
    r[DriveRow()] = LineSeries(k, drive_, drive_.axis, q_series, trig_series) - (k == 1 ? 1.0 : 0.0);
  }
}

}  // namespace koppel

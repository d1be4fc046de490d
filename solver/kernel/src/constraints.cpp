#include "koppel/solver/constraints.hpp"

#include <cmath>

namespace koppel {
namespace {

Eigen::Vector2d Rotate(double theta, const Eigen::Vector2d& v) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// v turned by +90 degrees: the derivative of R(theta) v with respect to theta.
Eigen::Vector2d Perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

}  // namespace

Expected<TransmissionGeometry> ResolveTransmission(const Mechanism& m, const Output& o) {
  using Result = Expected<TransmissionGeometry>;
  TransmissionGeometry g;
  const int coupler = o.link;
  const Joint& out = m.joints[o.joint];
  if (out.link_a != coupler && out.link_b != coupler) {
    return Result::Error("joint '" + out.name + "' does not belong to coupler '" + m.links[coupler].name + "'");
  }
  const int other = OtherJointOfBinaryLink(m, coupler, o.joint);
  if (other < 0) {
    return Result::Error("coupler '" + m.links[coupler].name + "' must be a binary link (exactly two joints)");
  }
  // The coupler carries force along the line between its two joints; for a P joint at the far
  // end that line is not defined by points alone, so both joints must be revolute.
  if (m.joints[other].type != JointType::kRevolute || out.type != JointType::kRevolute) {
    return Result::Error("the coupler's joints '" + m.joints[other].name + "' and '" + out.name + "' must be revolute");
  }
  g.coupler_from = JointPointOn(m.joints[other], coupler);
  g.coupler_to = JointPointOn(out, coupler);
  const int output_link = out.link_a == coupler ? out.link_b : out.link_a;
  const int frame = m.FrameLink();
  for (int k = 0; k < static_cast<int>(m.joints.size()); ++k) {
    const Joint& j = m.joints[k];
    if (k == o.joint) continue;
    const bool joins_frame = (j.link_a == frame && j.link_b == output_link) || (j.link_b == frame && j.link_a == output_link);
    if (!joins_frame) continue;
    if (j.type == JointType::kRevolute) {
      g.pivot = JointPointOn(j, output_link);
      return g;
    }
    if (j.link_a == frame) {  // the slide line belongs to the frame: its direction is fixed
      g.slide_joint = k;
      return g;
    }
  }
  return Result::Error("output link '" + m.links[output_link].name + "' must turn about or slide on the frame");
}

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

void ConstraintSystem::Jacobian(const double* q, Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  const double scale = length_scale_;
  auto theta = [&](int link) { return LinkAngle(link, q); };
  // Global offset R(theta) p of a joint point from its link's origin.
  auto arm = [&](int link, int point) { return Rotate(theta(link), mechanism_.links[link].points[point].local); };
  auto global = [&](int link, int point) {
    const int i = coordinate_[link];
    const Eigen::Vector2d origin = i < 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(q[i], q[i + 1]);
    return Eigen::Vector2d(origin + arm(link, point));
  };
  // Row of w(theta_a) . (p_b - p_a) where w is a direction fixed in link a (normal or axis).
  auto line_row = [&](int row, const Joint& j, const Eigen::Vector2d& w_local) {
    const Eigen::Vector2d w = Rotate(theta(j.link_a), w_local);
    const Eigen::Vector2d d = global(j.link_b, j.point_b) - global(j.link_a, j.point_a);
    if (const int ia = coordinate_[j.link_a]; ia >= 0) {
      jac(row, ia) = -w.x();
      jac(row, ia + 1) = -w.y();
      jac(row, ia + 2) = Perp(w).dot(d) - w.dot(Perp(arm(j.link_a, j.point_a)));
    }
    if (const int ib = coordinate_[j.link_b]; ib >= 0) {
      jac(row, ib) = w.x();
      jac(row, ib + 1) = w.y();
      jac(row, ib + 2) = w.dot(Perp(arm(j.link_b, j.point_b)));
    }
  };
  auto angle_row = [&](int row, const Joint& j) {
    if (const int ia = coordinate_[j.link_a]; ia >= 0) jac(row, ia + 2) = -scale;
    if (const int ib = coordinate_[j.link_b]; ib >= 0) jac(row, ib + 2) = scale;
  };

  for (int k = 0; k < static_cast<int>(mechanism_.joints.size()); ++k) {
    const Joint& j = mechanism_.joints[k];
    const int row = FirstRowOf(k);
    if (j.type == JointType::kRevolute) {
      if (const int ia = coordinate_[j.link_a]; ia >= 0) {
        const Eigen::Vector2d t = Perp(arm(j.link_a, j.point_a));
        jac(row, ia) = 1.0;
        jac(row + 1, ia + 1) = 1.0;
        jac(row, ia + 2) = t.x();
        jac(row + 1, ia + 2) = t.y();
      }
      if (const int ib = coordinate_[j.link_b]; ib >= 0) {
        const Eigen::Vector2d t = Perp(arm(j.link_b, j.point_b));
        jac(row, ib) = -1.0;
        jac(row + 1, ib + 1) = -1.0;
        jac(row, ib + 2) = -t.x();
        jac(row + 1, ib + 2) = -t.y();
      }
    } else {
      line_row(row, j, Perp(j.axis));
      angle_row(row + 1, j);
    }
  }
  const Joint& drive_joint = mechanism_.joints[mechanism_.drive.joint];
  if (drive_joint.type == JointType::kRevolute) {
    angle_row(DriveRow(), drive_joint);
  } else {
    line_row(DriveRow(), drive_joint, drive_joint.axis);
  }
}

}  // namespace koppel

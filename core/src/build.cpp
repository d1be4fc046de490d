#include "koppel/core/build.hpp"

#include <stdexcept>

namespace koppel {
namespace {

int LinkIndex(const Mechanism& m, const std::string& link) {
  const int index = m.FindLink(link);
  if (index < 0) throw std::invalid_argument("mechanism '" + m.name + "' has no link '" + link + "'");
  return index;
}

int JointIndex(const Mechanism& m, const std::string& joint) {
  const int index = m.FindJoint(joint);
  if (index < 0) throw std::invalid_argument("mechanism '" + m.name + "' has no joint '" + joint + "'");
  return index;
}

Output& Push(Mechanism& m, const std::string& name, OutputKind kind) {
  Output o;
  o.name = name;
  o.kind = kind;
  m.outputs.push_back(o);
  return m.outputs.back();
}

}  // namespace

PointRef PointByName(const Mechanism& m, const std::string& link, const std::string& point) {
  const int l = LinkIndex(m, link);
  const int p = m.links[l].FindPoint(point);
  if (p < 0) throw std::invalid_argument("link '" + link + "' has no point '" + point + "'");
  return {l, p};
}

int AddLink(Mechanism& m, const std::string& name, const PointList& points, bool frame) {
  Link link;
  link.name = name;
  link.is_frame = frame;
  for (const auto& [point, local] : points) link.points.push_back({point, local});
  m.links.push_back(std::move(link));
  return static_cast<int>(m.links.size()) - 1;
}

Joint& Revolute(Mechanism& m, const std::string& name, const std::string& link_a, const std::string& link_b,
                const std::string& point_a, const std::string& point_b) {
  Joint j;
  j.name = name;
  j.type = JointType::kRevolute;
  const PointRef a = PointByName(m, link_a, point_a.empty() ? name : point_a);
  const PointRef b = PointByName(m, link_b, point_b.empty() ? name : point_b);
  j.link_a = a.link;
  j.point_a = a.point;
  j.link_b = b.link;
  j.point_b = b.point;
  m.joints.push_back(j);
  return m.joints.back();
}

Joint& Prismatic(Mechanism& m, const std::string& name, const std::string& guide, const std::string& on_guide,
                 const std::string& block, const std::string& on_block, const Eigen::Vector2d& axis, double angle) {
  if (!(axis.norm() > 0)) throw std::invalid_argument("joint '" + name + "': the slide axis has no direction");
  Joint j;
  j.name = name;
  j.type = JointType::kPrismatic;
  const PointRef a = PointByName(m, guide, on_guide);
  const PointRef b = PointByName(m, block, on_block);
  j.link_a = a.link;
  j.point_a = a.point;
  j.link_b = b.link;
  j.point_b = b.point;
  j.axis = axis.normalized();
  j.angle = angle;
  m.joints.push_back(j);
  return m.joints.back();
}

void SetDrive(Mechanism& m, const std::string& joint, double zero, const std::string& input_name) {
  m.drive.joint = JointIndex(m, joint);
  m.drive.zero = zero;
  m.drive.input_name = input_name;
}

Output& JointOutput(Mechanism& m, const std::string& name, const std::string& joint) {
  const int j = JointIndex(m, joint);
  Output& o = Push(m, name, OutputKind::kJoint);
  o.joint = j;
  return o;
}

Output& LinkAngleOutput(Mechanism& m, const std::string& name, const std::string& link) {
  const int l = LinkIndex(m, link);
  Output& o = Push(m, name, OutputKind::kLinkAngle);
  o.link = l;
  return o;
}

Output& PointOutput(Mechanism& m, const std::string& name, const std::string& link, const std::string& point) {
  const PointRef p = PointByName(m, link, point);
  Output& o = Push(m, name, OutputKind::kPoint);
  o.p = p;
  return o;
}

Output& DistanceOutput(Mechanism& m, const std::string& name, const std::string& link_p, const std::string& p,
                       const std::string& link_q, const std::string& q) {
  const PointRef from = PointByName(m, link_p, p), to = PointByName(m, link_q, q);
  Output& o = Push(m, name, OutputKind::kDistance);
  o.p = from;
  o.q = to;
  return o;
}

Output& DirectionOutput(Mechanism& m, const std::string& name, const std::string& link_p, const std::string& p,
                        const std::string& link_q, const std::string& q) {
  const PointRef from = PointByName(m, link_p, p), to = PointByName(m, link_q, q);
  Output& o = Push(m, name, OutputKind::kDirection);
  o.p = from;
  o.q = to;
  return o;
}

Output& TransmissionOutput(Mechanism& m, const std::string& name, const std::string& coupler, const std::string& joint) {
  const int l = LinkIndex(m, coupler), j = JointIndex(m, joint);
  Output& o = Push(m, name, OutputKind::kTransmissionAngle);
  o.link = l;
  o.joint = j;
  return o;
}

void HintInput(Mechanism& m, double input) { m.hint.input = input; }

void HintPoint(Mechanism& m, const std::string& link, const std::string& point, const Eigen::Vector2d& global) {
  m.hint.points.push_back({PointByName(m, link, point), global});
}

}  // namespace koppel

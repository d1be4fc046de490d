#include "koppel/core/structure.hpp"

namespace koppel {

StructureSummary AnalyseStructure(const Mechanism& m) {
  StructureSummary s;
  s.links = static_cast<int>(m.links.size());
  s.joints = static_cast<int>(m.joints.size());
  std::vector<int> degree(m.links.size(), 0);
  const int frame = m.FrameLink();
  for (int j = 0; j < s.joints; ++j) {
    const Joint& joint = m.joints[j];
    ++degree[joint.link_a];
    ++degree[joint.link_b];
    (joint.type == JointType::kRevolute ? s.revolute : s.prismatic) += 1;
    const bool is_drive = (j == m.drive.joint);
    if (is_drive) {
      s.drive_joints = 1;
      s.drive_joints_at_frame = (joint.link_a == frame || joint.link_b == frame) ? 1 : 0;
    }
    s.formula += joint.name + ": " + (joint.type == JointType::kRevolute ? "D " : "S ") +
                 m.links[joint.link_a].name + "-" + m.links[joint.link_b].name +
                 (is_drive ? " (drive)" : "") + "\n";
  }
  for (int d : degree) ++s.links_by_degree[d];
  // Grübler–Kutzbach for planar joints of one degree of freedom each.
  s.gruebler_mobility = 3 * (s.links - 1) - 2 * s.joints;
  return s;
}

int OutputLink(const Mechanism& m, const Output& output) {
  switch (output.kind) {
    case OutputKind::kJoint: {
      const Joint& j = m.joints[output.joint];
      return m.links[j.link_b].is_frame ? j.link_a : j.link_b;
    }
    case OutputKind::kLinkAngle:
      return output.link;
    case OutputKind::kPoint:
      return output.p.link;
    case OutputKind::kDistance:
    case OutputKind::kDirection:
      return output.p.link == output.q.link ? output.p.link : -1;
    case OutputKind::kTransmissionAngle:
      return -1;
  }
  return -1;
}

double CrankLength(const Mechanism& m) {
  const Joint& drive = m.joints[m.drive.joint];
  const int crank = m.links[drive.link_a].is_frame ? drive.link_b : drive.link_a;
  const int pivot = drive.link_a == crank ? drive.point_a : drive.point_b;
  for (int k = 0; k < static_cast<int>(m.joints.size()); ++k) {
    const Joint& j = m.joints[k];
    if (k == m.drive.joint || (j.link_a != crank && j.link_b != crank)) continue;
    const int p = j.link_a == crank ? j.point_a : j.point_b;
    return (m.links[crank].points[p].local - m.links[crank].points[pivot].local).norm();
  }
  return 0.0;
}

std::string DegreeName(int degree) {
  static const char* kNames[] = {"isolated", "unary", "binary", "ternary", "quaternary", "quinary", "senary"};
  if (degree >= 0 && degree <= 6) return kNames[degree];
  return std::to_string(degree) + "-ary";
}

}  // namespace koppel

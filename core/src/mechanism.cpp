#include "koppel/core/mechanism.hpp"

#include <algorithm>
#include <cmath>

namespace koppel {
namespace {

template <class Items>
int FindByName(const Items& items, const std::string& name) {
  for (int i = 0; i < static_cast<int>(items.size()); ++i) {
    if (items[i].name == name) return i;
  }
  return -1;
}

bool PointRefValid(const Mechanism& m, const PointRef& ref) {
  if (ref.link < 0 || ref.link >= static_cast<int>(m.links.size())) return false;
  return ref.point >= 0 && ref.point < static_cast<int>(m.links[ref.link].points.size());
}

}  // namespace

std::string ComponentName(const std::string& name, int c) { return name + (c == 0 ? "_x" : "_y"); }

std::optional<std::pair<std::string, int>> SplitComponentName(const std::string& name) {
  if (name.size() <= 2 || !(name.ends_with("_x") || name.ends_with("_y"))) return std::nullopt;
  return std::pair(name.substr(0, name.size() - 2), name.back() == 'x' ? 0 : 1);
}

std::string Output::ComponentLabel(int c) const { return Components() == 2 ? ComponentName(name, c) : name; }

int Link::FindPoint(const std::string& point_name) const { return FindByName(points, point_name); }

bool Mechanism::OutputIsAngle(int output) const { return IsAngleOutput(*this, outputs[output]); }

bool IsAngleOutput(const Mechanism& m, const Output& o) {
  switch (o.kind) {
    case OutputKind::kJoint:
      return o.joint >= 0 && o.joint < static_cast<int>(m.joints.size()) && m.joints[o.joint].type == JointType::kRevolute;
    case OutputKind::kLinkAngle:
    case OutputKind::kDirection:
    case OutputKind::kTransmissionAngle: return true;
    case OutputKind::kPoint:
    case OutputKind::kDistance: return false;
  }
  return false;
}

int Mechanism::FindLink(const std::string& link_name) const { return FindByName(links, link_name); }
int Mechanism::FindJoint(const std::string& joint_name) const { return FindByName(joints, joint_name); }
int Mechanism::FindOutput(const std::string& output_name) const { return FindByName(outputs, output_name); }

int Mechanism::FrameLink() const {
  for (int i = 0; i < static_cast<int>(links.size()); ++i) {
    if (links[i].is_frame) return i;
  }
  return -1;
}

bool Mechanism::InputIsAngle() const {
  return drive.joint >= 0 && joints[drive.joint].type == JointType::kRevolute;
}

Joint PinJoint(const Mechanism& m, const std::string& name, int link_a, int link_b) {
  Joint j;
  j.name = name;
  j.type = JointType::kRevolute;
  j.link_a = link_a;
  j.link_b = link_b;
  j.point_a = m.links[link_a].FindPoint(name);
  j.point_b = m.links[link_b].FindPoint(name);
  return j;
}

PointRef JointPointOn(const Joint& j, int link) {
  return j.link_a == link ? PointRef{j.link_a, j.point_a} : PointRef{j.link_b, j.point_b};
}

int OtherJointOfBinaryLink(const Mechanism& m, int link, int joint) {
  int other = -1, count = 0;
  for (int k = 0; k < static_cast<int>(m.joints.size()); ++k) {
    if (m.joints[k].link_a != link && m.joints[k].link_b != link) continue;
    ++count;
    if (k != joint) other = k;
  }
  return count == 2 ? other : -1;
}

Mechanism MirrorMechanism(const Mechanism& original) {
  // global reflection M = diag(1, -1): pose (x, y, theta) -> (x, -y, -theta), and with body
  // points reflected too, R(-theta) M p = M R(theta) p keeps every joint closed
  Mechanism m = original;
  auto flip = [](Eigen::Vector2d v) { return Eigen::Vector2d(v.x(), -v.y()); };
  for (Link& link : m.links) {
    for (NamedPoint& p : link.points) p.local = flip(p.local);
  }
  for (Joint& j : m.joints) {
    j.axis = flip(j.axis);
    j.angle = -j.angle;
  }
  const bool angle_input = m.InputIsAngle();
  if (angle_input) {
    m.drive.zero = -m.drive.zero;
    m.hint.input = -m.hint.input;
  }
  for (Output& o : m.outputs) o.offset = -o.offset;
  for (AssemblyHint::Entry& e : m.hint.points) e.global = flip(e.global);
  return m;
}

std::vector<std::string> CheckConsistency(const Mechanism& m) {
  std::vector<std::string> problems;
  const int n_links = static_cast<int>(m.links.size());
  const auto frames = std::count_if(m.links.begin(), m.links.end(), [](const Link& l) { return l.is_frame; });
  if (frames != 1) problems.push_back("a mechanism needs exactly one frame link, found " + std::to_string(frames));
  for (const Joint& j : m.joints) {
    const std::string where = "joint '" + j.name + "'";
    if (j.link_a < 0 || j.link_a >= n_links || j.link_b < 0 || j.link_b >= n_links) {
      problems.push_back(where + " names a link that does not exist");
      continue;
    }
    if (j.link_a == j.link_b) problems.push_back(where + " joins link '" + m.links[j.link_a].name + "' to itself");
    if (!PointRefValid(m, {j.link_a, j.point_a}) || !PointRefValid(m, {j.link_b, j.point_b}))
      problems.push_back(where + " names a point that does not exist");
    if (j.type == JointType::kPrismatic && std::abs(j.axis.norm() - 1.0) > 1e-12)
      problems.push_back(where + " has a slide axis that is not a unit vector");
  }
  if (m.drive.joint < 0 || m.drive.joint >= static_cast<int>(m.joints.size()))
    problems.push_back("the drive names no joint");
  for (const Output& o : m.outputs) {
    const std::string where = "output '" + o.name + "'";
    switch (o.kind) {
      case OutputKind::kJoint:
        if (o.joint < 0 || o.joint >= static_cast<int>(m.joints.size())) problems.push_back(where + " names no joint");
        break;
      case OutputKind::kLinkAngle:
        if (o.link < 0 || o.link >= n_links) problems.push_back(where + " names no link");
        break;
      case OutputKind::kPoint:
        if (!PointRefValid(m, o.p)) problems.push_back(where + " names no point");
        break;
      case OutputKind::kDistance:
      case OutputKind::kDirection:
        if (!PointRefValid(m, o.p) || !PointRefValid(m, o.q)) problems.push_back(where + " names no point");
        break;
      case OutputKind::kTransmissionAngle:
        if (o.joint < 0 || o.joint >= static_cast<int>(m.joints.size()) || o.link < 0 || o.link >= n_links)
          problems.push_back(where + " needs a coupler link and an output joint");
        break;
    }
  }
  for (const AssemblyHint::Entry& e : m.hint.points) {
    if (!PointRefValid(m, e.point)) problems.push_back("an assembly hint names no point");
  }
  return problems;
}

double LengthScale(const Mechanism& m) {
  double scale = 0.0;
  for (const Link& link : m.links) {
    for (const NamedPoint& p : link.points) scale = std::max(scale, p.local.norm());
  }
  // No floor: a mechanism drawn in micrometres or kilometres keeps its own scale, so that every
  // tolerance built on it gives the same dimensionless results.
  return scale > 0.0 ? scale : 1.0;
}

Expected<PointRef> FindPointByText(const Mechanism& m, const std::string& text) {
  const int output = m.FindOutput(text);
  if (output >= 0 && m.outputs[output].kind == OutputKind::kPoint) return m.outputs[output].p;
  const auto dot = text.find('.');
  if (dot != std::string::npos) {
    const int link = m.FindLink(text.substr(0, dot));
    if (link >= 0) {
      const int point = m.links[link].FindPoint(text.substr(dot + 1));
      if (point >= 0) return PointRef{link, point};
    }
  } else {
    std::vector<PointRef> found;
    for (int l = 0; l < static_cast<int>(m.links.size()); ++l) {
      if (const int p = m.links[l].FindPoint(text); p >= 0) found.push_back({l, p});
    }
    if (found.size() == 1) return found[0];
    if (found.size() > 1) {
      std::string links;
      for (const PointRef& r : found) links += " " + m.links[r.link].name + "." + text;
      return Expected<PointRef>::Error("point '" + text + "' is on several links; name one:" + links);
    }
  }
  return Expected<PointRef>::Error("no point '" + text + "' (give a point output, link.point, or a point name)");
}

Expected<int> FindScalarOutput(const Mechanism& m, const std::string& name) {
  std::string scalars;
  for (int o = 0; o < static_cast<int>(m.outputs.size()); ++o) {
    if (m.outputs[o].Components() != 1) continue;
    if (name.empty() || m.outputs[o].name == name) return o;
    scalars += (scalars.empty() ? "" : ", ") + m.outputs[o].name;
  }
  if (name.empty()) return Expected<int>::Error("the mechanism declares no scalar output (outputs: an angle or a distance, see README)");
  return Expected<int>::Error("has no scalar output '" + name + "'" + (scalars.empty() ? "" : " (its scalar outputs: " + scalars + ")"));
}

}  // namespace koppel

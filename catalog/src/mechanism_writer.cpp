#include "koppel/catalog/mechanism_writer.hpp"

#include "koppel/core/angles.hpp"

#include <fmt/core.h>

#include <sstream>

namespace koppel {
namespace {

std::string Num(double v) {
  if (v == 0.0) return "0";
  return fmt::format("{:.17g}", v);
}

std::string PointName(const Mechanism& m, const PointRef& p) { return m.links[p.link].name + "." + m.links[p.link].points[p.point].name; }

}  // namespace

std::string WriteMechanismYaml(const Mechanism& m, const std::string& comment, const SweepDefaults& sweep,
                               const std::vector<std::pair<std::string, double>>& parameters) {
  std::ostringstream out;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "# " << line << "\n";
  const bool angle = m.InputIsAngle();
  out << "koppel: 1\nname: " << m.name << "\n";
  if (!parameters.empty()) {
    out << "parameters:\n";
    for (const auto& [n, v] : parameters) out << "  " << n << ": " << Num(v) << "\n";
  }
  out << "links:\n";
  for (const Link& l : m.links) {
    out << "  " << l.name << ":\n";
    if (l.is_frame) out << "    frame: true\n";
    out << "    points:\n";
    for (const NamedPoint& p : l.points) out << "      " << p.name << ": [" << Num(p.local.x()) << ", " << Num(p.local.y()) << "]\n";
  }
  out << "joints:\n";
  for (const Joint& j : m.joints) {
    out << "  " << j.name << ": {type: " << (j.type == JointType::kRevolute ? "R" : "P") << ", links: [" << m.links[j.link_a].name
        << ", " << m.links[j.link_b].name << "], points: [" << m.links[j.link_a].points[j.point_a].name << ", "
        << m.links[j.link_b].points[j.point_b].name << "]";
    if (j.type == JointType::kPrismatic) out << ", axis: [" << Num(j.axis.x()) << ", " << Num(j.axis.y()) << "], angle: " << Num(RadToDeg(j.angle));
    out << "}\n";
  }
  out << "drive: {joint: " << m.joints[m.drive.joint].name << ", zero: " << Num(angle ? RadToDeg(m.drive.zero) : m.drive.zero)
      << ", name: " << m.drive.input_name << "}\n";
  if (!m.outputs.empty()) {
    out << "outputs:\n";
    for (const Output& o : m.outputs) {
      out << "  " << o.name << ": {";
      switch (o.kind) {
        case OutputKind::kJoint: out << "joint: " << m.joints[o.joint].name; break;
        case OutputKind::kLinkAngle: out << "link: " << m.links[o.link].name; break;
        case OutputKind::kPoint: out << "point: " << PointName(m, o.p); break;
        case OutputKind::kDistance: out << "distance: [" << PointName(m, o.p) << ", " << PointName(m, o.q) << "]"; break;
        case OutputKind::kDirection: out << "direction: [" << PointName(m, o.p) << ", " << PointName(m, o.q) << "]"; break;
        case OutputKind::kTransmissionAngle:
          out << "transmission: {coupler: " << m.links[o.link].name << ", joint: " << m.joints[o.joint].name << "}";
          break;
      }
      const bool zero_allowed = o.kind == OutputKind::kLinkAngle || o.kind == OutputKind::kDirection ||
                                (o.kind == OutputKind::kJoint && m.joints[o.joint].type == JointType::kRevolute);
      if (zero_allowed && o.offset != 0.0) out << ", zero: " << Num(RadToDeg(o.offset));
      out << "}\n";
    }
  }
  if (!m.hint.points.empty()) {
    out << "assembly:\n  input: " << Num(angle ? RadToDeg(m.hint.input) : m.hint.input) << "\n  points:\n";
    for (const AssemblyHint::Entry& e : m.hint.points)
      out << "    " << PointName(m, e.point) << ": [" << Num(e.global.x()) << ", " << Num(e.global.y()) << "]\n";
  }
  out << "sweep: {from: " << Num(sweep.from) << ", to: " << Num(sweep.to) << ", step: " << Num(sweep.step) << "}\n";
  return out.str();
}

}  // namespace koppel

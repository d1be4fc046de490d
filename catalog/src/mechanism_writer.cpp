#include "koppel/catalog/mechanism_writer.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/printable_text.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace koppel {
namespace {

std::string Num(double v) {
  if (v == 0.0) return "0";
  return fmt::format("{:.17g}", v);
}

// A formula as a double-quoted YAML string (a plain scalar could read as an alias or a number).
std::string Quoted(const std::string& text) {
  std::string q = "\"";
  for (char c : text) q += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return q + "\"";
}

// A name as YAML reads it back: plain when it is a word (a letter or '_', then letters, digits,
// '_', '-') that YAML does not take for null or a truth value; double-quoted otherwise (quotes,
// commas, ':', '#', '<', spaces, any script), a character that is not printable (the reader would
// refuse it; koppel/core/printable_text.hpp) written as U+FFFD.
std::string Name(const std::string& name) {
  static const char* const kYamlWords[] = {"null", "true", "false", "yes", "no", "on", "off", "y", "n"};
  const auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; };
  bool plain = !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') &&
               std::all_of(name.begin(), name.end(), word_char);
  std::string lower = name;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* word : kYamlWords) plain &= lower != word;
  return plain ? name : Quoted(PrintableText(name, Replacement::kReplacementCharacter));
}

std::string PointName(const Mechanism& m, const PointRef& p) {
  return Name(m.links[p.link].name + "." + m.links[p.link].points[p.point].name);
}

void WriteMass(std::ostringstream& out, const Loads& loads, long link) {
  for (const LinkMass& mass : loads.masses) {
    if (mass.link != link) continue;
    out << "    mass: " << Num(mass.mass) << "\n    cg: [" << Num(mass.centre.x()) << ", " << Num(mass.centre.y()) << "]\n"
        << "    inertia: " << Num(mass.inertia) << "\n";
  }
}

void WriteLoads(std::ostringstream& out, const Mechanism& m, const Loads& loads) {
  if (!loads.length_unit_name.empty()) {
    out << "units: {length: " << loads.length_unit_name << "}\n";
  } else if (loads.length_unit_given || loads.metres_per_unit != 1.0) {
    out << "units: {length: " << Num(loads.metres_per_unit) << "}\n";
  }
  if (loads.gravity.squaredNorm() > 0.0) out << "gravity: [" << Num(loads.gravity.x()) << ", " << Num(loads.gravity.y()) << "]\n";
  if (loads.forces.empty() && loads.torques.empty() && loads.springs.empty()) return;
  out << "loads:\n";
  for (const PointForce& f : loads.forces) {
    out << "  " << Name(f.name) << ": {force: " << PointName(m, f.point) << ", direction: [" << Num(f.direction.x()) << ", "
        << Num(f.direction.y()) << "], in: " << Name(m.links[f.direction_link].name) << ", magnitude: " << Quoted(f.magnitude) << "}\n";
  }
  for (const LinkTorque& t : loads.torques)
    out << "  " << Name(t.name) << ": {torque: " << Name(m.links[t.link].name) << ", magnitude: " << Quoted(t.magnitude) << "}\n";
  for (const SpringDamper& s : loads.springs) {
    out << "  " << Name(s.name) << ": {spring: [" << PointName(m, s.from) << ", " << PointName(m, s.to) << "], stiffness: " << Num(s.stiffness)
        << ", free_length: " << Num(s.free_length) << ", damping: " << Num(s.damping) << "}\n";
  }
}

}  // namespace

std::string WriteMechanismYaml(const Mechanism& m, const std::string& comment, const SweepDefaults& sweep,
                               const std::vector<std::pair<std::string, double>>& parameters, const Loads* loads) {
  std::ostringstream out;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "# " << line << "\n";
  const bool angle = m.InputIsAngle();
  out << "koppel: 1\nname: " << Name(m.name) << "\n";
  if (!parameters.empty()) {
    out << "parameters:\n";
    for (const auto& [n, v] : parameters) out << "  " << Name(n) << ": " << Num(v) << "\n";
  }
  out << "links:\n";
  for (const Link& l : m.links) {
    out << "  " << Name(l.name) << ":\n";
    if (l.is_frame) out << "    frame: true\n";
    out << "    points:\n";
    for (const NamedPoint& p : l.points) out << "      " << Name(p.name) << ": [" << Num(p.local.x()) << ", " << Num(p.local.y()) << "]\n";
    if (loads) WriteMass(out, *loads, &l - m.links.data());
  }
  out << "joints:\n";
  for (const Joint& j : m.joints) {
    out << "  " << Name(j.name) << ": {type: " << (j.type == JointType::kRevolute ? "R" : "P") << ", links: [" << Name(m.links[j.link_a].name) << ", " << Name(m.links[j.link_b].name)
        << "], points: [" << Name(m.links[j.link_a].points[j.point_a].name) << ", " << Name(m.links[j.link_b].points[j.point_b].name) << "]";
    if (j.type == JointType::kPrismatic) out << ", axis: [" << Num(j.axis.x()) << ", " << Num(j.axis.y()) << "], angle: " << Num(RadToDeg(j.angle));
    out << "}\n";
  }
  out << "drive: {joint: " << Name(m.joints[m.drive.joint].name) << ", zero: " << Num(angle ? RadToDeg(m.drive.zero) : m.drive.zero)
      << ", name: " << Name(m.drive.input_name) << "}\n";
  if (!m.outputs.empty()) {
    out << "outputs:\n";
    for (const Output& o : m.outputs) {
      out << "  " << Name(o.name) << ": {";
      switch (o.kind) {
        case OutputKind::kJoint: out << "joint: " << Name(m.joints[o.joint].name); break;
        case OutputKind::kLinkAngle: out << "link: " << Name(m.links[o.link].name); break;
        case OutputKind::kPoint: out << "point: " << PointName(m, o.p); break;
        case OutputKind::kDistance: out << "distance: [" << PointName(m, o.p) << ", " << PointName(m, o.q) << "]"; break;
        case OutputKind::kDirection: out << "direction: [" << PointName(m, o.p) << ", " << PointName(m, o.q) << "]"; break;
        case OutputKind::kTransmissionAngle:
          out << "transmission: {coupler: " << Name(m.links[o.link].name) << ", joint: " << Name(m.joints[o.joint].name) << "}";
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
  if (loads) WriteLoads(out, m, *loads);
  return out.str();
}

}  // namespace koppel

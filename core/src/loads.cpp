#include "koppel/core/loads.hpp"

#include <iomanip>
#include <sstream>

#include <cmath>

namespace koppel {

std::string Loads::LengthUnit() const {
  if (!length_unit_name.empty()) return length_unit_name;
  if (!length_unit_given) return "length";
  std::ostringstream text;
  text << std::setprecision(12) << metres_per_unit << " m";
  return text.str();
}

bool Loads::HasMass() const {
  for (const LinkMass& m : masses) {
    if (m.mass > 0.0 || m.inertia > 0.0) return true;
  }
  return false;
}

std::vector<std::string> LoadVariables(const Mechanism& mechanism) {
  std::vector<std::string> names = {mechanism.drive.input_name, mechanism.drive.input_name + "_dot", "t"};
  for (const Output& o : mechanism.outputs) {
    for (int c = 0; c < o.Components(); ++c) names.push_back(o.ComponentLabel(c));
  }
  return names;
}

std::vector<std::string> CheckLoads(const Mechanism& m, const Loads& loads) {
  std::vector<std::string> problems;
  const int links = static_cast<int>(m.links.size());
  auto link_ok = [&](int link) { return link >= 0 && link < links; };
  auto point_ok = [&](const PointRef& p) {
    return link_ok(p.link) && p.point >= 0 && p.point < static_cast<int>(m.links[p.link].points.size());
  };
  auto non_negative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!(std::isfinite(loads.metres_per_unit) && loads.metres_per_unit > 0.0)) problems.push_back("the length unit must be a positive number of metres");
  if (!loads.gravity.allFinite()) problems.push_back("gravity must be finite");
  std::vector<bool> has_mass(links, false);
  for (const LinkMass& mass : loads.masses) {
    if (!link_ok(mass.link)) {
      problems.push_back("a mass names no link");
      continue;
    }
    const std::string& name = m.links[mass.link].name;
    if (m.links[mass.link].is_frame) problems.push_back("link '" + name + "' is the frame: it does not move, so it takes no mass");
    if (has_mass[mass.link]) problems.push_back("link '" + name + "' has two masses");
    has_mass[mass.link] = true;
    if (!non_negative(mass.mass) || !non_negative(mass.inertia) || !mass.centre.allFinite())
      problems.push_back("link '" + name + "': mass and moment of inertia must be finite and not negative");
  }
  for (const PointForce& f : loads.forces) {
    if (!point_ok(f.point) || !link_ok(f.direction_link)) problems.push_back("force '" + f.name + "' names no point or link");
    if (!(std::abs(f.direction.norm() - 1.0) < 1e-12)) problems.push_back("force '" + f.name + "' needs a unit direction");
  }
  for (const LinkTorque& t : loads.torques) {
    if (!link_ok(t.link)) problems.push_back("torque '" + t.name + "' names no link");
  }
  for (const SpringDamper& s : loads.springs) {
    if (!point_ok(s.from) || !point_ok(s.to)) problems.push_back("spring '" + s.name + "' names no point");
    if (!non_negative(s.stiffness) || !non_negative(s.free_length) || !non_negative(s.damping))
      problems.push_back("spring '" + s.name + "': stiffness, free length and damping must be finite and not negative");
  }
  return problems;
}

}  // namespace koppel

// The masses and loads of a mechanism file: links.*.{mass, cg, inertia}, units, gravity, loads
// (format in README.md, "Masses and loads"). Every problem is reported at its line like the rest
// of the file's.
#include "koppel/catalog/length_units.hpp"
#include "koppel/core/formula.hpp"
#include "koppel/core/limits.hpp"
#include "yaml_reader.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace koppel {
namespace {

class LoadsReader {
 public:
  LoadsReader(YamlReader& reader, MechanismFile& file) : r_(reader), file_(file), m_(file.mechanism), loads_(file.loads) {}

  void Read(const YAML::Node& root) {
    loads_.parameters = file_.parameters;
    if (const YAML::Node u = root["units"]; u.IsDefined() && !u.IsNull()) ReadUnits(u);
    if (const YAML::Node g = root["gravity"]; g.IsDefined() && !g.IsNull()) {
      if (auto v = r_.Vector(g, "gravity")) loads_.gravity = *v;
    }
    if (const YAML::Node links = root["links"]; links.IsMap()) {
      for (auto it = links.begin(); it != links.end(); ++it) {
        if (it->first.IsScalar() && it->second.IsMap()) ReadMass(it->first.Scalar(), it->second);
      }
    }
    if (const YAML::Node l = root["loads"]; l.IsDefined() && !l.IsNull()) {
      CheckNameClashes(root["parameters"]);
      ReadLoads(l);
    }
  }

 private:
  void ReadUnits(const YAML::Node& node) {
    if (!r_.ExpectMap(node, "units")) return;
    r_.CheckKeys(node, "units", {"length"});
    const YAML::Node length = node["length"];
    if (!length.IsDefined() || length.IsNull()) return;
    if (length.IsScalar()) {
      for (const auto& [name, metres] : NamedLengthUnits()) {
        if (name != length.Scalar()) continue;
        loads_.metres_per_unit = metres;
        loads_.length_unit_given = true;
        loads_.length_unit_name = name;
        return;
      }
    }
    // a unit's name that is not one of koppel's (inch, feet): say which names there are, rather
    // than that the word is no formula
    if (length.IsScalar()) {
      const std::string& word = length.Scalar();
      const bool is_word = !word.empty() && std::all_of(word.begin(), word.end(), [](unsigned char c) { return std::isalpha(c) != 0; });
      if (is_word && !file_.parameters.Has(word)) {
        r_.Error(length, "units.length",
                 "unknown length unit '" + word + "': the length unit must be " + NamedLengthUnitList() + " or a positive number of metres");
        return;
      }
    }
    const std::optional<double> metres = r_.Number(length, "units.length");
    if (!metres) return;
    if (!(*metres > 0.0)) {
      r_.Error(length, "units.length", "the length unit must be " + NamedLengthUnitList() + " or a positive number of metres");
      return;
    }
    // forces and energies scale with powers of the unit: beyond these they overflow a double
    if (*metres < kMinLengthUnit || *metres > kMaxLengthUnit) {
      r_.Error(length, "units.length",
               fmt::format("a length unit of {:g} m is outside {:g} to {:g} m (kMinLengthUnit, kMaxLengthUnit)", *metres,
                           kMinLengthUnit, kMaxLengthUnit));
      return;
    }
    loads_.metres_per_unit = *metres;
    loads_.length_unit_given = true;
  }

  void ReadMass(const std::string& link_name, const YAML::Node& node) {
    const YAML::Node mass = node["mass"], cg = node["cg"], inertia = node["inertia"];
    if (!mass.IsDefined() && !cg.IsDefined() && !inertia.IsDefined()) return;
    const std::string path = Child("links", link_name);
    const int link = m_.FindLink(link_name);
    if (link < 0) return;  // reported with the links
    const YAML::Node where = mass.IsDefined() ? mass : (cg.IsDefined() ? cg : inertia);
    if (m_.links[link].is_frame) {
      r_.Error(where, path, "link '" + link_name + "' is the frame: it does not move, so it takes no mass");
      return;
    }
    LinkMass entry;
    entry.link = link;
    bool ok = true;
    if (!mass.IsDefined() || !cg.IsDefined()) {
      r_.Error(where, path, "link '" + link_name + "': give its mass and its centre of gravity (cg) together");
      ok = false;
    }
    if (mass.IsDefined()) ok &= NonNegative(mass, Child(path, "mass"), &entry.mass);
    if (inertia.IsDefined()) ok &= NonNegative(inertia, Child(path, "inertia"), &entry.inertia);
    if (cg.IsDefined()) {
      if (cg.IsScalar()) {
        const int point = m_.links[link].FindPoint(cg.Scalar());
        if (point < 0) {
          r_.Error(cg, Child(path, "cg"), "link '" + link_name + "' has no point '" + cg.Scalar() + "' (give a point name or [x, y])");
          ok = false;
        } else {
          entry.centre = m_.links[link].points[point].local;
        }
      } else if (auto v = r_.Vector(cg, Child(path, "cg"))) {
        entry.centre = *v;
      } else {
        ok = false;
      }
    }
    if (ok) loads_.masses.push_back(entry);
  }

  bool NonNegative(const YAML::Node& node, const std::string& path, double* value) {
    const std::optional<double> v = r_.Number(node, path);
    if (!v) return false;
    if (*v < 0.0) {
      r_.Error(node, path, "must not be negative");
      return false;
    }
    *value = *v;
    return true;
  }

  // "link.point"
  std::optional<PointRef> Point(const YAML::Node& node, const std::string& path, const std::string& owner) {
    const std::optional<std::string> text = r_.Text(node, path);
    if (!text) return std::nullopt;
    const auto dot = text->find('.');
    const int link = dot == std::string::npos ? -1 : m_.FindLink(text->substr(0, dot));
    const int point = link < 0 ? -1 : m_.links[link].FindPoint(text->substr(dot + 1));
    if (point < 0) {
      r_.Error(node, path, owner + ": '" + *text + "' is no point of the mechanism (expected link.point)");
      return std::nullopt;
    }
    return PointRef{link, point};
  }

  int LinkOf(const YAML::Node& node, const std::string& path, const std::string& owner) {
    const std::optional<std::string> name = r_.Text(node, path);
    if (!name) return -1;
    const int link = m_.FindLink(*name);
    if (link < 0) r_.Error(node, path, owner + " names unknown link '" + *name + "'");
    return link;
  }

  // A magnitude formula: compiled now, so that a typo is reported at its line.
  std::optional<std::string> Magnitude(const YAML::Node& map, const std::string& path, const std::string& owner) {
    const YAML::Node node = r_.Require(map, "magnitude", path);
    if (!node.IsDefined() || node.IsNull()) return std::nullopt;
    const std::optional<std::string> text = r_.Text(node, Child(path, "magnitude"));
    if (!text) return std::nullopt;
    if (const Expected<CompiledFormula> f = CompiledFormula::Compile(*text, loads_.parameters, LoadVariables(m_)); !f) {
      r_.Error(node, Child(path, "magnitude"), owner + ": " + f.error());
      return std::nullopt;
    }
    return text;
  }

  void ReadLoads(const YAML::Node& node) {
    for (const YamlReader::Entry& e : r_.Entries(node, "loads")) {
      const std::string path = Child("loads", e.key);
      if (!r_.CheckName(e.key_node, path, "load", e.key) || !r_.ExpectMap(e.value, path)) continue;
      const int kinds = e.value["force"].IsDefined() + e.value["torque"].IsDefined() + e.value["spring"].IsDefined() +
                        e.value["damper"].IsDefined();
      if (kinds != 1) {
        r_.Error(e.value, path, "load '" + e.key + "': give exactly one of force, torque, spring, damper");
        continue;
      }
      if (e.value["force"].IsDefined()) ReadForce(e, path);
      if (e.value["torque"].IsDefined()) ReadTorque(e, path);
      if (e.value["spring"].IsDefined() || e.value["damper"].IsDefined()) ReadSpring(e, path);
    }
  }

  void ReadForce(const YamlReader::Entry& e, const std::string& path) {
    const std::string owner = "force '" + e.key + "'";
    r_.CheckKeys(e.value, path, {"force", "direction", "in", "magnitude"});
    PointForce f;
    f.name = e.key;
    f.direction_link = m_.FrameLink();
    const std::optional<PointRef> at = Point(e.value["force"], Child(path, "force"), owner);
    bool ok = at.has_value();
    if (at) f.point = *at;
    const YAML::Node direction = r_.Require(e.value, "direction", path);
    if (direction.IsDefined() && !direction.IsNull()) {
      const std::optional<Eigen::Vector2d> d = r_.Vector(direction, Child(path, "direction"));
      if (d && d->norm() > 0.0) {
        f.direction = d->normalized();
      } else {
        if (d) r_.Error(direction, Child(path, "direction"), owner + ": the direction must not be zero");
        ok = false;
      }
    } else {
      ok = false;
    }
    if (const YAML::Node in = e.value["in"]; in.IsDefined()) {
      f.direction_link = LinkOf(in, Child(path, "in"), owner);
      ok &= f.direction_link >= 0;
    }
    const std::optional<std::string> magnitude = Magnitude(e.value, path, owner);
    if (ok && magnitude) {
      f.magnitude = *magnitude;
      loads_.forces.push_back(f);
    }
  }

  void ReadTorque(const YamlReader::Entry& e, const std::string& path) {
    const std::string owner = "torque '" + e.key + "'";
    r_.CheckKeys(e.value, path, {"torque", "magnitude"});
    LinkTorque t;
    t.name = e.key;
    t.link = LinkOf(e.value["torque"], Child(path, "torque"), owner);
    if (t.link >= 0 && m_.links[t.link].is_frame) r_.Error(e.value["torque"], Child(path, "torque"), owner + ": the frame does not move");
    const std::optional<std::string> magnitude = Magnitude(e.value, path, owner);
    if (t.link >= 0 && !m_.links[t.link].is_frame && magnitude) {
      t.magnitude = *magnitude;
      loads_.torques.push_back(t);
    }
  }

  void ReadSpring(const YamlReader::Entry& e, const std::string& path) {
    const bool spring = e.value["spring"].IsDefined();
    const char* key = spring ? "spring" : "damper";
    const std::string owner = std::string(key) + " '" + e.key + "'";
    if (spring) {
      r_.CheckKeys(e.value, path, {"spring", "stiffness", "free_length", "damping"});
    } else {
      r_.CheckKeys(e.value, path, {"damper", "damping"});
    }
    SpringDamper s;
    s.name = e.key;
    const YAML::Node ends = e.value[key];
    bool ok = true;
    if (!ends.IsSequence() || ends.size() != 2) {
      r_.Error(ends, Child(path, key), owner + ": expected two points [link.point, link.point]");
      ok = false;
    } else {
      const auto from = Point(ends[0], Index(Child(path, key), 0), owner);
      const auto to = Point(ends[1], Index(Child(path, key), 1), owner);
      ok = from && to;
      if (ok) {
        s.from = *from;
        s.to = *to;
      }
    }
    auto number = [&](const char* name, bool required, double* value) {
      const YAML::Node v = required ? r_.Require(e.value, name, path) : e.value[name];
      if (!v.IsDefined() || v.IsNull()) return !required;
      return NonNegative(v, Child(path, name), value);
    };
    if (spring) {
      ok &= number("stiffness", true, &s.stiffness);
      ok &= number("free_length", true, &s.free_length);
      ok &= number("damping", false, &s.damping);
    } else {
      ok &= number("damping", true, &s.damping);
    }
    if (ok) loads_.springs.push_back(s);
  }

  // A parameter that has the name of a load variable (the input, its speed, t, an output) would
  // be shadowed in the formulas without a word: refuse it.
  void CheckNameClashes(const YAML::Node& parameters) {
    for (const std::string& name : LoadVariables(m_)) {
      if (!file_.parameters.Has(name)) continue;
      const YAML::Node where = parameters.IsMap() ? parameters[name] : parameters;
      r_.Error(where, Child("parameters", name), "parameter '" + name + "' has the name of a load formula variable (the input, its speed '" +
                                                     m_.drive.input_name + "_dot', the time 't' or an output): rename it");
    }
  }

  YamlReader& r_;
  MechanismFile& file_;
  const Mechanism& m_;
  Loads& loads_;
};

}  // namespace

void ReadLoads(YamlReader& reader, const YAML::Node& root, MechanismFile& file) { LoadsReader(reader, file).Read(root); }

}  // namespace koppel

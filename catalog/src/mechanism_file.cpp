#include "koppel/catalog/mechanism_file.hpp"

#include "koppel/catalog/catalog.hpp"
#include "koppel/catalog/parameter_use.hpp"

#include "mechanism_node.hpp"

#include "input_file.hpp"
#include "koppel/core/angles.hpp"
#include "koppel/core/limits.hpp"
#include "koppel/core/transmission.hpp"
#include "yaml_reader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <limits>
#include <string>
#include <utility>

namespace koppel {
namespace {

bool ValidId(const std::string& id) {
  if (id.empty()) return false;
  for (char c : id) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_')) return false;
  }
  return true;
}

// Reads one mechanism file into a MechanismFile, collecting diagnostics in `reader`.
class MechanismReader {
 public:
  MechanismReader(YamlReader& reader, MechanismFile& out) : r_(reader), out_(out), m_(out.mechanism) {}

  void Read(const YAML::Node& root, const Overrides& overrides) {
    if (!r_.ExpectMap(root, "")) return;
    r_.CheckKeys(root, "", {"koppel", "name", "title", "description", "parameters", "links", "joints", "drive",
                            "outputs", "assembly", "sweep", "catalog", "units", "gravity", "loads"});
    if (const YAML::Node v = root["koppel"]; v.IsDefined()) {
      if (!v.IsScalar() || v.Scalar() != "1") r_.Error(v, "koppel", "unsupported format version (this koppel reads 1)");
    }
    if (const YAML::Node name = r_.Require(root, "name", ""); name.IsDefined() && !name.IsNull()) {
      if (auto id = r_.Text(name, "name")) {
        if (!ValidId(*id)) r_.Error(name, "name", "the id '" + *id + "' may use only letters, digits, '-' and '_'");
        out_.id = *id;
        m_.name = *id;
      }
    }
    if (const YAML::Node t = root["title"]; t.IsDefined()) out_.title = r_.Text(t, "title").value_or("");
    if (const YAML::Node d = root["description"]; d.IsDefined()) out_.description = r_.Text(d, "description").value_or("");
    ReadParameters(root["parameters"], overrides);
    r_.set_parameters(&out_.parameters);
    ReadLinks(r_.Require(root, "links", ""));
    ReadJoints(r_.Require(root, "joints", ""));
    ReadDrive(r_.Require(root, "drive", ""));
    if (const YAML::Node o = root["outputs"]; o.IsDefined() && !o.IsNull()) ReadOutputs(o);
    if (const YAML::Node a = root["assembly"]; a.IsDefined() && !a.IsNull()) ReadAssembly(a);
    if (const YAML::Node s = root["sweep"]; s.IsDefined() && !s.IsNull()) ReadSweep(s);
    if (r_.diagnostics().empty()) ReadLoads(r_, root, out_);  // masses and loads name links, points, outputs
  }

 private:
  void ReadParameters(const YAML::Node& node, const Overrides& overrides) {
    std::vector<bool> used(overrides.size(), false);
    if (node.IsDefined() && node.IsMap() && node.size() > kMaxParameters) {
      r_.Error(node, "parameters", "more than the limit of " + std::to_string(kMaxParameters) + " parameters (kMaxParameters)");
      return;
    }
    if (node.IsDefined() && !node.IsNull()) {
      std::string previous_value;  // the entry before's value, for the decimal-comma hint
      for (const YamlReader::Entry& e : r_.Entries(node, "parameters")) {
        const std::string path = Child("parameters", e.key);
        const std::string before = std::exchange(previous_value, e.value.IsScalar() ? e.value.Scalar() : "");
        if (!r_.CheckName(e.key_node, path, "parameter", e.key)) continue;
        if (!ParameterSet::ValidName(e.key)) {
          // {l2: 130,5, e: 15}: the flow map reads "5" as a key of its own after l2: 130
          const bool digits = !e.key.empty() && e.key.find_first_not_of("0123456789") == std::string::npos;
          const bool decimal_comma = digits && e.value.IsNull() && !before.empty() && before.find_first_not_of("0123456789+-") == std::string::npos;
          r_.Error(e.key_node, path, "'" + e.key + "' cannot be a parameter name (a letter then letters, digits, '_'; not pi or deg)" +
                                         (decimal_comma ? " (a decimal comma? write " + before + "." + e.key + ")" : std::string()));
          continue;
        }
        std::optional<std::string> formula = e.value.IsScalar() ? std::optional<std::string>(e.value.Scalar()) : std::nullopt;
        if (!formula) {
          r_.Error(e.value, path, "expected a number or formula");
          continue;
        }
        bool overridden = false;
        for (size_t i = 0; i < overrides.size(); ++i) {
          if (overrides[i].first == e.key) {
            formula = overrides[i].second;
            used[i] = overridden = true;
          }
        }
        out_.formulas.emplace_back(path, *formula);
        if (const Expected<double> v = out_.parameters.Define(e.key, *formula); !v) {
          // an override's error belongs to the command line, the file's to its line; a formula
          // that fails because it names a failed parameter is that one's error, not a second one
          if (overridden) {
            r_.diagnostics().push_back({r_.file(), 0, 0, "--set " + e.key, v.error()});
          } else if (!r_.NamesFailedParameter(*formula)) {
            r_.Error(e.value, path, v.error());
          }
          r_.MarkFailedParameter(e.key);
        }
      }
    }
    for (size_t i = 0; i < overrides.size(); ++i) {
      if (!used[i]) {
        r_.diagnostics().push_back({r_.file(), 0, 0, "--set " + overrides[i].first,
                                    "'" + overrides[i].first + "' is not a parameter of this file"});
      }
    }
  }

  void ReadLinks(const YAML::Node& node) {
    if (!node.IsDefined() || node.IsNull()) return;
    for (const YamlReader::Entry& e : r_.Entries(node, "links")) {
      const std::string path = Child("links", e.key);
      Link link;
      link.name = e.key;
      r_.CheckName(e.key_node, path, "link", e.key);
      if (!r_.ExpectMap(e.value, path)) continue;
      r_.CheckKeys(e.value, path, {"frame", "points", "mass", "cg", "inertia"});
      if (const YAML::Node f = e.value["frame"]; f.IsDefined()) link.is_frame = r_.Flag(f, Child(path, "frame")).value_or(false);
      const YAML::Node points = r_.Require(e.value, "points", path);
      if (points.IsDefined() && !points.IsNull()) {
        for (const YamlReader::Entry& p : r_.Entries(points, Child(path, "points"))) {
          r_.CheckName(p.key_node, Child(Child(path, "points"), p.key), "point", p.key);
          if (auto v = r_.Position(p.value, Child(Child(path, "points"), p.key))) {
            link.points.push_back({p.key, *v});
          } else if (p.value.IsSequence() && p.value.size() == 2) {
            // its number is reported; the point still exists, so joints naming it report nothing more
            link.points.push_back({p.key, Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN())});
          }
        }
      }
      if (link.is_frame && m_.FrameLink() >= 0) {
        r_.Error(e.key_node, path, "a second frame link ('" + m_.links[m_.FrameLink()].name + "' is the frame already)");
        link.is_frame = false;
      }
      m_.links.push_back(std::move(link));
    }
    if (m_.FrameLink() < 0 && !m_.links.empty()) r_.Error(node, "links", "no link has 'frame: true': a mechanism needs a frame");
  }

  int LinkIndex(const YAML::Node& node, const std::string& path, const std::string& owner) {
    const std::optional<std::string> name = r_.Text(node, path);
    if (!name) return -1;
    const int index = m_.FindLink(*name);
    if (index < 0) r_.Error(node, path, owner + " names unknown link '" + *name + "'");
    return index;
  }

  int PointIndex(int link, const std::string& point, const YAML::Node& node, const std::string& path, const std::string& owner) {
    if (link < 0) return -1;
    const int index = m_.links[link].FindPoint(point);
    if (index < 0) r_.Error(node, path, owner + ": link '" + m_.links[link].name + "' has no point '" + point + "'");
    return index;
  }

  // "link.point" -> PointRef
  std::optional<PointRef> PointReference(const YAML::Node& node, const std::string& path, const std::string& owner) {
    const std::optional<std::string> text = r_.Text(node, path);
    if (!text) return std::nullopt;
    const auto dot = text->find('.');
    if (dot == std::string::npos) {
      r_.Error(node, path, owner + ": expected 'link.point', found '" + *text + "'");
      return std::nullopt;
    }
    const int link = m_.FindLink(text->substr(0, dot));
    if (link < 0) {
      r_.Error(node, path, owner + " names unknown link '" + text->substr(0, dot) + "'");
      return std::nullopt;
    }
    const int point = PointIndex(link, text->substr(dot + 1), node, path, owner);
    if (point < 0) return std::nullopt;
    return PointRef{link, point};
  }

  void ReadJoints(const YAML::Node& node) {
    if (!node.IsDefined() || node.IsNull()) return;
    for (const YamlReader::Entry& e : r_.Entries(node, "joints")) {
      const std::string path = Child("joints", e.key);
      const std::string owner = "joint '" + e.key + "'";
      r_.CheckName(e.key_node, path, "joint", e.key);
      if (!r_.ExpectMap(e.value, path)) continue;
      r_.CheckKeys(e.value, path, {"type", "links", "points", "axis", "angle"});
      Joint j;
      j.name = e.key;
      const YAML::Node type = r_.Require(e.value, "type", path);
      if (type.IsDefined() && !type.IsNull()) {
        const std::string t = r_.Text(type, Child(path, "type")).value_or("");
        if (t == "R" || t == "D" || t == "revolute") {
          j.type = JointType::kRevolute;
        } else if (t == "P" || t == "S" || t == "prismatic") {
          j.type = JointType::kPrismatic;
        } else {
          r_.Error(type, Child(path, "type"), owner + " has unknown type '" + t + "' (expected R or P; also D, S, revolute, prismatic)");
        }
      }
      const YAML::Node links = r_.Require(e.value, "links", path);
      if (links.IsDefined() && !links.IsNull()) {
        if (!links.IsSequence() || links.size() != 2) {
          r_.Error(links, Child(path, "links"), owner + ": expected two links [a, b]");
        } else {
          j.link_a = LinkIndex(links[0], Index(Child(path, "links"), 0), owner);
          j.link_b = LinkIndex(links[1], Index(Child(path, "links"), 1), owner);
          if (j.link_a >= 0 && j.link_a == j.link_b) r_.Error(links, Child(path, "links"), owner + " joins a link to itself");
        }
      }
      ReadJointPoints(e, path, owner, &j);
      ReadSlideAxisAndAngle(e.value, path, owner, &j);
      m_.joints.push_back(std::move(j));
    }
  }

  // The joint's point on each link: `points: [on a, on b]`, or the point named as the joint.
  void ReadJointPoints(const YamlReader::Entry& e, const std::string& path, const std::string& owner, Joint* j) {
    std::string point_a = e.key, point_b = e.key;
    YAML::Node point_node_a = e.key_node, point_node_b = e.key_node;
    std::string path_a = path, path_b = path;
    if (const YAML::Node points = e.value["points"]; points.IsDefined()) {
      if (!points.IsSequence() || points.size() != 2) {
        r_.Error(points, Child(path, "points"), owner + ": expected two point names [on a, on b]");
      } else {
        point_a = r_.Text(points[0], Index(Child(path, "points"), 0)).value_or("");
        point_b = r_.Text(points[1], Index(Child(path, "points"), 1)).value_or("");
        point_node_a = points[0];
        point_node_b = points[1];
        path_a = Index(Child(path, "points"), 0);
        path_b = Index(Child(path, "points"), 1);
      }
    }
    j->point_a = PointIndex(j->link_a, point_a, point_node_a, path_a, owner);
    j->point_b = PointIndex(j->link_b, point_b, point_node_b, path_b, owner);
  }

  // A P joint's slide axis (required, not zero) and angle [deg]; neither belongs to an R joint.
  void ReadSlideAxisAndAngle(const YAML::Node& node, const std::string& path, const std::string& owner, Joint* j) {
    if (const YAML::Node axis = node["axis"]; axis.IsDefined()) {
      if (j->type != JointType::kPrismatic) r_.Error(axis, Child(path, "axis"), owner + ": only a P joint has an axis");
      if (auto v = r_.Vector(axis, Child(path, "axis"))) {
        if (v->norm() < 1e-12) {
          r_.Error(axis, Child(path, "axis"), owner + ": the slide axis must not be zero");
        } else {
          j->axis = v->normalized();
        }
      }
    }
    // A slide has no natural direction to fall back on: a missing axis was read as [1, 0]
    // without a word (issue 22, item 14); the file must say it.
    if (j->type == JointType::kPrismatic && !node["axis"].IsDefined())
      r_.Error(node, Child(path, "axis"),
               owner + ": a P joint needs its slide axis: the guide's direction in the guide's (first link's) coordinates, e.g. axis: [1, 0]");
    if (const YAML::Node angle = node["angle"]; angle.IsDefined()) {
      if (j->type != JointType::kPrismatic) r_.Error(angle, Child(path, "angle"), owner + ": only a P joint has an angle");
      if (auto v = r_.Number(angle, Child(path, "angle"))) j->angle = DegToRad(*v);
    }
  }

  void ReadDrive(const YAML::Node& node) {
    if (!node.IsDefined() || node.IsNull() || !r_.ExpectMap(node, "drive")) return;
    r_.CheckKeys(node, "drive", {"joint", "zero", "name"});
    const YAML::Node joint = r_.Require(node, "joint", "drive");
    if (joint.IsDefined() && !joint.IsNull()) {
      if (auto name = r_.Text(joint, "drive.joint")) {
        m_.drive.joint = m_.FindJoint(*name);
        if (m_.drive.joint < 0) r_.Error(joint, "drive.joint", "the drive names unknown joint '" + *name + "'");
      }
    }
    const bool angle = m_.drive.joint >= 0 && m_.joints[m_.drive.joint].type == JointType::kRevolute;
    m_.drive.input_name = angle ? "phi" : "s_in";
    if (const YAML::Node z = node["zero"]; z.IsDefined()) {
      if (auto v = r_.Number(z, "drive.zero")) m_.drive.zero = angle ? DegToRad(*v) : *v;
    }
    if (const YAML::Node n = node["name"]; n.IsDefined()) {
      if (auto v = r_.Text(n, "drive.name"); v && r_.CheckName(n, "drive.name", "drive's input", *v)) m_.drive.input_name = *v;
    }
  }

  void ReadOutputs(const YAML::Node& node) {
    for (const YamlReader::Entry& e : r_.Entries(node, "outputs")) {
      const std::string path = Child("outputs", e.key);
      const std::string owner = "output '" + e.key + "'";
      r_.CheckName(e.key_node, path, "output", e.key);
      if (!r_.ExpectMap(e.value, path)) continue;
      r_.CheckKeys(e.value, path, {"joint", "link", "point", "distance", "direction", "transmission", "zero"});
      Output o;
      o.name = e.key;
      int kinds = 0;
      const bool ok = ReadOutputKind(e.value, path, owner, &o, &kinds);
      if (kinds != 1) {
        r_.Error(e.value, path, owner + ": give exactly one of joint, link, point, distance, direction, transmission");
        continue;
      }
      if (const YAML::Node z = e.value["zero"]; z.IsDefined()) {
        const bool angle = IsAngleOutput(m_, o);
        if (!angle || o.kind == OutputKind::kTransmissionAngle) {
          r_.Error(z, Child(path, "zero"), owner + ": only a joint angle, link angle or direction has a zero");
        } else if (auto v = r_.Number(z, Child(path, "zero"))) {
          o.offset = DegToRad(*v);
        }
      }
      if (m_.FindOutput(o.name) >= 0) continue;
      if (ok) m_.outputs.push_back(std::move(o));
    }
  }

  // What an output measures: each of its keys joint, link, point, distance, direction and
  // transmission read into *o and counted in *kinds (exactly one is right). False when a name in
  // it is unknown or malformed.
  bool ReadOutputKind(const YAML::Node& node, const std::string& path, const std::string& owner, Output* o, int* kinds) {
    bool ok = true;
    if (const YAML::Node v = node["joint"]; v.IsDefined()) {
      ++*kinds;
      o->kind = OutputKind::kJoint;
      const std::string name = r_.Text(v, Child(path, "joint")).value_or("");
      o->joint = m_.FindJoint(name);
      if (o->joint < 0) {
        r_.Error(v, Child(path, "joint"), owner + " names unknown joint '" + name + "'");
        ok = false;
      }
    }
    if (const YAML::Node v = node["link"]; v.IsDefined()) {
      ++*kinds;
      o->kind = OutputKind::kLinkAngle;
      o->link = LinkIndex(v, Child(path, "link"), owner);
      ok &= o->link >= 0;
    }
    if (const YAML::Node v = node["point"]; v.IsDefined()) {
      ++*kinds;
      o->kind = OutputKind::kPoint;
      const auto p = PointReference(v, Child(path, "point"), owner);
      ok &= p.has_value();
      if (p) o->p = *p;
    }
    for (const char* key : {"distance", "direction"}) {
      const YAML::Node v = node[key];
      if (!v.IsDefined()) continue;
      ++*kinds;
      o->kind = std::string(key) == "distance" ? OutputKind::kDistance : OutputKind::kDirection;
      if (!v.IsSequence() || v.size() != 2) {
        r_.Error(v, Child(path, key), owner + ": expected two points [link.point, link.point]");
        ok = false;
        continue;
      }
      const auto p = PointReference(v[0], Index(Child(path, key), 0), owner);
      const auto q = PointReference(v[1], Index(Child(path, key), 1), owner);
      ok &= p.has_value() && q.has_value();
      if (p) o->p = *p;
      if (q) o->q = *q;
    }
    if (const YAML::Node v = node["transmission"]; v.IsDefined()) {
      ++*kinds;
      o->kind = OutputKind::kTransmissionAngle;
      ok = ReadTransmission(v, Child(path, "transmission"), owner, ok, o);
    }
    return ok;
  }

  // A transmission angle's coupler and output joint; `ok` says whether the output's other keys
  // were sound. Returns it, false when the transmission is not.
  bool ReadTransmission(const YAML::Node& v, const std::string& tpath, const std::string& owner, bool ok, Output* o) {
    if (!r_.ExpectMap(v, tpath)) return false;
    r_.CheckKeys(v, tpath, {"coupler", "joint"});
    const YAML::Node c = r_.Require(v, "coupler", tpath), j = r_.Require(v, "joint", tpath);
    if (c.IsDefined() && !c.IsNull()) o->link = LinkIndex(c, Child(tpath, "coupler"), owner);
    if (j.IsDefined() && !j.IsNull()) {
      const std::string name = r_.Text(j, Child(tpath, "joint")).value_or("");
      o->joint = m_.FindJoint(name);
      if (o->joint < 0) r_.Error(j, Child(tpath, "joint"), owner + " names unknown joint '" + name + "'");
    }
    ok &= o->link >= 0 && o->joint >= 0;
    // the coupler's joints are only meaningful once the rest of the file is sound
    if (ok && r_.diagnostics().empty() && CheckConsistency(m_).empty()) {
      if (const Expected<TransmissionGeometry> geometry = ResolveTransmission(m_, *o); !geometry) {
        r_.Error(v, tpath, owner + ": " + geometry.error());
        ok = false;
      }
    }
    return ok;
  }

  void ReadAssembly(const YAML::Node& node) {
    if (!r_.ExpectMap(node, "assembly")) return;
    r_.CheckKeys(node, "assembly", {"input", "points"});
    const bool angle = m_.InputIsAngle();
    if (const YAML::Node in = node["input"]; in.IsDefined()) {
      if (auto v = r_.Number(in, "assembly.input")) m_.hint.input = angle ? DegToRad(*v) : *v;
    }
    const YAML::Node points = node["points"];
    if (!points.IsDefined() || points.IsNull()) return;
    for (const YamlReader::Entry& e : r_.Entries(points, "assembly.points")) {
      const std::string path = Child("assembly.points", e.key);
      const std::optional<Eigen::Vector2d> where = r_.Position(e.value, path);
      if (!where) continue;
      const auto dot = e.key.find('.');
      if (dot != std::string::npos) {
        const int link = m_.FindLink(e.key.substr(0, dot));
        if (link < 0) {
          r_.Error(e.key_node, path, "assembly hint names unknown link '" + e.key.substr(0, dot) + "'");
          continue;
        }
        const int point = PointIndex(link, e.key.substr(dot + 1), e.key_node, path, "assembly hint");
        if (point >= 0) m_.hint.points.push_back({{link, point}, *where});
        continue;
      }
      // a bare point name: that point on every link that has it
      bool found = false;
      for (int l = 0; l < static_cast<int>(m_.links.size()); ++l) {
        const int point = m_.links[l].FindPoint(e.key);
        if (point < 0) continue;
        found = true;
        m_.hint.points.push_back({{l, point}, *where});
      }
      if (!found) r_.Error(e.key_node, path, "assembly hint: no link has a point '" + e.key + "'");
    }
  }

  void ReadSweep(const YAML::Node& node) {
    if (!r_.ExpectMap(node, "sweep")) return;
    r_.CheckKeys(node, "sweep", {"from", "to", "step"});
    if (const YAML::Node v = node["from"]; v.IsDefined()) out_.sweep.from = r_.Number(v, "sweep.from").value_or(out_.sweep.from);
    if (const YAML::Node v = node["to"]; v.IsDefined()) out_.sweep.to = r_.Number(v, "sweep.to").value_or(out_.sweep.to);
    if (const YAML::Node v = node["step"]; v.IsDefined()) {
      out_.sweep.step = r_.Number(v, "sweep.step").value_or(out_.sweep.step);
      if (out_.sweep.step == 0.0) r_.Error(v, "sweep.step", "the step must not be 0");
    }
  }

  YamlReader& r_;
  MechanismFile& out_;
  Mechanism& m_;
};

// An override of a parameter that no formula reads would change nothing: the user believes a
// change was made when it was not. Unknown names are reported by ReadParameters.
void RefuseUnreadOverrides(const MechanismFile& file, const Overrides& overrides, std::vector<Diagnostic>& diagnostics) {
  const std::vector<std::string> read = ParametersRead(file);
  for (const auto& [name, formula] : overrides) {
    if (!file.parameters.Has(name) || std::find(read.begin(), read.end(), name) != read.end()) continue;
    diagnostics.push_back({file.path, 0, 0, "--set " + name, UnreadParameterMessage(name, read)});
  }
}

}  // namespace

MechanismFile ParseMechanismText(const std::string& text, const std::string& file_name, const Overrides& overrides,
                                 CardReading card) {
  return ParseMechanismNode(ParseYamlText(text, file_name), file_name, overrides, card);
}

MechanismFile ParseMechanismNode(const YAML::Node& root, const std::string& file_name, const Overrides& overrides,
                                 CardReading card) {
  MechanismFile out;
  out.path = file_name;
  YamlReader reader(file_name, &out.parameters);
  reader.set_fallback(YAML::Mark());  // line 1, column 1 for problems without a place
  reader.set_formula_log(&out.formulas);
  try {
    MechanismReader(reader, out).Read(root, overrides);
    reader.set_formula_log(nullptr);  // the card's formulas do not make the model
    if (reader.diagnostics().empty()) {
      for (const std::string& problem : CheckConsistency(out.mechanism)) reader.diagnostics().push_back({file_name, 1, 1, "", problem});
    }
    // only a file read in full knows every formula (a problem above may have stopped the reading)
    if (reader.diagnostics().empty() && !overrides.empty()) RefuseUnreadOverrides(out, overrides, reader.diagnostics());
    if (card == CardReading::kRead && reader.diagnostics().empty() && root.IsMap() && root["catalog"].IsDefined()) {
      out.card = ReadCard(reader, root["catalog"], out);
    }
  } catch (const YAML::Exception& e) {
    // yaml-cpp throws on conversions we did not guard; report it at its place, never crash
    reader.Error(e.mark, "", "unreadable value: " + e.msg);
  }
  if (!reader.diagnostics().empty()) throw InputError(reader.diagnostics());
  return out;
}

MechanismFile ReadMechanismFile(const std::string& name, const Overrides& overrides) {
  std::string path;
  const std::string text = ReadMechanismFileText(name, &path);
  return ParseMechanismText(text, path, overrides);
}

std::string ReadMechanismFileText(const std::string& name, std::string* resolved) {
  const std::string path = ResolveMechanismName(name);
  std::string text;
  try {
    text = ReadInputText(path);
  } catch (const InputError& e) {
    // a name that is neither a file nor a catalog id: say both, with the id it may have meant
    std::error_code ec;
    if (path != name || !ValidId(name) || std::filesystem::exists(name, ec)) throw;
    const std::string directory = DefaultCatalogDirectory();
    Diagnostic d = e.diagnostics().at(0);
    d.message += "; nor is it a catalog id: " + UnknownCatalogId(name, CatalogIds(directory), directory);
    throw InputError({d});
  }
  *resolved = path;
  return text;
}

std::pair<std::string, std::string> ParseAssignment(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw InputError({Diagnostic{"--set", 0, 0, "", "expected NAME=VALUE, found '" + text + "'"}});
  return {text.substr(0, eq), text.substr(eq + 1)};
}

}  // namespace koppel

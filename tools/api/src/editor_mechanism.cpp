// The editor page's mechanism as JSON, both ways, and the points it draws (koppel/api/editor.hpp).
// Compiled into the API and into the page's WebAssembly module: nothing here reads YAML or
// evaluates a formula.
#include "koppel/api/editor.hpp"

#include "display.hpp"
#include "model_impl.hpp"

#include "admission.hpp"
#include "koppel/solver/sweep.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>

namespace koppel {

using namespace api_detail;
using nlohmann::json;

namespace {

constexpr const char* kEditorJson = "editor JSON";

// Output kinds by their words in the JSON (the order of OutputKind).
constexpr std::array<std::pair<OutputKind, const char*>, 6> kOutputKinds = {{
    {OutputKind::kJoint, "joint"},
    {OutputKind::kLinkAngle, "link"},
    {OutputKind::kPoint, "point"},
    {OutputKind::kDistance, "distance"},
    {OutputKind::kDirection, "direction"},
    {OutputKind::kTransmissionAngle, "transmission"},
}};

const char* KindWord(OutputKind kind) {
  for (const auto& [k, word] : kOutputKinds)
    if (k == kind) return word;
  return "joint";
}

json PointRefJson(const PointRef& p) { return json::array({p.link, p.point}); }

// A field of the page's JSON, or InputError naming it.
template <class T>
T Field(const json& object, const char* key, const std::string& where) {
  try {
    return object.at(key).get<T>();
  } catch (const json::exception&) {
    BadInput(kEditorJson, where + "." + key, "missing or of the wrong type");
  }
}

// A whole number (an index into the links, points or joints): 1.7 is refused, not cut to 1.
int IndexField(const json& object, const char* key, const std::string& where) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number_integer()) BadInput(kEditorJson, where + "." + key, "missing or not a whole number");
  return it->get<int>();
}

PointRef PointRefOf(const json& object, const char* key, const std::string& where) {
  const auto pair = Field<std::vector<int>>(object, key, where);
  if (pair.size() != 2) BadInput(kEditorJson, where + "." + key, "expected [link, point]");
  return {pair[0], pair[1]};
}

Link LinkOf(const json& j, const std::string& where) {
  Link link;
  link.name = Field<std::string>(j, "name", where);
  link.is_frame = Field<bool>(j, "frame", where);
  const json& points = j.at("points");
  for (size_t k = 0; k < points.size(); ++k) {
    const json& p = points[k];
    const std::string at = where + ".points[" + std::to_string(k) + "]";
    link.points.push_back({Field<std::string>(p, "name", at), {Field<double>(p, "x", at), Field<double>(p, "y", at)}});
  }
  return link;
}

Joint JointOf(const json& j, const std::string& where) {
  Joint joint;
  joint.name = Field<std::string>(j, "name", where);
  const std::string type = Field<std::string>(j, "type", where);
  if (type != "R" && type != "P") BadInput(kEditorJson, where + ".type", "expected R or P, found '" + type + "'");
  joint.type = type == "P" ? JointType::kPrismatic : JointType::kRevolute;
  joint.link_a = IndexField(j, "link_a", where);
  joint.link_b = IndexField(j, "link_b", where);
  joint.point_a = IndexField(j, "point_a", where);
  joint.point_b = IndexField(j, "point_b", where);
  const auto axis = Field<std::vector<double>>(j, "axis", where);
  if (axis.size() != 2) BadInput(kEditorJson, where + ".axis", "expected [x, y]");
  const Eigen::Vector2d a(axis[0], axis[1]);
  // the reader's rule: a slide axis is a direction, not zero, normalised
  if (joint.type == JointType::kPrismatic && !(a.norm() >= 1e-12)) BadInput(kEditorJson, where + ".axis", "the slide axis must not be zero");
  joint.axis = joint.type == JointType::kPrismatic ? a.normalized() : a;
  joint.angle = Field<double>(j, "angle", where);
  return joint;
}

Output OutputOf(const json& j, const std::string& where) {
  Output o;
  o.name = Field<std::string>(j, "name", where);
  const std::string kind = Field<std::string>(j, "kind", where);
  bool known = false;
  for (const auto& [k, word] : kOutputKinds)
    if (kind == word) o.kind = k, known = true;
  if (!known) BadInput(kEditorJson, where + ".kind", "unknown output kind '" + kind + "'");
  o.joint = IndexField(j, "joint", where);
  o.link = IndexField(j, "link", where);
  o.p = PointRefOf(j, "p", where);
  o.q = PointRefOf(j, "q", where);
  o.offset = Field<double>(j, "offset", where);
  return o;
}

// Every number must be finite: a formula the page evaluated to NaN is refused here, never solved.
void CheckFinite(const json& j, const std::string& where) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) BadInput(kEditorJson, where, "not a finite number");
  if (j.is_null()) BadInput(kEditorJson, where, "not a number (null)");
  if (j.is_object())
    for (const auto& [key, value] : j.items()) CheckFinite(value, where + "." + key);
  if (j.is_array())
    for (size_t i = 0; i < j.size(); ++i) CheckFinite(j[i], where + "[" + std::to_string(i) + "]");
}

}  // namespace

std::string EditorMechanismJson(const Model& model) {
  const MechanismFile& f = ModelAccess::File(model);
  const Mechanism& m = f.mechanism;
  json j;
  j["name"] = m.name;
  j["title"] = f.title.empty() ? f.id : f.title;
  j["units"] = {{"given", f.loads.length_unit_given}, {"name", f.loads.length_unit_name}, {"metres", f.loads.metres_per_unit}};
  j["sweep"] = {{"from", f.sweep.from}, {"to", f.sweep.to}, {"step", f.sweep.step}};
  j["parameters"] = json::array();
  for (const auto& [name, value] : f.parameters.Values()) j["parameters"].push_back({name, value});
  for (const Link& l : m.links) {
    json points = json::array();
    for (const NamedPoint& p : l.points) points.push_back({{"name", p.name}, {"x", p.local.x()}, {"y", p.local.y()}});
    j["links"].push_back({{"name", l.name}, {"frame", l.is_frame}, {"points", points}});
  }
  for (const Joint& jt : m.joints) {
    j["joints"].push_back({{"name", jt.name}, {"type", jt.type == JointType::kPrismatic ? "P" : "R"}, {"link_a", jt.link_a},
                           {"link_b", jt.link_b}, {"point_a", jt.point_a}, {"point_b", jt.point_b},
                           {"axis", {jt.axis.x(), jt.axis.y()}}, {"angle", jt.angle}});
  }
  j["drive"] = {{"joint", m.drive.joint}, {"zero", m.drive.zero}, {"input_name", m.drive.input_name}};
  j["outputs"] = json::array();
  for (const Output& o : m.outputs) {
    j["outputs"].push_back({{"name", o.name}, {"kind", KindWord(o.kind)}, {"joint", o.joint}, {"link", o.link},
                            {"p", PointRefJson(o.p)}, {"q", PointRefJson(o.q)}, {"offset", o.offset}});
  }
  json hint = json::array();
  for (const AssemblyHint::Entry& e : m.hint.points)
    hint.push_back({{"link", e.point.link}, {"point", e.point.point}, {"x", e.global.x()}, {"y", e.global.y()}});
  j["hint"] = {{"input", m.hint.input}, {"points", hint}};
  return j.dump();
}

Model ModelFromEditorJson(const std::string& text) {
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) BadInput(kEditorJson, "", "not a JSON object");
  CheckFinite(j, "mechanism");
  MechanismFile f;
  f.path = kEditorJson;
  Mechanism& m = f.mechanism;
  try {
    m.name = f.id = Field<std::string>(j, "name", "mechanism");
    f.title = Field<std::string>(j, "title", "mechanism");
    const json& units = j.at("units");
    f.loads.length_unit_given = Field<bool>(units, "given", "units");
    f.loads.length_unit_name = Field<std::string>(units, "name", "units");
    f.loads.metres_per_unit = Field<double>(units, "metres", "units");
    const json& sweep = j.at("sweep");
    f.sweep = {Field<double>(sweep, "from", "sweep"), Field<double>(sweep, "to", "sweep"), Field<double>(sweep, "step", "sweep")};
    for (const json& p : j.at("parameters")) f.parameters.DefineValue(p.at(0).get<std::string>(), p.at(1).get<double>());
    for (size_t i = 0; i < j.at("links").size(); ++i) m.links.push_back(LinkOf(j["links"][i], "links[" + std::to_string(i) + "]"));
    for (size_t i = 0; i < j.at("joints").size(); ++i) m.joints.push_back(JointOf(j["joints"][i], "joints[" + std::to_string(i) + "]"));
    const json& drive = j.at("drive");
    m.drive = {Field<int>(drive, "joint", "drive"), Field<double>(drive, "zero", "drive"), Field<std::string>(drive, "input_name", "drive")};
    for (size_t i = 0; i < j.at("outputs").size(); ++i) m.outputs.push_back(OutputOf(j["outputs"][i], "outputs[" + std::to_string(i) + "]"));
    const json& hint = j.at("hint");
    m.hint.input = Field<double>(hint, "input", "hint");
    for (const json& e : hint.at("points"))
      m.hint.points.push_back({{Field<int>(e, "link", "hint"), Field<int>(e, "point", "hint")}, {Field<double>(e, "x", "hint"), Field<double>(e, "y", "hint")}});
  } catch (const json::exception& e) {
    BadInput(kEditorJson, "mechanism", e.what());
  }
  std::vector<Diagnostic> problems;
  for (const std::string& problem : CheckConsistency(m)) problems.push_back({kEditorJson, 0, 0, "", problem});
  if (!problems.empty()) throw InputError(problems);
  return ModelAccess::FromFile(std::move(f));
}

EditorFrames EditorPoints(const Model& model, double from, double to, double step, AtBranchPoint at_branch_point) {
  const Mechanism& m = model.mechanism();
  // the sweep Model::Sweep walks (analyses.cpp): the same range in the solver's units
  SweepOptions options;
  options.from = InputInternal(m, from);
  options.to = InputInternal(m, to);
  options.step = InputInternal(m, step);
  options.order = 2;
  options.continuation.at_branch_point = at_branch_point;
  if (std::string why; !options.IsValid(&why)) BadInput(model.path(), "from/to/step", why);
  const SweepResult result = koppel::Sweep(m, options);
  EditorFrames frames;
  frames.status = ToString(result.status);
  frames.message = result.message;
  for (size_t i = 0; i < result.inputs.size(); ++i) {
    frames.inputs.push_back(InputShown(m, result.inputs[i]));
    frames.singular.push_back(result.singular[i] != 0);
    for (int l = 0; l < static_cast<int>(m.links.size()); ++l) {
      // the frame link's body frame is the global frame; a moving link's pose is (x, y, theta)
      double x = 0, y = 0, theta = 0;
      if (!m.links[l].is_frame) {
        const int c = 3 * (l - (m.FrameLink() < l ? 1 : 0));
        x = result.poses(i, c), y = result.poses(i, c + 1), theta = result.poses(i, c + 2);
      }
      const double cs = std::cos(theta), sn = std::sin(theta);
      for (const NamedPoint& p : m.links[l].points) {
        frames.points.push_back(x + cs * p.local.x() - sn * p.local.y());
        frames.points.push_back(y + sn * p.local.x() + cs * p.local.y());
      }
    }
  }
  return frames;
}

}  // namespace koppel

// The document `koppel edit` writes into its page (koppel/api/editor.hpp): the evaluated mechanism
// and, for every formula of the file's model part, where its value goes in the mechanism JSON.
#include "koppel/api/editor.hpp"

#include "model_impl.hpp"

#include "koppel/catalog/document_edit.hpp"
#include "koppel/catalog/parameter_use.hpp"
#include "koppel/core/angles.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <optional>

namespace koppel {

using nlohmann::json;

namespace {

// Where one formula's value goes: a JSON pointer into the mechanism JSON and the factor from the
// file's unit to the model's (pi/180 for degrees, as DegToRad).
struct Target {
  std::string pointer;
  double scale = 1.0;
};

constexpr double kDegree = kPi / 180.0;

bool StartsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

// "NAME[i]" -> NAME and i (0 or 1); nullopt for anything else.
std::optional<std::pair<std::string, int>> Indexed(const std::string& s) {
  if (s.size() < 4 || s.back() != ']' || s[s.size() - 3] != '[') return std::nullopt;
  const char digit = s[s.size() - 2];
  if (digit != '0' && digit != '1') return std::nullopt;
  return std::make_pair(s.substr(0, s.size() - 3), digit - '0');
}

std::string Axis(int i) { return i == 0 ? "x" : "y"; }

// The targets of the reader's key path `path` (mechanism_file.cpp names them); empty for a path
// the page does not follow (masses, loads). `hint_keys` collects assembly.points' keys in order,
// so that a bare point name goes to every hint entry it made (one per link that has the point).
std::vector<Target> TargetsOf(const Mechanism& m, const std::string& path, std::vector<std::string>* hint_keys) {
  const bool angle_input = m.InputIsAngle();
  if (path == "drive.zero") return {{"/drive/zero", angle_input ? kDegree : 1.0}};
  if (path == "assembly.input") return {{"/hint/input", angle_input ? kDegree : 1.0}};
  if (path == "sweep.from" || path == "sweep.to" || path == "sweep.step") return {{"/sweep/" + path.substr(6), 1.0}};
  if (StartsWith(path, "links.")) {
    const size_t at = path.find(".points.", 6);
    const auto point = at == std::string::npos ? std::nullopt : Indexed(path.substr(at + 8));
    const int link = at == std::string::npos ? -1 : m.FindLink(path.substr(6, at - 6));
    if (!point || link < 0) return {};
    const int p = m.links[link].FindPoint(point->first);
    if (p < 0) return {};
    return {{"/links/" + std::to_string(link) + "/points/" + std::to_string(p) + "/" + Axis(point->second), 1.0}};
  }
  if (StartsWith(path, "joints.")) {
    const size_t dot = path.rfind('.');
    const int joint = m.FindJoint(path.substr(7, dot - 7));
    const std::string field = path.substr(dot + 1);
    if (joint < 0) return {};
    if (field == "angle") return {{"/joints/" + std::to_string(joint) + "/angle", kDegree}};
    if (const auto axis = Indexed(field); axis && axis->first == "axis")
      return {{"/joints/" + std::to_string(joint) + "/axis/" + std::to_string(axis->second), 1.0}};
    return {};
  }
  if (StartsWith(path, "outputs.") && path.size() > 13 && path.compare(path.size() - 5, 5, ".zero") == 0) {
    const int output = m.FindOutput(path.substr(8, path.size() - 13));
    return output < 0 ? std::vector<Target>{} : std::vector<Target>{{"/outputs/" + std::to_string(output) + "/offset", kDegree}};
  }
  if (StartsWith(path, "assembly.points.")) {
    const auto key = Indexed(path.substr(16));
    if (!key) return {};
    if (key->second == 0) hint_keys->push_back(key->first);
    // the hint entries before this key's: one per earlier key (link.point) or per link with the point
    size_t first = 0;
    const auto entries = [&](const std::string& k) {
      if (k.find('.') != std::string::npos) return size_t{1};
      size_t n = 0;
      for (const Link& l : m.links) n += l.FindPoint(k) >= 0;
      return n;
    };
    for (size_t i = 0; i + 1 < hint_keys->size(); ++i) first += entries((*hint_keys)[i]);
    std::vector<Target> targets;
    for (size_t e = first; e < first + entries(key->first) && e < m.hint.points.size(); ++e)
      targets.push_back({"/hint/points/" + std::to_string(e) + "/" + Axis(key->second), 1.0});
    return targets;
  }
  return {};
}

// The user's own text (with the parameters set so far written in, Model::ToYaml) and the place in
// it of every value the page may change (its parameters and the formulas it follows): the page's
// export writes its changes there (SpliceScalars) and keeps every other byte. A value written over
// several lines has no place; the page says so when a change needs one. Null for a model of no file.
json SourceOf(const Model& model, const json& doc) {
  if (!ModelAccess::HasSource(model)) return nullptr;
  const std::string text = model.ToYaml();
  const std::string& file = ModelAccess::File(model).path;
  json places = json::object();
  const std::unordered_map<std::string, ScalarPlace> all = ScalarPlaces(text, file);
  const auto place = [&](const std::string& path) {
    const auto p = all.find(path);
    if (p != all.end()) places[path] = {p->second.span.begin, p->second.span.end, p->second.quote == '\0' ? "" : std::string(1, p->second.quote)};
  };
  for (const json& p : doc["parameters"]) place("parameters." + p["name"].get<std::string>());
  for (const json& f : doc["formulas"])
    if (!places.contains(f["path"].get<std::string>())) place(f["path"].get<std::string>());
  return {{"text", text}, {"file", file}, {"places", places}};
}

}  // namespace

std::string EditorDocumentJson(const Model& model) {
  const MechanismFile& f = ModelAccess::File(model);
  const Mechanism& m = f.mechanism;
  json doc;
  doc["title"] = f.title.empty() ? f.id : f.title;
  doc["file"] = f.path;
  doc["input"] = {{"name", model.input_name()}, {"angle", model.input_is_angle()}, {"unit", model.input_is_angle() ? "deg" : model.length_unit()}};
  doc["parameters"] = json::array();
  doc["formulas"] = json::array();
  doc["unfollowed"] = json::array();
  std::vector<std::string> hint_keys;
  const std::vector<std::string> read = ParametersRead(f);
  for (const auto& [path, formula] : f.formulas) {
    if (StartsWith(path, "parameters.")) {
      const std::string name = path.substr(11);
      json p = {{"name", name}, {"formula", formula}, {"value", f.parameters.Value(name)}};
      // setting a parameter no formula reads changes nothing: the page refuses it in the library's words
      if (std::find(read.begin(), read.end(), name) == read.end()) p["unread"] = UnreadParameterMessage(name, read);
      doc["parameters"].push_back(std::move(p));
      continue;
    }
    const std::vector<Target> targets = TargetsOf(m, path, &hint_keys);
    if (targets.empty()) {
      doc["unfollowed"].push_back(path);
      continue;
    }
    // the value muparser gives, in the file's units: the page checks its own evaluation against it
    const Expected<double> value = f.parameters.Evaluate(formula);
    for (const Target& t : targets)
      doc["formulas"].push_back({{"path", path}, {"formula", formula}, {"value", value ? json(*value) : json(nullptr)},
                                 {"target", t.pointer}, {"scale", t.scale}});
  }
  doc["has_loads"] = f.loads.HasMass() || !f.loads.forces.empty() || !f.loads.torques.empty() || !f.loads.springs.empty();
  doc["mechanism"] = json::parse(EditorMechanismJson(model));
  doc["source"] = SourceOf(model, doc);
  return doc.dump();
}

}  // namespace koppel

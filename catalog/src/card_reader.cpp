// The `catalog` section of a mechanism file -> CatalogCard (format: the three seed entries in
// catalog/entries/ and README.md "Catalog cards").
#include "koppel/core/structure.hpp"
#include "yaml_reader.hpp"

#include <cmath>

namespace koppel {
namespace {

int DegreeOf(const std::string& word) {
  for (int d = 0; d <= 6; ++d) {
    if (DegreeName(d) == word) return d;
  }
  return -1;
}

// Formulas are checked for parse errors and unknown names when the card is read; their values
// (which may be undefined at some input) only when `check` runs.
void CheckFormula(YamlReader& r, const YAML::Node& node, const std::string& path, const ParameterSet& names) {
  if (!node.IsScalar()) {
    r.Error(node, path, "expected a formula");
    return;
  }
  std::string error;
  if (!names.Evaluate(node.Scalar(), &error) && error.find("does not parse") != std::string::npos) r.Error(node, path, error);
}

void ReadFeatures(YamlReader& r, const YAML::Node& node, AccessFeatures& f) {
  const std::string path = "catalog.features";
  if (!r.ExpectMap(node, path)) return;
  r.CheckKeys(node, path, {"drive_joints", "drive_joints_at_frame", "output_links", "output_links_at_frame", "links",
                           "links_by_degree", "joints", "joints_by_type"});
  auto count = [&](const char* key, int& out) {
    if (const YAML::Node v = node[key]; v.IsDefined()) out = r.Count(v, Child(path, key)).value_or(-1);
  };
  count("drive_joints", f.drive_joints);
  count("drive_joints_at_frame", f.drive_joints_at_frame);
  count("output_links", f.output_links);
  count("output_links_at_frame", f.output_links_at_frame);
  count("links", f.links);
  count("joints", f.joints);
  const std::vector<std::string> required = {"drive_joints", "output_links", "links", "joints"};
  for (const std::string& key : required) {
    if (!node[key].IsDefined()) r.Error(node, Child(path, key), "missing access feature '" + key + "'");
  }
  if (const YAML::Node v = node["links_by_degree"]; v.IsDefined()) {
    for (const YamlReader::Entry& e : r.Entries(v, Child(path, "links_by_degree"))) {
      const int degree = DegreeOf(e.key);
      if (degree < 0) {
        r.Error(e.key_node, Child(Child(path, "links_by_degree"), e.key), "expected binary, ternary, quaternary, ...");
        continue;
      }
      f.links_by_degree[degree] = r.Count(e.value, Child(Child(path, "links_by_degree"), e.key)).value_or(0);
    }
  }
  if (const YAML::Node v = node["joints_by_type"]; v.IsDefined()) {
    for (const YamlReader::Entry& e : r.Entries(v, Child(path, "joints_by_type"))) {
      // D revolute, S prismatic, W helical (Schraubung): the document's letters
      if (e.key != "D" && e.key != "S" && e.key != "W") {
        r.Error(e.key_node, Child(Child(path, "joints_by_type"), e.key), "expected D, S or W");
        continue;
      }
      f.joints_by_type[e.key] = r.Count(e.value, Child(Child(path, "joints_by_type"), e.key)).value_or(0);
    }
  }
}

}  // namespace

std::optional<CatalogCard> ReadCard(YamlReader& r, const YAML::Node& node, const MechanismFile& file) {
  const std::string path = "catalog";
  if (!r.ExpectMap(node, path)) return std::nullopt;
  r.CheckKeys(node, path, {"title", "kind", "motion", "applications", "source", "outputs", "features", "variants",
                           "sweep", "where", "equations", "figures"});
  CatalogCard card;
  const Mechanism& m = file.mechanism;
  if (const YAML::Node t = r.Require(node, "title", path); t.IsDefined() && r.ExpectMap(t, "catalog.title")) {
    r.CheckKeys(t, "catalog.title", {"de", "en"});
    if (t["de"].IsDefined()) card.title_de = r.Text(t["de"], "catalog.title.de").value_or("");
    if (t["en"].IsDefined()) card.title_en = r.Text(t["en"], "catalog.title.en").value_or("");
  }
  if (const YAML::Node k = r.Require(node, "kind", path); k.IsDefined() && !k.IsNull()) {
    card.kind = r.Text(k, "catalog.kind").value_or("");
    if (card.kind != "transfer" && card.kind != "guidance")
      r.Error(k, "catalog.kind", "expected transfer (Übertragungsgetriebe) or guidance (Führungsgetriebe)");
  }
  if (node["motion"].IsDefined()) card.motion = r.Text(node["motion"], "catalog.motion").value_or("");
  if (node["applications"].IsDefined()) card.applications = r.TextList(node["applications"], "catalog.applications");
  if (const YAML::Node s = node["source"]; s.IsDefined() && r.ExpectMap(s, "catalog.source")) {
    r.CheckKeys(s, "catalog.source", {"document", "author", "literature"});
    if (s["document"].IsDefined()) card.document = r.Text(s["document"], "catalog.source.document").value_or("");
    if (s["author"].IsDefined()) card.author = r.Text(s["author"], "catalog.source.author").value_or("");
    if (s["literature"].IsDefined()) card.literature = r.TextList(s["literature"], "catalog.source.literature");
  }
  if (const YAML::Node o = r.Require(node, "outputs", path); o.IsDefined() && !o.IsNull()) {
    card.outputs = r.TextList(o, "catalog.outputs");
    for (size_t i = 0; i < card.outputs.size(); ++i) {
      if (m.FindOutput(card.outputs[i]) < 0)
        r.Error(o[i], Index("catalog.outputs", static_cast<int>(i)), "the card names output '" + card.outputs[i] + "', which the file does not declare");
    }
  }
  if (const YAML::Node f = r.Require(node, "features", path); f.IsDefined() && !f.IsNull()) ReadFeatures(r, f, card.declared);

  if (const YAML::Node v = node["variants"]; v.IsDefined()) {
    for (const YamlReader::Entry& e : r.Entries(v, "catalog.variants")) {
      CheckVariant variant;
      variant.name = e.key;
      for (const YamlReader::Entry& p : r.Entries(e.value, Child("catalog.variants", e.key))) {
        if (!file.parameters.Has(p.key)) {
          r.Error(p.key_node, Child(Child("catalog.variants", e.key), p.key), "'" + p.key + "' is not a parameter of this file");
          continue;
        }
        if (auto text = r.Text(p.value, Child(Child("catalog.variants", e.key), p.key))) variant.overrides.emplace_back(p.key, *text);
      }
      card.variants.push_back(std::move(variant));
    }
  }
  if (const YAML::Node s = node["sweep"]; s.IsDefined() && r.ExpectMap(s, "catalog.sweep")) {
    r.CheckKeys(s, "catalog.sweep", {"from", "to", "step"});
    if (s["from"].IsDefined()) card.from = r.Number(s["from"], "catalog.sweep.from").value_or(card.from);
    if (s["to"].IsDefined()) card.to = r.Number(s["to"], "catalog.sweep.to").value_or(card.to);
    if (s["step"].IsDefined()) card.step = r.Number(s["step"], "catalog.sweep.step").value_or(card.step);
    if (card.step == 0.0) r.Error(s, "catalog.sweep.step", "the step must not be 0");
  }

  // names a formula may use: parameters, phi, then the `where` definitions in order
  ParameterSet names = file.parameters;
  names.DefineValue("phi", 0.5);
  if (const YAML::Node w = node["where"]; w.IsDefined()) {
    for (const YamlReader::Entry& e : r.Entries(w, "catalog.where")) {
      const std::string wpath = Child("catalog.where", e.key);
      if (!ParameterSet::ValidName(e.key)) {
        r.Error(e.key_node, wpath, "'" + e.key + "' cannot be a name");
        continue;
      }
      CheckFormula(r, e.value, wpath, names);
      if (!e.value.IsScalar()) continue;
      card.where.emplace_back(e.key, e.value.Scalar());
      names.DefineValue(e.key, 0.5);
    }
  }
  auto output_of = [&](const YAML::Node& item, const std::string& ipath, std::string& name, int& component) {
    const YAML::Node o = r.Require(item, "output", ipath);
    if (!o.IsDefined() || o.IsNull()) return;
    name = r.Text(o, Child(ipath, "output")).value_or("");
    const int index = m.FindOutput(name);
    if (index < 0) {
      r.Error(o, Child(ipath, "output"), "names output '" + name + "', which the file does not declare");
      return;
    }
    if (const YAML::Node c = item["component"]; c.IsDefined()) {
      const std::string text = r.Text(c, Child(ipath, "component")).value_or("");
      component = (text == "y" || text == "1") ? 1 : 0;
      if (m.outputs[index].Components() == 1 && component == 1) r.Error(c, Child(ipath, "component"), "a scalar output has no y component");
    }
  };

  if (const YAML::Node eqs = node["equations"]; eqs.IsDefined() && r.ExpectSequence(eqs, "catalog.equations")) {
    for (size_t i = 0; i < eqs.size(); ++i) {
      const YAML::Node item = eqs[i];
      const std::string ipath = Index("catalog.equations", static_cast<int>(i));
      if (!r.ExpectMap(item, ipath)) continue;
      r.CheckKeys(item, ipath, {"name", "output", "component", "order", "formula", "tolerance", "printed", "note"});
      EquationCheck e;
      e.line = item.Mark().line + 1;
      if (item["name"].IsDefined()) e.name = r.Text(item["name"], Child(ipath, "name")).value_or("");
      output_of(item, ipath, e.output, e.component);
      if (item["order"].IsDefined()) e.order = r.Count(item["order"], Child(ipath, "order")).value_or(0);
      if (e.order > 8) r.Error(item["order"], Child(ipath, "order"), "orders above 8 are not computed");
      const YAML::Node formula = r.Require(item, "formula", ipath);
      if (formula.IsDefined() && !formula.IsNull()) {
        CheckFormula(r, formula, Child(ipath, "formula"), names);
        e.formula = formula.IsScalar() ? formula.Scalar() : "";
      }
      const YAML::Node tol = r.Require(item, "tolerance", ipath);
      if (tol.IsDefined() && !tol.IsNull()) e.tolerance = r.Number(tol, Child(ipath, "tolerance")).value_or(0);
      if (item["printed"].IsDefined()) e.printed = r.Text(item["printed"], Child(ipath, "printed")).value_or("");
      if (item["note"].IsDefined()) e.note = r.Text(item["note"], Child(ipath, "note")).value_or("");
      if (e.name.empty()) e.name = e.output + (e.order ? "_d" + std::to_string(e.order) : "");
      card.equations.push_back(std::move(e));
    }
  }
  if (const YAML::Node figs = node["figures"]; figs.IsDefined() && r.ExpectSequence(figs, "catalog.figures")) {
    for (size_t i = 0; i < figs.size(); ++i) {
      const YAML::Node item = figs[i];
      const std::string ipath = Index("catalog.figures", static_cast<int>(i));
      if (!r.ExpectMap(item, ipath)) continue;
      FigureCheck f;
      f.line = item.Mark().line + 1;
      for (const YamlReader::Entry& e : r.Entries(item, ipath)) {
        const std::string kpath = Child(ipath, e.key);
        if (e.key == "name") f.name = r.Text(e.value, kpath).value_or("");
        else if (e.key == "quantity") f.quantity = r.Text(e.value, kpath).value_or("");
        else if (e.key == "output" || e.key == "component") continue;  // below
        else if (e.key == "order") f.order = r.Count(e.value, kpath).value_or(0);
        else if (e.key == "expected") { CheckFormula(r, e.value, kpath, file.parameters); f.expected = e.value.IsScalar() ? e.value.Scalar() : "0"; }
        else if (e.key == "unit") f.unit = r.Text(e.value, kpath).value_or("");
        else if (e.key == "tolerance") f.tolerance = r.Number(e.value, kpath).value_or(0);
        else if (e.key == "printed") f.printed = r.Text(e.value, kpath).value_or("");
        else if (e.key == "note") f.note = r.Text(e.value, kpath).value_or("");
        else if (e.key == "variant") f.variant = r.Text(e.value, kpath).value_or("");
        else if (e.key == "pending") f.pending = r.Flag(e.value, kpath).value_or(false);
        else if (e.value.IsScalar()) f.args[e.key] = e.value.Scalar();  // quantity arguments: at, from, to, qg ...
        else r.Error(e.value, kpath, "a figure argument must be a single value");
      }
      if (item["output"].IsDefined()) output_of(item, ipath, f.output, f.component);
      if (f.quantity.empty()) r.Error(item, Child(ipath, "quantity"), "missing required key 'quantity'");
      if (f.expected.empty()) r.Error(item, Child(ipath, "expected"), "missing required key 'expected'");
      if (!item["tolerance"].IsDefined()) r.Error(item, Child(ipath, "tolerance"), "missing required key 'tolerance'");
      if (!f.unit.empty() && f.unit != "deg") r.Error(item["unit"], Child(ipath, "unit"), "the only unit is deg (angles in degrees)");
      if (!f.variant.empty()) {
        bool known = false;
        for (const CheckVariant& v : card.variants) known |= v.name == f.variant;
        if (!known) r.Error(item["variant"], Child(ipath, "variant"), "unknown variant '" + f.variant + "'");
      }
      if (f.name.empty()) f.name = f.quantity + " " + f.output;
      card.figures.push_back(std::move(f));
    }
  }
  return card;
}

}  // namespace koppel

// The `catalog` section of a mechanism file -> CatalogCard (format: README.md "The catalog").
// Every key is checked when the card is read, figures against their quantity's row in the table
// of figure_quantities.hpp, so a misspelled quantity or argument is an error with its line, never
// a figure that silently does not run.
#include "figures.hpp"
#include "koppel/catalog/classes.hpp"
#include "koppel/catalog/figure_quantities.hpp"
#include "koppel/catalog/text_search.hpp"
#include "koppel/core/structure.hpp"
#include "yaml_reader.hpp"

namespace koppel {

const char* ToString(CardKind kind) { return kind == CardKind::kTransfer ? "transfer" : "guidance"; }

namespace {

int DegreeOf(const std::string& word) {
  for (int d = 0; d <= 6; ++d) {
    if (DegreeName(d) == word) return d;
  }
  return -1;
}

const std::vector<std::string> kFigureKeys = {"name", "quantity", "output", "component", "expected", "unit",
                                              "tolerance", "printed", "note", "variant"};

class CardReader {
 public:
  CardReader(YamlReader& reader, const MechanismFile& file, CatalogCard& card)
      : r_(reader), file_(file), m_(file.mechanism), card_(card), names_(file.parameters) {
    names_.DefineValue("phi", 0.5);  // the input, for equations and `where`
  }

  void Read(const YAML::Node& node) {
    r_.CheckKeys(node, "catalog", {"title", "kind", "class", "motion", "applications", "keywords", "source", "outputs", "features",
                                   "variants", "sweep", "where", "equations", "figures"});
    ReadDescription(node);
    if (const YAML::Node o = r_.Require(node, "outputs", "catalog"); o.IsDefined() && !o.IsNull()) ReadAbtrieb(o);
    if (const YAML::Node f = r_.Require(node, "features", "catalog"); f.IsDefined() && !f.IsNull()) ReadFeatures(f);
    if (const YAML::Node v = node["variants"]; v.IsDefined()) ReadVariants(v);
    if (const YAML::Node s = node["sweep"]; s.IsDefined()) ReadSweep(s);
    if (const YAML::Node w = node["where"]; w.IsDefined()) ReadWhere(w);
    if (const YAML::Node e = node["equations"]; e.IsDefined() && r_.ExpectSequence(e, "catalog.equations")) {
      for (size_t i = 0; i < e.size(); ++i) ReadEquation(e[i], Index("catalog.equations", static_cast<int>(i)));
    }
    if (const YAML::Node f = node["figures"]; f.IsDefined() && r_.ExpectSequence(f, "catalog.figures")) {
      for (size_t i = 0; i < f.size(); ++i) ReadFigure(f[i], Index("catalog.figures", static_cast<int>(i)));
    }
  }

 private:
  // Assigns only what was read: a value with a problem leaves the default and a diagnostic.
  void Set(std::string& out, const YAML::Node& node, const std::string& path) {
    if (auto v = r_.Text(node, path)) out = *v;
  }
  void Set(int& out, const YAML::Node& node, const std::string& path) {
    if (auto v = r_.Count(node, path)) out = *v;
  }
  void Set(double& out, const YAML::Node& node, const std::string& path) {
    if (auto v = r_.Number(node, path)) out = *v;
  }

  // titles, kind, classes, motion, applications, source
  void ReadDescription(const YAML::Node& node) {
    if (const YAML::Node t = r_.Require(node, "title", "catalog"); t.IsDefined() && r_.ExpectMap(t, "catalog.title")) {
      r_.CheckKeys(t, "catalog.title", {"de", "en"});
      if (t["de"].IsDefined()) Set(card_.title_de, t["de"], "catalog.title.de");
      if (t["en"].IsDefined()) Set(card_.title_en, t["en"], "catalog.title.en");
    }
    if (const YAML::Node k = r_.Require(node, "kind", "catalog"); k.IsDefined() && !k.IsNull()) {
      if (k.IsScalar() && k.Scalar() == "transfer") card_.kind = CardKind::kTransfer;
      else if (k.IsScalar() && k.Scalar() == "guidance") card_.kind = CardKind::kGuidance;
      else r_.Error(k, "catalog.kind", "expected transfer (Übertragungsgetriebe) or guidance (Führungsgetriebe)");
    }
    if (const YAML::Node c = node["class"]; c.IsDefined()) {
      card_.classes = r_.TextList(c, "catalog.class");
      for (size_t i = 0; i < card_.classes.size(); ++i) {
        if (IsCatalogClass(card_.classes[i])) continue;
        std::vector<std::string> names;
        for (const CatalogClass& k : CatalogClasses()) names.push_back(k.name);
        r_.Error(c[i], Index("catalog.class", static_cast<int>(i)), UnknownName("class", card_.classes[i], names));
      }
    }
    if (const YAML::Node mo = node["motion"]; mo.IsDefined()) {
      Set(card_.motion, mo, "catalog.motion");
      if (const std::string problem = MotionProblem(card_.motion); mo.IsScalar() && !problem.empty()) r_.Error(mo, "catalog.motion", problem);
    }
    if (node["applications"].IsDefined()) card_.applications = r_.TextList(node["applications"], "catalog.applications");
    if (node["keywords"].IsDefined()) card_.keywords = r_.TextList(node["keywords"], "catalog.keywords");
    if (const YAML::Node s = node["source"]; s.IsDefined() && r_.ExpectMap(s, "catalog.source")) {
      r_.CheckKeys(s, "catalog.source", {"document", "author", "literature"});
      if (s["document"].IsDefined()) Set(card_.document, s["document"], "catalog.source.document");
      if (s["author"].IsDefined()) Set(card_.author, s["author"], "catalog.source.author");
      if (s["literature"].IsDefined()) card_.literature = r_.TextList(s["literature"], "catalog.source.literature");
    }
  }

  void ReadAbtrieb(const YAML::Node& o) {
    card_.outputs = r_.TextList(o, "catalog.outputs");
    for (size_t i = 0; i < card_.outputs.size(); ++i) {
      if (m_.FindOutput(card_.outputs[i]) < 0)
        r_.Error(o[i], Index("catalog.outputs", static_cast<int>(i)), "the card names output '" + card_.outputs[i] + "', which the file does not declare");
    }
  }

  void ReadFeatures(const YAML::Node& node) {
    const std::string path = "catalog.features";
    if (!r_.ExpectMap(node, path)) return;
    r_.CheckKeys(node, path, {"drive_joints", "drive_joints_at_frame", "output_links", "output_links_at_frame", "links",
                              "links_by_degree", "joints", "joints_by_type"});
    AccessFeatures& f = card_.declared;
    const std::pair<const char*, int*> counts[] = {{"drive_joints", &f.drive_joints}, {"drive_joints_at_frame", &f.drive_joints_at_frame},
                                                   {"output_links", &f.output_links}, {"output_links_at_frame", &f.output_links_at_frame},
                                                   {"links", &f.links},               {"joints", &f.joints}};
    for (const auto& [key, out] : counts) {
      if (const YAML::Node v = node[key]; v.IsDefined()) Set(*out, v, Child(path, key));
    }
    for (const char* key : {"drive_joints", "output_links", "links", "joints"}) {
      if (!node[key].IsDefined()) r_.Error(node, Child(path, key), std::string("missing access feature '") + key + "'");
    }
    if (const YAML::Node v = node["links_by_degree"]; v.IsDefined()) {
      const std::string lpath = Child(path, "links_by_degree");
      for (const YamlReader::Entry& e : r_.Entries(v, lpath)) {
        const int degree = DegreeOf(e.key);
        if (degree < 0) r_.Error(e.key_node, Child(lpath, e.key), "expected binary, ternary, quaternary, ...");
        else if (auto n = r_.Count(e.value, Child(lpath, e.key))) f.links_by_degree[degree] = *n;
      }
    }
    if (const YAML::Node v = node["joints_by_type"]; v.IsDefined()) {
      const std::string jpath = Child(path, "joints_by_type");
      for (const YamlReader::Entry& e : r_.Entries(v, jpath)) {
        // D revolute, S prismatic, W helical (Schraubung): the document's letters
        if (e.key != "D" && e.key != "S" && e.key != "W") r_.Error(e.key_node, Child(jpath, e.key), "expected D, S or W");
        else if (auto n = r_.Count(e.value, Child(jpath, e.key))) f.joints_by_type[e.key] = *n;
      }
    }
  }

  void ReadVariants(const YAML::Node& node) {
    for (const YamlReader::Entry& e : r_.Entries(node, "catalog.variants")) {
      CheckVariant variant;
      variant.name = e.key;
      const std::string vpath = Child("catalog.variants", e.key);
      for (const YamlReader::Entry& p : r_.Entries(e.value, vpath)) {
        if (!file_.parameters.Has(p.key)) r_.Error(p.key_node, Child(vpath, p.key), "'" + p.key + "' is not a parameter of this file");
        else if (auto text = r_.Text(p.value, Child(vpath, p.key))) variant.overrides.emplace_back(p.key, *text);
      }
      card_.variants.push_back(std::move(variant));
    }
  }

  void ReadSweep(const YAML::Node& s) {
    if (!r_.ExpectMap(s, "catalog.sweep")) return;
    r_.CheckKeys(s, "catalog.sweep", {"from", "to", "step"});
    if (s["from"].IsDefined()) Set(card_.from, s["from"], "catalog.sweep.from");
    if (s["to"].IsDefined()) Set(card_.to, s["to"], "catalog.sweep.to");
    if (s["step"].IsDefined()) Set(card_.step, s["step"], "catalog.sweep.step");
    if (card_.step == 0.0) r_.Error(s, "catalog.sweep.step", "the step must not be 0");
  }

  // names an equation may use: parameters, phi, then the `where` definitions in order
  void ReadWhere(const YAML::Node& node) {
    for (const YamlReader::Entry& e : r_.Entries(node, "catalog.where")) {
      const std::string wpath = Child("catalog.where", e.key);
      if (!ParameterSet::ValidName(e.key)) {
        r_.Error(e.key_node, wpath, "'" + e.key + "' cannot be a name");
        continue;
      }
      if (!CheckFormula(e.value, wpath, names_)) continue;
      card_.where.emplace_back(e.key, e.value.Scalar());
      names_.DefineValue(e.key, 0.5);
    }
  }

  // Formulas are checked for parse errors and unknown names when the card is read; their values
  // (which may be undefined at some input) only when `check` runs.
  bool CheckFormula(const YAML::Node& node, const std::string& path, const ParameterSet& names) {
    if (!node.IsScalar()) {
      r_.Error(node, path, "expected a formula");
      return false;
    }
    // only the syntax is checked here: a value that is not finite yet may be one at check time
    const Expected<double> value = names.Evaluate(node.Scalar());
    if (!value && value.error().find("does not parse") != std::string::npos) {
      r_.Error(node, path, value.error());
      return false;
    }
    return true;
  }

  // `output` (and `component`) of an equation or figure, as `use` requires
  void ReadOutput(const YAML::Node& item, const std::string& ipath, OutputUse use, std::string& name, int& component) {
    const YAML::Node o = item["output"], c = item["component"];
    if (use == OutputUse::kNone) {
      if (o.IsDefined()) r_.Error(o, Child(ipath, "output"), "this quantity is a figure of the whole mechanism: it takes no output");
      if (c.IsDefined()) r_.Error(c, Child(ipath, "component"), "this quantity takes no component");
      return;
    }
    if (!r_.Require(item, "output", ipath).IsDefined() || o.IsNull()) return;
    if (auto text = r_.Text(o, Child(ipath, "output"))) name = *text;
    const int index = m_.FindOutput(name);
    if (index < 0) {
      r_.Error(o, Child(ipath, "output"), "names output '" + name + "', which the file does not declare");
      return;
    }
    const koppel::Output& out = m_.outputs[index];
    if (use == OutputUse::kPoint && out.kind != OutputKind::kPoint) r_.Error(o, Child(ipath, "output"), "this quantity needs a point output");
    if (use == OutputUse::kAngle && !IsAngleOutput(m_, out)) r_.Error(o, Child(ipath, "output"), "this quantity needs an angle output");
    if (!c.IsDefined()) return;
    const std::optional<std::string> text = r_.Text(c, Child(ipath, "component"));
    if (!text) return;
    if (use != OutputUse::kAny || out.Components() == 1) r_.Error(c, Child(ipath, "component"), "only a point output has components (x, y)");
    else if (*text == "x" || *text == "0") component = 0;
    else if (*text == "y" || *text == "1") component = 1;
    else r_.Error(c, Child(ipath, "component"), "expected x or y");
  }

  void ReadEquation(const YAML::Node& item, const std::string& ipath) {
    if (!r_.ExpectMap(item, ipath)) return;
    r_.CheckKeys(item, ipath, {"name", "output", "component", "order", "formula", "tolerance", "printed", "note"});
    EquationCheck e;
    e.line = item.Mark().line + 1;
    if (item["name"].IsDefined()) Set(e.name, item["name"], Child(ipath, "name"));
    ReadOutput(item, ipath, OutputUse::kAny, e.output, e.component);
    if (item["order"].IsDefined()) {
      Set(e.order, item["order"], Child(ipath, "order"));
      if (e.order > 8) r_.Error(item["order"], Child(ipath, "order"), "orders above 8 are not computed");
    }
    if (const YAML::Node f = r_.Require(item, "formula", ipath); f.IsDefined() && !f.IsNull() && CheckFormula(f, Child(ipath, "formula"), names_))
      e.formula = f.Scalar();
    if (const YAML::Node t = r_.Require(item, "tolerance", ipath); t.IsDefined() && !t.IsNull()) ReadTolerance(t, Child(ipath, "tolerance"), e.tolerance);
    if (item["printed"].IsDefined()) Set(e.printed, item["printed"], Child(ipath, "printed"));
    if (item["note"].IsDefined()) Set(e.note, item["note"], Child(ipath, "note"));
    if (e.name.empty()) e.name = e.output + (e.order ? "_d" + std::to_string(e.order) : "");
    card_.equations.push_back(std::move(e));
  }

  void ReadTolerance(const YAML::Node& node, const std::string& path, double& out) {
    const std::optional<double> t = r_.Number(node, path);
    if (t && *t < 0) r_.Error(node, path, "a tolerance must not be negative");
    else if (t) out = *t;
  }

  void ReadFigure(const YAML::Node& item, const std::string& ipath) {
    if (!r_.ExpectMap(item, ipath)) return;
    FigureCheck f;
    f.line = item.Mark().line + 1;
    const FigureQuantityInfo* info = ReadQuantity(item, ipath);
    if (!info) {
      // still report the other keys' problems, but not as unknown arguments
      ReadFigureCommon(item, ipath, f, nullptr);
      return;
    }
    f.quantity = info->quantity;
    std::vector<std::string> allowed = kFigureKeys;
    for (const FigureArgument& a : info->arguments) allowed.push_back(a.name);
    r_.CheckKeys(item, ipath, allowed);
    ReadOutput(item, ipath, info->output, f.output, f.component);
    for (const FigureArgument& a : info->arguments) ReadArgument(item, ipath, a, f);
    ReadFigureCommon(item, ipath, f, info);
    if (f.name.empty()) f.name = std::string(info->name) + (f.output.empty() ? "" : " " + f.output);
    card_.figures.push_back(std::move(f));
  }

  const FigureQuantityInfo* ReadQuantity(const YAML::Node& item, const std::string& ipath) {
    const YAML::Node q = r_.Require(item, "quantity", ipath);
    if (!q.IsDefined() || q.IsNull()) return nullptr;
    const std::optional<std::string> name = r_.Text(q, Child(ipath, "quantity"));
    if (!name) return nullptr;
    if (const FigureQuantityInfo* info = FindFigureQuantity(*name)) return info;
    std::vector<std::string> names;
    for (const FigureQuantityInfo& i : FigureQuantities()) names.push_back(i.name);
    r_.Error(q, Child(ipath, "quantity"), UnknownName("quantity", *name, names));
    return nullptr;
  }

  void ReadArgument(const YAML::Node& item, const std::string& ipath, const FigureArgument& a, FigureCheck& f) {
    const YAML::Node v = item[a.name];
    const std::string apath = Child(ipath, a.name);
    if (!v.IsDefined() || v.IsNull()) {
      if (a.required) r_.Error(item, apath, std::string("quantity '") + QuantityInfo(f.quantity).name + "' needs '" + a.name + "'");
      return;
    }
    if (!v.IsScalar()) {
      r_.Error(v, apath, "a figure argument must be a single value");
      return;
    }
    switch (a.kind) {
      case ArgumentKind::kInput:
      case ArgumentKind::kNumber:
        if (!CheckFormula(v, apath, file_.parameters)) return;
        break;
      case ArgumentKind::kOrder: {
        const std::optional<int> order = r_.Count(v, apath);
        if (!order) return;
        if (*order < 1 || *order > 8) {
          r_.Error(v, apath, "expected an order 1..8");
          return;
        }
        break;
      }
      case ArgumentKind::kJoint: {
        const int joint = m_.FindJoint(v.Scalar());
        if (joint < 0) {
          r_.Error(v, apath, "names unknown joint '" + v.Scalar() + "'");
          return;
        }
        if (m_.joints[joint].type != JointType::kRevolute) {
          r_.Error(v, apath, "joint '" + v.Scalar() + "' is not an R joint: only an R joint can turn");
          return;
        }
        break;
      }
    }
    f.args[a.name] = v.Scalar();
  }

  // name, expected, unit, tolerance, printed, note, variant
  void ReadFigureCommon(const YAML::Node& item, const std::string& ipath, FigureCheck& f, const FigureQuantityInfo* info) {
    if (item["name"].IsDefined()) Set(f.name, item["name"], Child(ipath, "name"));
    if (const YAML::Node e = r_.Require(item, "expected", ipath); e.IsDefined() && !e.IsNull() && CheckFormula(e, Child(ipath, "expected"), file_.parameters))
      f.expected = e.Scalar();
    if (const YAML::Node t = r_.Require(item, "tolerance", ipath); t.IsDefined() && !t.IsNull()) ReadTolerance(t, Child(ipath, "tolerance"), f.tolerance);
    if (item["printed"].IsDefined()) Set(f.printed, item["printed"], Child(ipath, "printed"));
    if (item["note"].IsDefined()) Set(f.note, item["note"], Child(ipath, "note"));
    if (const YAML::Node v = item["variant"]; v.IsDefined()) {
      Set(f.variant, v, Child(ipath, "variant"));
      const bool known = std::any_of(card_.variants.begin(), card_.variants.end(), [&](const CheckVariant& c) { return c.name == f.variant; });
      if (!known) r_.Error(v, Child(ipath, "variant"), "unknown variant '" + f.variant + "'");
    }
    const YAML::Node unit = item["unit"];
    if (unit.IsDefined()) {
      f.degrees = unit.IsScalar() && unit.Scalar() == "deg";
      if (!f.degrees) {
        r_.Error(unit, Child(ipath, "unit"), "the only unit is deg (angles in degrees)");
        return;
      }
    }
    if (!info) return;
    // a time ratio is the slow stroke over the fast one, >= 1 (figures named so once checked a phase ratio)
    if (info->quantity != FigureQuantity::kTimeRatio && FoldForSearch(f.name).find("timeratio") != std::string::npos)
      r_.Error(item, Child(ipath, "quantity"), "a figure named a time ratio is quantity time_ratio (the slow stroke's crank angle over the fast one's, >= 1)");
    // a rest says the output stands still: its expected stroke is 0 and its band is the tolerance
    if (info->quantity == FigureQuantity::kRest && item["expected"].IsScalar() && item["expected"].Scalar() != "0")
      r_.Error(item["expected"], Child(ipath, "expected"), "a rest's expected value is 0 (the output stands still); its tolerance is the band it rests in");
    // an angle is compared in degrees, so `unit: deg` says so; anything else has no unit
    const bool angle = ValueIsAngle(*info, f);
    if (angle && !unit.IsDefined()) r_.Error(item, Child(ipath, "unit"), "this figure is an angle: give 'unit: deg' and the expected value in degrees");
    if (!angle && unit.IsDefined()) r_.Error(unit, Child(ipath, "unit"), "this figure is not an angle: it has no unit");
  }

  bool ValueIsAngle(const FigureQuantityInfo& info, const FigureCheck& f) const {
    switch (info.unit) {
      case ValueUnit::kOfInput: return m_.InputIsAngle();
      case ValueUnit::kPlain: return false;
      case ValueUnit::kOfOutput: {
        const int o = m_.FindOutput(f.output);
        return o >= 0 && IsAngleOutput(m_, m_.outputs[o]);
      }
    }
    return false;
  }

  YamlReader& r_;
  const MechanismFile& file_;
  const Mechanism& m_;
  CatalogCard& card_;
  ParameterSet names_;  // what an equation may name: parameters, phi and the `where` names
};

}  // namespace

std::optional<CatalogCard> ReadCard(YamlReader& r, const YAML::Node& node, const MechanismFile& file) {
  if (!r.ExpectMap(node, "catalog")) return std::nullopt;
  CatalogCard card;
  CardReader(r, file, card).Read(node);
  return card;
}

}  // namespace koppel

// koppel catalog show ID: an entry as a page in the terminal (or JSON), its checks run and their
// status shown beside each equation and figure.
#include "catalog_command.hpp"
#include "common.hpp"

#include "koppel/catalog/figure_quantities.hpp"
#include "koppel/core/structure.hpp"

#include <fmt/core.h>

#include <iostream>
#include <sstream>

namespace koppel::cli {
namespace catalog_show {  // this file's own names, apart from the other commands' in a unity build
namespace {

// The outcomes of one equation or figure, over the variants it runs in.
std::vector<const CheckOutcome*> OutcomesOf(const EntryReport& report, CheckKind kind, const std::string& name) {
  std::vector<const CheckOutcome*> found;
  for (const CheckOutcome& c : report.checks) {
    if (c.kind == kind && c.name == name) found.push_back(&c);
  }
  return found;
}

std::string StatusLines(const std::vector<const CheckOutcome*>& outcomes, bool figure) {
  std::string s;
  for (const CheckOutcome* c : outcomes) {
    s += "      " + std::string(ToString(c->status)) + (c->variant.empty() ? "" : " [" + c->variant + "]");
    if (c->status == CheckStatus::kNotComputed) {
      s += ": " + c->detail + "\n";
      continue;
    }
    if (figure) s += ": koppel " + FormatNumber(c->value) + ",";
    s += " deviation " + Short(c->worst, 3) + (figure ? "" : " (worst, at " + FormatNumber(c->where) + ")") + "\n";
  }
  return s;
}

// `head` then `text`, wrapped at 100 columns with the continuation lines indented by `indent`
std::string Wrap(const std::string& head, const std::string& text, size_t indent) {
  constexpr size_t kWidth = 100;
  std::string out = head;
  size_t column = head.size();
  std::istringstream words(text);
  bool first = true;
  for (std::string word; words >> word; first = false) {
    if (!first && column + 1 + word.size() > kWidth) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
    } else if (!first) {
      out += " ";
      ++column;
    }
    out += word;
    column += word.size();
  }
  return out + "\n";
}

// "P_x", "P_y" for a point output's components, the name otherwise
std::string OutputText(const Mechanism& m, const std::string& output, int component) {
  const int o = m.FindOutput(output);
  if (o < 0 || m.outputs[o].Components() == 1) return output;
  return output + (component == 1 ? "_y" : "_x");
}

std::string Wrapped(const std::string& label, const std::string& text) { return Wrap("    " + label + ": ", text, 6); }

std::string Description(const CatalogEntry& e) {
  const CatalogCard& c = *e.file.card;
  std::string t = e.file.id + "\n" + std::string(e.file.id.size(), '=') + "\n";
  t += c.title_de + "\n" + c.title_en + "\n\n";
  t += "kind:         " + std::string(c.kind == CardKind::kTransfer ? "transfer mechanism (Übertragungsgetriebe)" : "guidance mechanism (Führungsgetriebe)") + "\n";
  t += "classes:      " + Join(e.classes, ", ") + "\n";
  if (!c.motion.empty()) t += "motion:       " + c.motion + "\n";
  for (const std::string& a : c.applications) t += "application:  " + a + "\n";
  t += "file:         " + e.file.path + "\n";
  return t;
}

std::string Features(const CatalogEntry& e) {
  const AccessFeatures& f = e.features;
  const Mechanism& m = e.file.mechanism;
  const StructureSummary s = AnalyseStructure(m);
  std::string t = "\nAccess features (Zugriffsmerkmale)\n";
  t += fmt::format("  drive joints:  {}, {} at the frame\n", f.drive_joints, f.drive_joints_at_frame);
  t += fmt::format("  output links:  {}, {} at the frame\n", f.output_links, f.output_links_at_frame);
  t += "  links:         " + LinksText(f) + "\n";
  t += "  joints:        " + JointsText(f) + "\n";
  t += fmt::format("  mobility:      {} (Grübler-Kutzbach)\n", s.gruebler_mobility);
  t += "\nStructure (joint: type links)\n";
  std::string formula = s.formula;
  for (size_t pos = 0; (pos = formula.find('\n', pos)) != std::string::npos && pos + 1 < formula.size(); pos += 3) formula.replace(pos, 1, "\n  ");
  t += "  " + formula;
  // the output links (Abtriebsglieder, marked with a double arrow in the Strukturbild)
  for (const std::string& o : e.file.card->outputs) {
    const int link = OutputLink(m, m.outputs[m.FindOutput(o)]);
    if (link >= 0) t += "  output link (Abtrieb): " + m.links[link].name + " (output '" + o + "')\n";
  }
  return t;
}

std::string Dimensions(const CatalogEntry& e) {
  const Mechanism& m = e.file.mechanism;
  const CatalogCard& c = *e.file.card;
  std::string t = "\nDimensions (parameters)\n";
  for (const auto& [n, v] : e.file.parameters.Values()) t += "  " + n + " = " + FormatNumber(v) + "\n";
  for (const CheckVariant& v : c.variants) {
    std::vector<std::string> parts;
    for (const auto& [n, f] : v.overrides) parts.push_back(n + " = " + f);
    t += "  variant " + v.name + ": " + Join(parts, ", ") + "\n";
  }
  t += "\nConventions\n  input " + m.drive.input_name + " = joint '" + m.joints[m.drive.joint].name + "' value" +
       (m.InputIsAngle() ? " [deg], counter-clockwise positive" : " [length]") + "; outputs: " + Join(c.outputs, ", ") + "\n";
  t += "  (the comments at the top of " + e.file.path + " give the coordinate system and branch)\n";
  return t;
}

std::string Checks(const CatalogEntry& e, const EntryReport& report) {
  const CatalogCard& c = *e.file.card;
  std::string t;
  for (const CheckOutcome* f : OutcomesOf(report, CheckKind::kFeatures, "access features"))
    t += "\nAccess features and classes against the joint graph: " + std::string(ToString(f->status)) + (f->passed() ? "" : " — " + f->detail) + "\n";
  if (!c.equations.empty()) t += "\nEquations (over " + Short(c.from, 6) + " .. " + Short(c.to, 6) + " step " + Short(c.step, 6) + ")\n";
  for (const auto& [name, formula] : c.where) t += "  where " + name + " = " + formula + "\n";
  for (const EquationCheck& q : c.equations) {
    t += Wrap("  ", q.name, 4) +
         Wrapped(OutputText(e.file.mechanism, q.output, q.component) + (q.order ? " d" + std::to_string(q.order) : ""),
                 q.formula + "   (tolerance " + Short(q.tolerance) + ")");
    if (!q.printed.empty()) t += Wrapped("printed", q.printed);
    if (!q.note.empty()) t += Wrapped("note", q.note);
    t += StatusLines(OutcomesOf(report, CheckKind::kEquation, q.name), false);
  }
  if (!c.figures.empty()) t += "\nFigures\n";
  for (const FigureCheck& fig : c.figures) {
    std::string args;
    for (const auto& [k, v] : fig.args) args += ", " + k + " " + v;
    t += Wrap("  ", fig.name, 4) +
         Wrapped(std::string(QuantityInfo(fig.quantity).name) + (fig.output.empty() ? "" : " of " + OutputText(e.file.mechanism, fig.output, fig.component)) + args,
                 fig.expected + (fig.degrees ? " deg" : "") + " ± " + Short(fig.tolerance) + (fig.variant.empty() ? "" : "   [" + fig.variant + "]"));
    if (!fig.printed.empty()) t += Wrapped("printed", fig.printed);
    if (!fig.note.empty()) t += Wrapped("note", fig.note);
    t += StatusLines(OutcomesOf(report, CheckKind::kFigure, fig.name), true);
  }
  return t;
}

std::string Literature(const CatalogCard& c) {
  std::string t = "\nSource\n" + Wrap("  ", c.document, 2);
  if (!c.author.empty()) t += "  " + c.author + "\n";
  if (!c.literature.empty()) t += "\nLiterature\n";
  for (const std::string& l : c.literature) t += Wrap("  - ", l, 4);
  return t;
}

nlohmann::json PageJson(const CatalogEntry& e, const EntryReport& report) {
  const CatalogCard& c = *e.file.card;
  const StructureSummary s = AnalyseStructure(e.file.mechanism);
  nlohmann::json params = nlohmann::json::object(), eqs = nlohmann::json::array(), figs = nlohmann::json::array();
  for (const auto& [n, v] : e.file.parameters.Values()) params[n] = v;
  auto statuses = [&](CheckKind kind, const std::string& name) {
    nlohmann::json j = nlohmann::json::array();
    for (const CheckOutcome* o : OutcomesOf(report, kind, name))
      j.push_back({{"variant", o->variant}, {"status", ToString(o->status)}, {"worst", o->worst}, {"value", o->value}});
    return j;
  };
  for (const EquationCheck& q : c.equations)
    eqs.push_back({{"name", q.name}, {"output", q.output}, {"order", q.order}, {"formula", q.formula}, {"tolerance", q.tolerance},
                   {"printed", q.printed}, {"note", q.note}, {"checks", statuses(CheckKind::kEquation, q.name)}});
  for (const FigureCheck& f : c.figures)
    figs.push_back({{"name", f.name}, {"quantity", QuantityInfo(f.quantity).name}, {"output", f.output}, {"arguments", f.args},
                    {"expected", f.expected}, {"unit", f.degrees ? "deg" : ""}, {"tolerance", f.tolerance}, {"printed", f.printed},
                    {"note", f.note}, {"variant", f.variant}, {"checks", statuses(CheckKind::kFigure, f.name)}});
  return {{"id", e.file.id}, {"title_de", c.title_de}, {"title_en", c.title_en}, {"kind", ToString(c.kind)},
          {"classes", e.classes}, {"motion", c.motion}, {"applications", c.applications}, {"document", c.document},
          {"author", c.author}, {"literature", c.literature}, {"file", e.file.path}, {"structure", s.formula},
          {"gruebler_mobility", s.gruebler_mobility}, {"parameters", params}, {"equations", eqs}, {"figures", figs},
          {"passed", report.passed()}};
}

}  // namespace
}  // namespace catalog_show

void RunShow(const CatalogArgs& args) {
  using namespace catalog_show;
  if (args.format != "html") CheckCatalogFormat(args.format);
  if (args.format == "csv") {
    Complain("catalog show prints a page (table, the default), html or json, not csv");
    throw Exit{kExitBadInput};
  }
  const Catalog catalog = LoadCatalog(args);
  const CatalogEntry& e = FindOrFail(catalog, args.ids.at(0), CatalogDirectoryOf(args));
  EntryReport report;
  try {
    report = CheckEntry(e.file.path);
  } catch (const InputError& error) {
    for (const Diagnostic& d : error.diagnostics()) std::cerr << d.ToString() << "\n";
    throw Exit{kExitBadInput};
  }
  const std::string page = Description(e) + Features(e) + Dimensions(e) + Checks(e, report) + Literature(*e.file.card) + "\n" +
                           report.Brief() + "\n";
  std::vector<std::string> problems;
  if (args.format == "json") {
    WriteOutput(args.out, JsonText(PageJson(e, report)));
  } else if (args.format == "html") {
    WriteOutput(args.out, EntryHtml(e, page, &problems));
    for (const std::string& p : problems) Complain(e.file.id + ": " + p);
  } else {
    WriteOutput(args.out, page);
  }
  // the page shows which checks fail (and what could not be drawn); the exit code says so too
  if (!report.passed() || !problems.empty()) throw Exit{kExitFailed};
}

}  // namespace koppel::cli

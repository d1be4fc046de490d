// koppel catalog show ID: an entry as a page in the terminal (or JSON), its checks run and their
// status shown beside each equation and figure.
#include "catalog_command.hpp"
#include "common.hpp"

#include <fmt/core.h>

#include <iostream>
#include <sstream>

namespace koppel::cli {
namespace catalog_show {  // this file's own names, apart from the other commands' in a unity build
namespace {

// The outcomes of one equation or figure, over the variants it runs in.
std::vector<const CatalogCheck*> OutcomesOf(const CatalogCheckReport& report, CatalogCheckKind kind, const std::string& name) {
  std::vector<const CatalogCheck*> found;
  for (const CatalogCheck& c : report.checks) {
    if (c.kind == kind && c.name == name) found.push_back(&c);
  }
  return found;
}

std::string StatusLines(const std::vector<const CatalogCheck*>& outcomes, bool figure) {
  std::string s;
  for (const CatalogCheck* c : outcomes) {
    s += "      " + std::string(ToString(c->status)) + (c->variant.empty() ? "" : " [" + c->variant + "]");
    if (!c->computed()) {
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

std::string Wrapped(const std::string& label, const std::string& text) { return Wrap("    " + label + ": ", text, 6); }

std::string Description(const CatalogPage& p) {
  const CatalogHit& e = p.entry;
  std::string t = e.id + "\n" + std::string(e.id.size(), '=') + "\n";
  t += e.title_de + "\n" + e.title_en + "\n\n";
  t += "kind:         " + std::string(e.kind == "transfer" ? "transfer mechanism (Übertragungsgetriebe)" : "guidance mechanism (Führungsgetriebe)") + "\n";
  t += "classes:      " + Join(e.classes, ", ") + "\n";
  if (!e.motion.empty()) t += "motion:       " + e.motion + "\n";
  for (const std::string& a : p.applications) t += "application:  " + a + "\n";
  t += "file:         " + e.path + "\n";
  return t;
}

std::string Features(const CatalogPage& p) {
  const CatalogFeatures& f = p.entry.features;
  std::string t = "\nAccess features (Zugriffsmerkmale)\n";
  t += fmt::format("  drive joints:  {}, {} at the frame\n", f.drive_joints, f.drive_joints_at_frame);
  t += fmt::format("  output links:  {}, {} at the frame\n", f.output_links, f.output_links_at_frame);
  t += "  links:         " + LinksText(f) + "\n";
  t += "  joints:        " + JointsText(f) + "\n";
  t += fmt::format("  mobility:      {} (Grübler-Kutzbach)\n", p.gruebler_mobility);
  t += "\nStructure (joint: type links)\n";
  std::string formula = p.structure;
  for (size_t pos = 0; (pos = formula.find('\n', pos)) != std::string::npos && pos + 1 < formula.size(); pos += 3) formula.replace(pos, 1, "\n  ");
  t += "  " + formula;
  // the output links (Abtriebsglieder, marked with a double arrow in the Strukturbild)
  for (const auto& [output, link] : p.output_links) t += "  output link (Abtrieb): " + link + " (output '" + output + "')\n";
  return t;
}

std::string Dimensions(const CatalogPage& p) {
  std::string t = "\nDimensions (parameters)\n";
  for (const auto& [n, v] : p.parameters) t += "  " + n + " = " + FormatNumber(v) + "\n";
  for (const CatalogVariant& v : p.variants) {
    std::vector<std::string> parts;
    for (const auto& [n, f] : v.overrides) parts.push_back(n + " = " + f);
    t += "  variant " + v.name + ": " + Join(parts, ", ") + "\n";
  }
  t += "\nConventions\n  input " + p.input_name + " = joint '" + p.drive_joint + "' value" +
       (p.input_is_angle ? " [deg], counter-clockwise positive" : " [length]") + "; outputs: " + Join(p.outputs, ", ") + "\n";
  t += "  (the comments at the top of " + p.entry.path + " give the coordinate system and branch)\n";
  return t;
}

std::string Checks(const CatalogPage& p) {
  const CatalogCheckReport& report = p.report;
  std::string t;
  for (const CatalogCheck* f : OutcomesOf(report, CatalogCheckKind::kFeatures, "access features"))
    t += "\nAccess features and classes against the joint graph: " + std::string(ToString(f->status)) + (f->passed() ? "" : " — " + f->detail) + "\n";
  if (!p.equations.empty()) t += "\nEquations (over " + Short(p.from, 6) + " .. " + Short(p.to, 6) + " step " + Short(p.step, 6) + ")\n";
  for (const auto& [name, formula] : p.where) t += "  where " + name + " = " + formula + "\n";
  for (const CatalogEquation& q : p.equations) {
    t += Wrap("  ", q.name, 4) +
         Wrapped(q.output_shown + (q.order ? " d" + std::to_string(q.order) : ""), q.formula + "   (tolerance " + Short(q.tolerance) + ")");
    if (!q.printed.empty()) t += Wrapped("printed", q.printed);
    if (!q.note.empty()) t += Wrapped("note", q.note);
    t += StatusLines(OutcomesOf(report, CatalogCheckKind::kEquation, q.name), false);
  }
  if (!p.figures.empty()) t += "\nFigures\n";
  for (const CatalogFigure& fig : p.figures) {
    std::string args;
    for (const auto& [k, v] : fig.arguments) args += ", " + k + " " + v;
    t += Wrap("  ", fig.name, 4) +
         Wrapped(fig.quantity + (fig.output.empty() ? "" : " of " + fig.output_shown) + args,
                 fig.expected + (fig.degrees ? " deg" : "") + " ± " + Short(fig.tolerance) + (fig.variant.empty() ? "" : "   [" + fig.variant + "]"));
    if (!fig.printed.empty()) t += Wrapped("printed", fig.printed);
    if (!fig.note.empty()) t += Wrapped("note", fig.note);
    t += StatusLines(OutcomesOf(report, CatalogCheckKind::kFigure, fig.name), true);
  }
  return t;
}

std::string Literature(const CatalogPage& p) {
  std::string t = "\nSource\n" + Wrap("  ", p.document, 2);
  if (!p.author.empty()) t += "  " + p.author + "\n";
  if (!p.literature.empty()) t += "\nLiterature\n";
  for (const std::string& l : p.literature) t += Wrap("  - ", l, 4);
  return t;
}

nlohmann::json PageJson(const CatalogPage& p) {
  const CatalogHit& e = p.entry;
  nlohmann::json params = nlohmann::json::object(), eqs = nlohmann::json::array(), figs = nlohmann::json::array();
  for (const auto& [n, v] : p.parameters) params[n] = v;
  auto statuses = [&](CatalogCheckKind kind, const std::string& name) {
    nlohmann::json j = nlohmann::json::array();
    for (const CatalogCheck* o : OutcomesOf(p.report, kind, name))
      j.push_back({{"variant", o->variant}, {"status", ToString(o->status)}, {"worst", o->worst}, {"value", o->value}});
    return j;
  };
  for (const CatalogEquation& q : p.equations)
    eqs.push_back({{"name", q.name}, {"output", q.output}, {"order", q.order}, {"formula", q.formula}, {"tolerance", q.tolerance},
                   {"printed", q.printed}, {"note", q.note}, {"checks", statuses(CatalogCheckKind::kEquation, q.name)}});
  for (const CatalogFigure& f : p.figures)
    figs.push_back({{"name", f.name}, {"quantity", f.quantity}, {"output", f.output}, {"arguments", f.arguments},
                    {"expected", f.expected}, {"unit", f.degrees ? "deg" : ""}, {"tolerance", f.tolerance}, {"printed", f.printed},
                    {"note", f.note}, {"variant", f.variant}, {"checks", statuses(CatalogCheckKind::kFigure, f.name)}});
  return {{"id", e.id}, {"title_de", e.title_de}, {"title_en", e.title_en}, {"kind", e.kind},
          {"classes", e.classes}, {"motion", e.motion}, {"applications", p.applications}, {"document", p.document},
          {"author", p.author}, {"literature", p.literature}, {"file", e.path}, {"structure", p.structure},
          {"gruebler_mobility", p.gruebler_mobility}, {"parameters", params}, {"equations", eqs}, {"figures", figs},
          {"passed", p.report.passed}};
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
  CatalogPage p;
  try {
    p = ShowCatalogEntry(args.ids.at(0), CatalogDirectoryOf(args));
  } catch (const InputError& error) {
    FailWithDiagnostics(error);
  }
  RefuseUnknownId(p.refused);
  const std::string page = Description(p) + Features(p) + Dimensions(p) + Checks(p) + Literature(p) + "\n" + p.report.brief + "\n";
  std::vector<std::string> problems;
  if (args.format == "json") {
    WriteOutput(args.out, JsonText(PageJson(p)));
  } else if (args.format == "html") {
    WriteOutput(args.out, EntryHtml(p, page, &problems));
    for (const std::string& problem : problems) Complain(p.entry.id + ": " + problem);
  } else {
    WriteOutput(args.out, page);
  }
  // the page shows which checks fail (and what could not be drawn); the exit code says so too
  if (!p.report.passed || !problems.empty()) throw Exit{kExitFailed};
}

}  // namespace koppel::cli

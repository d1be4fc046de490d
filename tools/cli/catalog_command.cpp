// koppel catalog list | find | show | check: the catalog of documented mechanisms.
#include "commands.hpp"
#include "common.hpp"

#include "koppel/catalog/catalog.hpp"
#include "koppel/catalog/check.hpp"
#include "koppel/core/structure.hpp"

#include <fmt/core.h>

#include <iostream>

namespace koppel::cli {
namespace {

struct CatalogArgs {
  std::string directory;
  std::string format = "csv";
  std::string out;
  // find
  std::string links, binary, ternary, quaternary, joints, revolute, prismatic;
  std::string drives, drives_at_frame, outputs, outputs_at_frame;
  std::string kind, text;
  // show / check
  std::vector<std::string> ids;
};

Catalog LoadCatalog(const CatalogArgs& args) {
  try {
    return Catalog::Load(args.directory.empty() ? DefaultCatalogDirectory() : args.directory);
  } catch (const InputError& e) {
    for (const Diagnostic& d : e.diagnostics()) std::cerr << d.ToString() << "\n";
    throw Exit{kExitBadInput};
  }
}

int Count(const std::map<int, int>& m, int k) {
  auto it = m.find(k);
  return it == m.end() ? 0 : it->second;
}
int Count(const std::map<std::string, int>& m, const std::string& k) {
  auto it = m.find(k);
  return it == m.end() ? 0 : it->second;
}

// "4 (4 binary)" / "7 (4 D, 3 S)"
std::string LinksText(const AccessFeatures& f) {
  std::string s = std::to_string(f.links) + " (";
  bool first = true;
  for (const auto& [degree, n] : f.links_by_degree) {
    if (n == 0) continue;
    s += (first ? "" : ", ") + std::to_string(n) + " " + DegreeName(degree);
    first = false;
  }
  return s + ")";
}
std::string JointsText(const AccessFeatures& f) {
  std::string s = std::to_string(f.joints) + " (";
  bool first = true;
  for (const auto& [type, n] : f.joints_by_type) {
    if (n == 0) continue;
    s += (first ? "" : ", ") + std::to_string(n) + " " + type;
    first = false;
  }
  return s + ")";
}

nlohmann::json FeaturesJson(const AccessFeatures& f) {
  nlohmann::json by_degree = nlohmann::json::object(), by_type = nlohmann::json::object();
  for (const auto& [d, n] : f.links_by_degree) by_degree[DegreeName(d)] = n;
  for (const auto& [t, n] : f.joints_by_type) by_type[t] = n;
  return {{"drive_joints", f.drive_joints}, {"drive_joints_at_frame", f.drive_joints_at_frame},
          {"output_links", f.output_links}, {"output_links_at_frame", f.output_links_at_frame},
          {"links", f.links}, {"links_by_degree", by_degree}, {"joints", f.joints}, {"joints_by_type", by_type}};
}

std::string CsvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void PrintEntries(const std::vector<const CatalogEntry*>& entries, const CatalogArgs& args) {
  if (args.format == "json") {
    nlohmann::json j = nlohmann::json::array();
    for (const CatalogEntry* e : entries) {
      const CatalogCard& c = *e->file.card;
      j.push_back({{"id", e->file.id}, {"title_de", c.title_de}, {"title_en", c.title_en}, {"kind", c.kind},
                   {"file", e->file.path}, {"features", FeaturesJson(e->features)}});
    }
    WriteOutput(args.out, JsonText(j));
    return;
  }
  std::string csv = "id,title_de,title_en,kind,drives,drives_at_frame,outputs,outputs_at_frame,links,binary,ternary,quaternary,joints,D,S\n";
  for (const CatalogEntry* e : entries) {
    const CatalogCard& c = *e->file.card;
    const AccessFeatures& f = e->features;
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", CsvField(e->file.id), CsvField(c.title_de),
                       CsvField(c.title_en), c.kind, f.drive_joints, f.drive_joints_at_frame, f.output_links,
                       f.output_links_at_frame, f.links, Count(f.links_by_degree, 2), Count(f.links_by_degree, 3),
                       Count(f.links_by_degree, 4), f.joints, Count(f.joints_by_type, "D"), Count(f.joints_by_type, "S"));
  }
  WriteOutput(args.out, csv);
}

std::optional<CountRange> Range(const std::string& flag, const std::string& text) {
  if (text.empty()) return std::nullopt;
  auto r = CountRange::Parse(text);
  if (!r) {
    Complain(flag + ": expected a count like 4 or a range like 4..6, found '" + text + "'");
    throw Exit{kExitBadInput};
  }
  return r;
}

void RunFind(const CatalogArgs& args, bool all) {
  CheckFormat(args.format);
  FeatureQuery q;
  if (!all) {
    q.links = Range("--links", args.links);
    q.binary = Range("--binary", args.binary);
    q.ternary = Range("--ternary", args.ternary);
    q.quaternary = Range("--quaternary", args.quaternary);
    q.joints = Range("--joints", args.joints);
    q.revolute = Range("--revolute", args.revolute);
    q.prismatic = Range("--prismatic", args.prismatic);
    q.drives = Range("--drives", args.drives);
    q.drives_at_frame = Range("--drives-at-frame", args.drives_at_frame);
    q.outputs = Range("--outputs", args.outputs);
    q.outputs_at_frame = Range("--outputs-at-frame", args.outputs_at_frame);
    if (!args.kind.empty() && args.kind != "transfer" && args.kind != "guidance") {
      Complain("--kind must be transfer or guidance");
      throw Exit{kExitBadInput};
    }
    q.kind = args.kind;
    q.text = args.text;
  }
  const Catalog catalog = LoadCatalog(args);
  PrintEntries(FindEntries(catalog, q), args);
}

const CatalogEntry& FindOrFail(const Catalog& catalog, const std::string& id) {
  const CatalogEntry* e = catalog.Find(id);
  if (!e) {
    std::string known;
    for (const CatalogEntry& c : catalog.entries()) known += " " + c.file.id;
    Complain("no catalog entry '" + id + "' (entries:" + known + ")");
    throw Exit{kExitBadInput};
  }
  return *e;
}

void RunShow(const CatalogArgs& args) {
  CheckFormat(args.format);
  const Catalog catalog = LoadCatalog(args);
  const CatalogEntry& e = FindOrFail(catalog, args.ids.at(0));
  const CatalogCard& c = *e.file.card;
  const Mechanism& m = e.file.mechanism;
  const StructureSummary s = AnalyseStructure(m);
  if (args.format == "json") {
    nlohmann::json params = nlohmann::json::object();
    for (const auto& [n, v] : e.file.parameters.Values()) params[n] = v;
    nlohmann::json eqs = nlohmann::json::array(), figs = nlohmann::json::array();
    for (const EquationCheck& q : c.equations)
      eqs.push_back({{"name", q.name}, {"output", q.output}, {"order", q.order}, {"formula", q.formula},
                     {"tolerance", q.tolerance}, {"printed", q.printed}, {"note", q.note}});
    for (const FigureCheck& f : c.figures)
      figs.push_back({{"name", f.name}, {"quantity", f.quantity}, {"expected", f.expected}, {"unit", f.unit},
                      {"tolerance", f.tolerance}, {"printed", f.printed}, {"note", f.note}, {"variant", f.variant}});
    nlohmann::json j = {{"id", e.file.id}, {"title_de", c.title_de}, {"title_en", c.title_en}, {"kind", c.kind},
                        {"motion", c.motion}, {"applications", c.applications}, {"document", c.document},
                        {"author", c.author}, {"literature", c.literature}, {"file", e.file.path},
                        {"features", FeaturesJson(e.features)}, {"structure", s.formula},
                        {"gruebler_mobility", s.gruebler_mobility}, {"parameters", params},
                        {"equations", eqs}, {"figures", figs}};
    WriteOutput(args.out, JsonText(j));
    return;
  }
  std::string t;
  t += e.file.id + ": " + c.title_de + " — " + c.title_en + "\n";
  t += "file:         " + e.file.path + "\n";
  t += "kind:         " + std::string(c.kind == "transfer" ? "transfer mechanism (Übertragungsgetriebe)" : "guidance mechanism (Führungsgetriebe)") + "\n";
  if (!c.motion.empty()) t += "motion:       " + c.motion + "\n";
  for (const std::string& a : c.applications) t += "application:  " + a + "\n";
  t += "source:       " + c.document + "\n";
  if (!c.author.empty()) t += "author:       " + c.author + "\n";
  for (const std::string& l : c.literature) t += "literature:   " + l + "\n";
  const AccessFeatures& f = e.features;
  t += "\nAccess features (Zugriffsmerkmale)\n";
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
  for (const std::string& o : c.outputs) {
    const int link = OutputLink(m, m.outputs[m.FindOutput(o)]);
    if (link >= 0) t += "  output link (Abtrieb): " + m.links[link].name + " (output '" + o + "')\n";
  }
  t += "\nParameters\n";
  for (const auto& [n, v] : e.file.parameters.Values()) t += "  " + n + " = " + FormatNumber(v) + "\n";
  t += "\nConventions\n  input " + m.drive.input_name + " = joint '" + m.joints[m.drive.joint].name + "' value" +
       (m.InputIsAngle() ? " [deg], counter-clockwise positive" : " [length]") + "; outputs:";
  for (const std::string& o : c.outputs) t += " " + o;
  t += "\n  (the comments at the top of " + e.file.path + " give the coordinate system and branch)\n";
  t += "\nChecks\n";
  for (const EquationCheck& q : c.equations) {
    t += "  equation: " + q.name + "  [" + q.output + (q.order ? " d" + std::to_string(q.order) : "") + " = " + q.formula +
         ", tol " + FormatNumber(q.tolerance) + "]\n";
    if (!q.printed.empty()) t += "    printed: " + q.printed + "\n";
    if (!q.note.empty()) t += "    note: " + q.note + "\n";
  }
  for (const FigureCheck& fig : c.figures) {
    t += "  figure: " + fig.name + "  [" + fig.quantity + " = " + fig.expected + (fig.unit.empty() ? "" : " " + fig.unit) +
         " ± " + FormatNumber(fig.tolerance) + (fig.variant.empty() ? "" : ", " + fig.variant) + "]\n";
    if (!fig.printed.empty()) t += "    printed: " + fig.printed + "\n";
    if (!fig.note.empty()) t += "    note: " + fig.note + "\n";
  }
  WriteOutput(args.out, t);
}

void RunCheck(const CatalogArgs& args) {
  CheckFormat(args.format);
  const Catalog catalog = LoadCatalog(args);
  std::vector<const CatalogEntry*> entries;
  if (args.ids.empty()) {
    for (const CatalogEntry& e : catalog.entries()) entries.push_back(&e);
  } else {
    for (const std::string& id : args.ids) entries.push_back(&FindOrFail(catalog, id));
  }
  std::vector<EntryReport> reports;
  for (const CatalogEntry* e : entries) {
    try {
      reports.push_back(CheckEntry(e->file.path));
    } catch (const InputError& error) {
      for (const Diagnostic& d : error.diagnostics()) std::cerr << d.ToString() << "\n";
      throw Exit{kExitBadInput};
    }
  }
  int failed = 0, pending = 0, passed = 0;
  if (args.format == "json") {
    nlohmann::json j = nlohmann::json::array();
    for (const EntryReport& r : reports) {
      nlohmann::json checks = nlohmann::json::array();
      for (const CheckOutcome& c : r.checks) {
        checks.push_back({{"variant", c.variant}, {"name", c.name}, {"kind", c.kind}, {"worst", c.worst},
                          {"tolerance", c.tolerance}, {"value", c.value}, {"where", c.where},
                          {"status", c.pending ? "pending" : (c.passed ? "pass" : "FAIL")}, {"detail", c.detail}});
        (c.pending ? pending : c.passed ? passed : failed) += 1;
      }
      j.push_back({{"id", r.id}, {"passed", r.passed()}, {"checks", checks}});
    }
    WriteOutput(args.out, JsonText(j));
  } else {
    std::string csv = "id,variant,kind,check,status,worst,tolerance,value,at,detail\n";
    for (const EntryReport& r : reports) {
      for (const CheckOutcome& c : r.checks) {
        const char* status = c.pending ? "pending" : (c.passed ? "pass" : "FAIL");
        (c.pending ? pending : c.passed ? passed : failed) += 1;
        csv += fmt::format("{},{},{},{},{},{:.3g},{:.3g},{},{},{}\n", r.id, CsvField(c.variant), c.kind, CsvField(c.name), status,
                           c.worst, c.tolerance, c.kind == "figure" ? FormatNumber(c.value) : "",
                           c.kind == "equation" ? FormatNumber(c.where) : "", CsvField(c.pending || !c.passed ? c.detail : ""));
      }
    }
    WriteOutput(args.out, csv);
  }
  std::cerr << fmt::format("koppel catalog check: {} entries, {} passed, {} failed, {} pending\n", reports.size(), passed,
                           failed, pending);
  if (failed > 0) throw Exit{kExitFailed};
}

}  // namespace

void AddCatalogCommand(CLI::App& app) {
  auto args = std::make_shared<CatalogArgs>();
  CLI::App* cmd = app.add_subcommand(
      "catalog",
      "The catalog of documented mechanisms (catalog/entries/*.yaml, or --catalog DIR, or $KOPPEL_CATALOG).\n"
      "Entries are found by their access features (Zugriffsmerkmale) and check themselves against their\n"
      "documents' equations and figures.");
  cmd->require_subcommand(1);
  auto common = [&](CLI::App* sub) {
    sub->add_option("--catalog", args->directory, "Catalog directory (default: the built-in one)");
    sub->add_option("--format", args->format, "csv (default) or json");
    sub->add_option("-o,--output-file", args->out, "Write to this file instead of stdout");
  };
  CLI::App* list = cmd->add_subcommand("list", "List every entry: id, titles, kind and access features (CSV).");
  common(list);
  list->callback([args] { RunFind(*args, true); });

  CLI::App* find = cmd->add_subcommand(
      "find",
      "Find entries by access features. Each count is a number (4) or a range (4..6, ..6, 4..); all given\n"
      "features must match. Example: koppel catalog find --links 6 --ternary 2 --revolute 4 --prismatic 3 --drives-at-frame 1");
  common(find);
  find->add_option("--links", args->links, "Links, the frame included");
  find->add_option("--binary", args->binary, "Binary links (two joints)");
  find->add_option("--ternary", args->ternary, "Ternary links (three joints)");
  find->add_option("--quaternary", args->quaternary, "Quaternary links (four joints)");
  find->add_option("--joints", args->joints, "Joints");
  find->add_option("--revolute", args->revolute, "Revolute joints (D)");
  find->add_option("--prismatic", args->prismatic, "Prismatic joints (S)");
  find->add_option("--drives", args->drives, "Drive joints");
  find->add_option("--drives-at-frame", args->drives_at_frame, "Drive joints at the frame");
  find->add_option("--outputs", args->outputs, "Output links");
  find->add_option("--outputs-at-frame", args->outputs_at_frame, "Output links jointed to the frame");
  find->add_option("--kind", args->kind, "transfer (Übertragungsgetriebe) or guidance (Führungsgetriebe)");
  find->add_option("--text", args->text, "Case-insensitive text in the id or titles");
  find->callback([args] { RunFind(*args, false); });

  CLI::App* show = cmd->add_subcommand("show", "Print an entry's full card: features, structure, dimensions, conventions, checks.");
  common(show);
  show->add_option("id", args->ids, "Entry id")->required()->expected(1);
  show->callback([args] { RunShow(*args); });

  CLI::App* check = cmd->add_subcommand(
      "check",
      "Recompute every check of the given entries (default: all) with the generic solver: access features from\n"
      "the joint graph, the document's equations over a sweep, its figures. Prints per check the worst deviation\n"
      "and the tolerance (CSV); exit code 1 if any check fails. Pending checks need an analysis not yet built.");
  common(check);
  check->add_option("ids", args->ids, "Entry ids (default: all)");
  check->callback([args] { RunCheck(*args); });
}

}  // namespace koppel::cli

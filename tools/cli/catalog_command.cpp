// koppel catalog list | find | show | check | page: the catalog of documented mechanisms.
#include "catalog_command.hpp"
#include "commands.hpp"
#include "common.hpp"

#include "koppel/api/catalog.hpp"
#include "koppel/core/printable_text.hpp"
#include "koppel/core/structure.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <iostream>

namespace koppel::cli {

void CheckCatalogFormat(const std::string& format) {
  if (format == "table" || format == "csv" || format == "json") return;
  Complain("--format must be table, csv or json, found '" + format + "'");
  throw Exit{kExitBadInput};
}

std::string CatalogDirectoryOf(const CatalogArgs& args) { return args.directory.empty() ? CatalogDirectory() : args.directory; }

void FailWithDiagnostics(const InputError& error) {
  for (const Diagnostic& d : error.diagnostics()) std::cerr << d.ToString() << "\n";
  throw Exit{kExitBadInput};
}

void RefuseUnknownId(const std::string& refused) {
  if (refused.empty()) return;
  Complain(refused);
  throw Exit{kExitBadInput};
}

namespace catalog_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

// display width of UTF-8 text: count the bytes that start a character
size_t Width(const std::string& s) {
  size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

int Count(const std::map<int, int>& m, int k) {
  auto it = m.find(k);
  return it == m.end() ? 0 : it->second;
}
int Count(const std::map<std::string, int>& m, const std::string& k) {
  auto it = m.find(k);
  return it == m.end() ? 0 : it->second;
}

}  // namespace
}  // namespace catalog_command

std::string TextTable(const std::vector<std::vector<std::string>>& raw_rows) {
  using namespace catalog_command;
  std::vector<std::vector<std::string>> rows = raw_rows;
  for (auto& row : rows)
    for (std::string& cell : row) cell = PrintableText(cell, Replacement::kReplacementCharacter);
  std::vector<size_t> widths;
  for (const auto& row : rows) {
    if (widths.size() < row.size()) widths.resize(row.size(), 0);
    for (size_t i = 0; i < row.size(); ++i) widths[i] = std::max(widths[i], Width(row[i]));
  }
  std::string out;
  for (const auto& row : rows) {
    std::string line;
    for (size_t i = 0; i < row.size(); ++i) {
      line += row[i];
      if (i + 1 < row.size()) line += std::string(widths[i] - Width(row[i]) + 2, ' ');
    }
    out += line + "\n";
  }
  return out;
}

std::string Join(const std::vector<std::string>& items, const std::string& separator) {
  using namespace catalog_command;
  std::string s;
  for (const std::string& i : items) s += (s.empty() ? "" : separator) + i;
  return s;
}

std::string Short(double value, int digits) {
  using namespace catalog_command;
  if (std::isinf(value)) return "inf";
  return fmt::format("{:.{}g}", value, digits);
}

std::string LinksText(const CatalogFeatures& f) {
  using namespace catalog_command;
  std::vector<std::string> parts;
  for (const auto& [degree, n] : f.links_by_degree) {
    if (n > 0) parts.push_back(std::to_string(n) + " " + DegreeName(degree));
  }
  return std::to_string(f.links) + " (" + Join(parts, ", ") + ")";
}

std::string JointsText(const CatalogFeatures& f) {
  using namespace catalog_command;
  std::vector<std::string> parts;
  for (const auto& [type, n] : f.joints_by_type) {
    if (n > 0) parts.push_back(std::to_string(n) + " " + type);
  }
  return std::to_string(f.joints) + " (" + Join(parts, ", ") + ")";
}

namespace catalog_command {  // this file's own names, apart from the other commands' in a unity build
namespace {

nlohmann::json FeaturesJson(const CatalogFeatures& f) {
  using namespace catalog_command;
  nlohmann::json by_degree = nlohmann::json::object(), by_type = nlohmann::json::object();
  for (const auto& [d, n] : f.links_by_degree) by_degree[DegreeName(d)] = n;
  for (const auto& [t, n] : f.joints_by_type) by_type[t] = n;
  return {{"drive_joints", f.drive_joints}, {"drive_joints_at_frame", f.drive_joints_at_frame},
          {"output_links", f.output_links}, {"output_links_at_frame", f.output_links_at_frame},
          {"links", f.links}, {"links_by_degree", by_degree}, {"joints", f.joints}, {"joints_by_type", by_type}};
}

void PrintEntries(const std::vector<CatalogHit>& entries, const CatalogArgs& args) {
  using namespace catalog_command;
  if (args.format == "json") {
    nlohmann::json j = nlohmann::json::array();
    for (const CatalogHit& e : entries) {
      j.push_back({{"id", e.id}, {"title_de", e.title_de}, {"title_en", e.title_en}, {"kind", e.kind},
                   {"classes", e.classes}, {"motion", e.motion}, {"file", e.path}, {"features", FeaturesJson(e.features)}});
    }
    WriteOutput(args.out, JsonText(j));
    return;
  }
  if (args.format == "csv") {
    std::string csv = "id,title_de,title_en,kind,drives,drives_at_frame,outputs,outputs_at_frame,links,binary,ternary,quaternary,joints,D,S,classes,motion\n";
    for (const CatalogHit& e : entries) {
      const CatalogFeatures& f = e.features;
      csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", CsvField(e.id), CsvField(e.title_de),
                         CsvField(e.title_en), e.kind, f.drive_joints, f.drive_joints_at_frame, f.output_links,
                         f.output_links_at_frame, f.links, Count(f.links_by_degree, 2), Count(f.links_by_degree, 3),
                         Count(f.links_by_degree, 4), f.joints, Count(f.joints_by_type, "D"), Count(f.joints_by_type, "S"),
                         CsvField(Join(e.classes, " ")), CsvField(e.motion));
    }
    WriteOutput(args.out, csv);
    return;
  }
  std::vector<std::vector<std::string>> rows = {{"id", "kind", "links", "joints D/S", "classes", "title"}};
  for (const CatalogHit& e : entries) {
    const CatalogFeatures& f = e.features;
    rows.push_back({e.id, e.kind, std::to_string(f.links),
                    std::to_string(Count(f.joints_by_type, "D")) + "/" + std::to_string(Count(f.joints_by_type, "S")),
                    Join(e.classes, " "), e.title_en});
  }
  WriteOutput(args.out, TextTable(rows) + fmt::format("{} entries\n", entries.size()));
}

std::optional<std::string> Given(const std::string& text) { return text.empty() ? std::nullopt : std::optional(text); }

// The flags as the API's query (koppel/api/catalog.hpp: FindInCatalog checks it).
CatalogQuery QueryOf(const CatalogArgs& args) {
  using namespace catalog_command;
  CatalogQuery q;
  q.links = Given(args.links);
  q.binary = Given(args.binary);
  q.ternary = Given(args.ternary);
  q.quaternary = Given(args.quaternary);
  q.joints = Given(args.joints);
  q.revolute = Given(args.revolute);
  q.prismatic = Given(args.prismatic);
  q.drives = Given(args.drives);
  q.drives_at_frame = Given(args.drives_at_frame);
  q.outputs = Given(args.outputs);
  q.outputs_at_frame = Given(args.outputs_at_frame);
  q.kind = args.kind;
  q.klass = args.klass;
  q.motion = args.motion;
  q.text = args.text;
  q.like = args.like;
  return q;
}

// A field of the query the API refused is named as the flag it came from; the --like mechanism's
// and the catalog's own diagnostics are printed as they are.
void RunFind(const CatalogArgs& args, bool all) {
  using namespace catalog_command;
  CheckCatalogFormat(args.format);
  std::vector<CatalogHit> hits;
  try {
    hits = FindInCatalog(all ? CatalogQuery{} : QueryOf(args), CatalogDirectoryOf(args));
  } catch (const InputError& e) {
    for (const Diagnostic& d : e.diagnostics()) {
      if (d.file != "catalog query") {
        std::cerr << d.ToString() << "\n";
        continue;
      }
      std::string flag = "--" + d.path;
      std::replace(flag.begin(), flag.end(), '_', '-');
      Complain(flag + ": " + d.message);
    }
    throw Exit{kExitBadInput};
  }
  PrintEntries(hits, args);
}

std::string ClassHelp() {
  using namespace catalog_command;
  std::string s = "Class (declared by the entry, or shown by its joint graph):";
  for (const CatalogTerm& c : CatalogClassTerms()) s += "\n  " + c.name + ": " + c.meaning;
  return s;
}

}  // namespace
}  // namespace catalog_command

// long: one flat list of the catalog command's subcommands and flags in the order --help shows them
void AddCatalogCommand(CLI::App& app) {
  using namespace catalog_command;
  auto args = std::make_shared<CatalogArgs>();
  CLI::App* cmd = app.add_subcommand(
      "catalog",
      "The catalog of documented mechanisms (catalog/entries/*.yaml, or --catalog DIR, or $KOPPEL_CATALOG).\n"
      "Entries are found by their access features (Zugriffsmerkmale), class, motion, title words or chain\n"
      "structure, and check themselves against their documents' equations and figures.");
  cmd->require_subcommand(1);
  auto common = [&](CLI::App* sub) {
    sub->add_option("--catalog", args->directory, "Catalog directory (default: the built-in one)");
    sub->add_option("--format", args->format, "table (default, for the terminal), csv or json");
    OutputFile(sub->add_option("-o,--output-file", args->out, "Write to this file instead of stdout"));
  };
  CLI::App* list = cmd->add_subcommand("list", "List every entry: id, kind, links, joints, classes, title.");
  common(list);
  list->callback([args] { RunFind(*args, true); });

  CLI::App* find = cmd->add_subcommand(
      "find",
      "Find entries. Each count is a number (4) or a range (4..6, ..6, 4..); all given criteria must match.\n"
      "Examples: koppel catalog find --links 6 --ternary 2 --revolute 4 --prismatic 3 --drives-at-frame 1\n"
      "          koppel catalog find --class quick-return --motion 'rotation -> translation'\n"
      "          koppel catalog find --like tests/data/kite.yaml   # entries with an isomorphic kinematic chain");
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
  find->add_option("--class", args->klass, ClassHelp());
  find->add_option("--motion", args->motion,
                   "Motion, 'INPUT -> OUTPUT', each side a part of the entry's (e.g. 'rotation -> oscillating translation');\n"
                   "one word alone matches either side");
  find->add_option("--text,--keyword", args->text, "Words in the id, the titles (German or English), the classes, keywords, motion or\n"
                                                    "applications, every word somewhere; case, hyphens, spaces and umlauts ignored ('straight\n"
                                                    "line' finds straight-line), German and English names of one thing alike ('Rast' finds\n"
                                                    "dwell, 'Eilrücklauf' quick-return); the best matches first");
  find->add_option("--like", args->like, "A mechanism file: entries whose kinematic chain is isomorphic to its own\n"
                                         "(joint types respected, the frame marked)");
  find->callback([args] { RunFind(*args, false); });

  CLI::App* show = cmd->add_subcommand(
      "show", "An entry as a page: titles, kind, classes, features, structure, dimensions, equations and figures\n"
              "with their check status, literature. --format html adds its kinematic scheme and the plots of its\n"
              "outputs (write it with -o page.html); json gives the same as data.");
  common(show);
  show->add_option("id", args->ids, "Entry id")->required()->expected(1);
  show->callback([args] { RunShow(*args); });

  CLI::App* page = cmd->add_subcommand(
      "page", "Every entry on one HTML page that opens offline: its kinematic scheme, titles, classes and motion, and a\n"
              "search box that finds and ranks entries as find --text does (the same search, compiled into the page).\n"
              "Example: koppel catalog page -o catalog.html");
  page->add_option("--catalog", args->directory, "Catalog directory (default: the built-in one)");
  OutputFile(page->add_option("-o,--output-file", args->out, "Write the page to this file instead of stdout"));
  page->callback([args] { RunCatalogPage(*args); });

  std::string quantities = "Figure quantities a card may use:";
  for (const CatalogTerm& q : FigureQuantityTerms()) quantities += "\n  " + q.name + ": " + q.meaning;
  CLI::App* check = cmd->add_subcommand(
      "check",
      "Recompute every check of the given entries (default: all) with the generic solver: access features and\n"
      "classes from the joint graph, the document's equations over a sweep, its figures. Prints one line per\n"
      "entry (checks passed, worst deviation relative to its tolerance) and a summary; --verbose or --format csv\n"
      "give every check. Exit code 1 if any check fails.\n" + quantities);
  common(check);
  check->add_flag("-v,--verbose", args->verbose, "Every check, not only one line per entry");
  check->add_option("ids", args->ids, "Entry ids (default: all)");
  check->callback([args] { RunCheck(*args); });
}

}  // namespace koppel::cli

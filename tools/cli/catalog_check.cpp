// koppel catalog check: one line per entry and a summary (the report a person reads), every
// check with --verbose, CSV or JSON for machines.
#include "catalog_command.hpp"
#include "common.hpp"

#include <fmt/core.h>

#include <chrono>
#include <iostream>

namespace koppel::cli {
namespace catalog_check {  // this file's own names, apart from the other commands' in a unity build
namespace {

std::string Status(const CheckOutcome& c) { return ToString(c.status); }

std::string ValueText(const CheckOutcome& c) {
  if (c.kind == CheckKind::kFigure && c.status != CheckStatus::kNotComputed) return FormatNumber(c.value);
  if (c.kind == CheckKind::kEquation && c.status != CheckStatus::kNotComputed) return "at " + FormatNumber(c.where);
  return "";
}

std::string Csv(const std::vector<EntryReport>& reports) {
  std::string csv = "id,variant,kind,check,status,worst,tolerance,value,at,detail\n";
  for (const EntryReport& r : reports) {
    for (const CheckOutcome& c : r.checks) {
      const bool computed = c.status != CheckStatus::kNotComputed;
      csv += fmt::format("{},{},{},{},{},{:.3g},{:.3g},{},{},{}\n", r.id, CsvField(c.variant), ToString(c.kind), CsvField(c.name),
                         Status(c), c.worst, c.tolerance, c.kind == CheckKind::kFigure && computed ? FormatNumber(c.value) : "",
                         c.kind == CheckKind::kEquation && computed ? FormatNumber(c.where) : "",
                         CsvField(c.passed() ? "" : c.detail));
    }
  }
  return csv;
}

std::string Json(const std::vector<EntryReport>& reports) {
  nlohmann::json j = nlohmann::json::array();
  for (const EntryReport& r : reports) {
    nlohmann::json checks = nlohmann::json::array();
    for (const CheckOutcome& c : r.checks) {
      checks.push_back({{"variant", c.variant}, {"name", c.name}, {"kind", ToString(c.kind)}, {"worst", c.worst},
                        {"tolerance", c.tolerance}, {"value", c.value}, {"where", c.where}, {"status", Status(c)},
                        {"detail", c.detail}});
    }
    j.push_back({{"id", r.id}, {"passed", r.passed()}, {"checks", checks}});
  }
  return j.dump(1) + "\n";
}

// One line per entry; under a failed entry, its failed checks.
std::string Lines(const std::vector<EntryReport>& reports, bool verbose) {
  std::vector<std::vector<std::string>> rows = {{"id", "result", "checks", "worst/tol", "worst check"}};
  std::string failures;
  for (const EntryReport& r : reports) {
    const CheckOutcome* w = r.Worst();
    const int passed = r.Count(CheckStatus::kPassed);
    rows.push_back({r.id, r.passed() ? "passed" : "FAILED", fmt::format("{}/{}", passed, r.checks.size()), w ? Short(w->Ratio(), 2) : "",
                    w ? w->name + (w->variant.empty() ? "" : " [" + w->variant + "]") : ""});
    for (const CheckOutcome& c : r.checks) {
      if (c.passed() && !verbose) continue;
      failures += fmt::format("  {} {} {} '{}'{}: worst {} tol {} {}{}\n", r.id, Status(c), ToString(c.kind), c.name,
                              c.variant.empty() ? "" : " [" + c.variant + "]", Short(c.worst, 4), Short(c.tolerance, 3), ValueText(c),
                              c.passed() || c.detail.empty() ? "" : " — " + c.detail);
    }
  }
  return TextTable(rows) + (failures.empty() ? "" : "\n" + failures);
}

}  // namespace
}  // namespace catalog_check

void RunCheck(const CatalogArgs& args) {
  using namespace catalog_check;
  CheckCatalogFormat(args.format);
  const auto start = std::chrono::steady_clock::now();
  const Catalog catalog = LoadCatalog(args);
  std::vector<const CatalogEntry*> entries;
  if (args.ids.empty()) {
    for (const CatalogEntry& e : catalog.entries()) entries.push_back(&e);
  } else {
    for (const std::string& id : args.ids) entries.push_back(&FindOrFail(catalog, id, CatalogDirectoryOf(args)));
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
  int failed_entries = 0, checks = 0, failed_checks = 0;
  for (const EntryReport& r : reports) {
    failed_entries += !r.passed();
    checks += static_cast<int>(r.checks.size());
    failed_checks += static_cast<int>(r.checks.size()) - r.Count(CheckStatus::kPassed);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string summary = fmt::format("koppel catalog check: {} entries, {} passed, {} failed; {} checks, {} failed; {:.1f} s\n",
                                          reports.size(), reports.size() - failed_entries, failed_entries, checks, failed_checks, seconds);
  if (args.format == "csv") {
    WriteOutput(args.out, Csv(reports));
    std::cerr << summary;
  } else if (args.format == "json") {
    WriteOutput(args.out, Json(reports));
    std::cerr << summary;
  } else {
    WriteOutput(args.out, Lines(reports, args.verbose) + summary);
  }
  if (failed_entries > 0) throw Exit{kExitFailed};
}

}  // namespace koppel::cli

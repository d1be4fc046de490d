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

std::string ValueText(const CatalogCheck& c) {
  if (c.kind == CatalogCheckKind::kFigure && c.computed()) return FormatNumber(c.value);
  if (c.kind == CatalogCheckKind::kEquation && c.computed()) return "at " + FormatNumber(c.where);
  return "";
}

std::string Csv(const std::vector<CatalogCheckReport>& reports) {
  std::string csv = "id,variant,kind,check,status,worst,tolerance,value,at,detail\n";
  for (const CatalogCheckReport& r : reports) {
    for (const CatalogCheck& c : r.checks) {
      csv += fmt::format("{},{},{},{},{},{:.3g},{:.3g},{},{},{}\n", r.id, CsvField(c.variant), ToString(c.kind), CsvField(c.name),
                         ToString(c.status), c.worst, c.tolerance, c.kind == CatalogCheckKind::kFigure && c.computed() ? FormatNumber(c.value) : "",
                         c.kind == CatalogCheckKind::kEquation && c.computed() ? FormatNumber(c.where) : "",
                         CsvField(c.passed() ? "" : c.detail));
    }
  }
  return csv;
}

std::string Json(const std::vector<CatalogCheckReport>& reports) {
  nlohmann::json j = nlohmann::json::array();
  for (const CatalogCheckReport& r : reports) {
    nlohmann::json checks = nlohmann::json::array();
    for (const CatalogCheck& c : r.checks) {
      checks.push_back({{"variant", c.variant}, {"name", c.name}, {"kind", ToString(c.kind)}, {"worst", c.worst},
                        {"tolerance", c.tolerance}, {"value", c.value}, {"where", c.where}, {"status", ToString(c.status)},
                        {"detail", c.detail}});
    }
    j.push_back({{"id", r.id}, {"passed", r.passed}, {"checks", checks}});
  }
  return j.dump(1) + "\n";
}

// One line per entry; under a failed entry, its failed checks.
std::string Lines(const std::vector<CatalogCheckReport>& reports, bool verbose) {
  std::vector<std::vector<std::string>> rows = {{"id", "result", "checks", "worst/tol", "worst check"}};
  std::string failures;
  for (const CatalogCheckReport& r : reports) {
    const CatalogCheck* w = r.worst >= 0 ? &r.checks[r.worst] : nullptr;
    rows.push_back({r.id, r.passed ? "passed" : "FAILED", fmt::format("{}/{}", r.passed_checks, r.checks.size()), w ? Short(w->ratio, 2) : "",
                    w ? w->name + (w->variant.empty() ? "" : " [" + w->variant + "]") : ""});
    for (const CatalogCheck& c : r.checks) {
      if (c.passed() && !verbose) continue;
      failures += fmt::format("  {} {} {} '{}'{}: worst {} tol {} {}{}\n", r.id, ToString(c.status), ToString(c.kind), c.name,
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
  CatalogChecks checked;
  try {
    checked = CheckCatalog(args.ids, CatalogDirectoryOf(args));
  } catch (const InputError& error) {
    FailWithDiagnostics(error);
  }
  RefuseUnknownId(checked.refused);
  const std::vector<CatalogCheckReport>& reports = checked.reports;
  int failed_entries = 0, checks = 0, failed_checks = 0;
  for (const CatalogCheckReport& r : reports) {
    failed_entries += !r.passed;
    checks += static_cast<int>(r.checks.size());
    failed_checks += static_cast<int>(r.checks.size()) - r.passed_checks;
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

// What the `koppel catalog` subcommands share: their arguments, loading the catalog, and the
// text helpers of their terminal output. list/find live in catalog_command.cpp, show in
// catalog_show.cpp, check in catalog_check.cpp.
#pragma once

#include "koppel/api/catalog.hpp"
#include "koppel/api/catalog_check.hpp"
#include "koppel/core/diagnostic.hpp"

#include <string>
#include <vector>

namespace koppel::cli {

struct CatalogArgs {
  std::string directory;
  std::string format = "table";
  std::string out;
  bool verbose = false;
  // find
  std::string links, binary, ternary, quaternary, joints, revolute, prismatic;
  std::string drives, drives_at_frame, outputs, outputs_at_frame;
  std::string kind, klass, motion, text, like;
  // show / check
  std::vector<std::string> ids;
};

// --format: table (the terminal's), csv or json (show also html). Exit{2} otherwise.
void CheckCatalogFormat(const std::string& format);

std::string CatalogDirectoryOf(const CatalogArgs& args);  // --catalog, or the built-in one
// An unreadable catalog or card (the API's InputError): its diagnostics on stderr, Exit{2}.
[[noreturn]] void FailWithDiagnostics(const InputError& error);
// An id the catalog lacks (the API's `refused`, "did you mean" the nearest id): Exit{2} with that
// one line. Nothing when `refused` is empty.
void RefuseUnknownId(const std::string& refused);

// Rows of text as columns padded to their widest cell (UTF-8 aware), two spaces apart.
// A cell's control characters are written as U+FFFD (koppel/core/printable_text.hpp): the
// table goes to a terminal. CSV cells: CsvField (common.hpp).
std::string TextTable(const std::vector<std::vector<std::string>>& rows);
// "4 (4 binary)", "7 (4 D, 3 S)"
std::string LinksText(const CatalogFeatures& features);
std::string JointsText(const CatalogFeatures& features);
std::string Join(const std::vector<std::string>& items, const std::string& separator);
// A number with `digits` significant digits, "inf" for infinity.
std::string Short(double value, int digits = 3);

void RunShow(const CatalogArgs& args);
// The entry's page as HTML: its scheme and the plots of its outputs above `text_page`; what
// could not be drawn goes to *problems (and onto the page).
std::string EntryHtml(const CatalogPage& page, const std::string& text_page, std::vector<std::string>* problems);
void RunCheck(const CatalogArgs& args);
void RunCatalogPage(const CatalogArgs& args);

}  // namespace koppel::cli

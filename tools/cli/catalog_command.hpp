// What the `koppel catalog` subcommands share: their arguments, loading the catalog, and the
// text helpers of their terminal output. list/find live in catalog_command.cpp, show in
// catalog_show.cpp, check in catalog_check.cpp.
#pragma once

#include "koppel/catalog/catalog.hpp"
#include "koppel/catalog/check.hpp"

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

// Loads the catalog of --catalog (default: the built-in one); Exit{2} with the diagnostics.
Catalog LoadCatalog(const CatalogArgs& args);
std::string CatalogDirectoryOf(const CatalogArgs& args);  // --catalog, or the built-in one
// The entry `id`; Exit{2} with one line, "did you mean" the nearest id (UnknownCatalogId).
const CatalogEntry& FindOrFail(const Catalog& catalog, const std::string& id, const std::string& directory);

// Rows of text as columns padded to their widest cell (UTF-8 aware), two spaces apart.
std::string TextTable(const std::vector<std::vector<std::string>>& rows);
std::string CsvField(const std::string& text);
// "4 (4 binary)", "7 (4 D, 3 S)"
std::string LinksText(const AccessFeatures& features);
std::string JointsText(const AccessFeatures& features);
std::string Join(const std::vector<std::string>& items, const std::string& separator);
// A number with `digits` significant digits, "inf" for infinity.
std::string Short(double value, int digits = 3);

void RunShow(const CatalogArgs& args);
// The entry's page as HTML: its scheme and the plots of its outputs above `text_page`; what
// could not be drawn goes to *problems (and onto the page).
std::string EntryHtml(const CatalogEntry& entry, const std::string& text_page, std::vector<std::string>* problems);
void RunCheck(const CatalogArgs& args);

}  // namespace koppel::cli

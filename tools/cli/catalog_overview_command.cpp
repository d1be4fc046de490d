// koppel catalog page: every entry of the catalog on one offline HTML page, with its scheme and a
// search box that finds what `catalog find --text` finds (koppel/plot/catalog_overview.hpp).
#include "catalog_command.hpp"
#include "common.hpp"

#include "koppel/plot/catalog_overview.hpp"

namespace koppel::cli {

void RunCatalogPage(const CatalogArgs& args) {
  std::vector<CatalogHit> hits;
  try {
    hits = FindInCatalog(CatalogQuery{}, CatalogDirectoryOf(args));
  } catch (const InputError& error) {
    FailWithDiagnostics(error);
  }
  const plot::CatalogOverview page = plot::CatalogOverviewPage(hits);
  WriteOutput(args.out, page.html);
  for (const std::string& problem : page.problems) Complain(problem);
  if (!plot::CatalogSearchAvailable())
    Complain("this koppel was built without em++ (Debian's emscripten): the page has no search box");
  // every entry drawn and the search box working, or the exit code says what is missing
  if (!page.problems.empty() || !plot::CatalogSearchAvailable()) throw Exit{kExitFailed};
}

}  // namespace koppel::cli

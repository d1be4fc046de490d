// The page of `koppel catalog page`: every catalog entry as a card with its kinematic scheme
// (drawn by scheme_drawing.hpp from the entry's Model, at its assembly's input, over its sweep),
// titles, classes and motion, and a search box that scores the entries with the catalog
// library's own search compiled to WebAssembly (tools/catalog_page): one self-contained HTML file
// that opens offline.
#pragma once

#include "koppel/api/catalog.hpp"
#include <string>
#include <vector>

namespace koppel::plot {

// True when this build has the search box's module (em++ was found when koppel was built).
bool CatalogSearchAvailable();

struct CatalogOverview {
  std::string html;
  // what could not be drawn, one line per entry ("ID: why"); its card says so on the page too
  std::vector<std::string> problems;
};

CatalogOverview CatalogOverviewPage(const std::vector<CatalogHit>& entries);

}  // namespace koppel::plot

// CatalogOverviewPage (tools/plot/src/catalog_overview.cpp): every hit a card with its scheme, the
// search fields handed to the page as JSON that reads back to the API's fields (the reference:
// CatalogHit::search_fields, which `catalog find --text` scores), a field holding markup unable to
// close the page's script element, and a hit whose file cannot be read named as a problem and on
// its card. (The page in a browser, its search against the CLI's: tests/tools/catalog_page.)
#include "koppel/plot/catalog_overview.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace koppel::catalog_overview_test {
namespace {

// the JSON inside <script type="application/json" id="search-fields">
nlohmann::json FieldsOf(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"search-fields\">";
  const size_t from = html.find(open);
  REQUIRE(from != std::string::npos);
  const size_t to = html.find("</script>", from);
  REQUIRE(to != std::string::npos);
  return nlohmann::json::parse(html.substr(from + open.size(), to - from - open.size()));
}

}  // namespace

TEST_CASE("the catalog page: a card and a scheme per entry, the search fields as the API gives them", "[plot][catalog-page]") {
  CatalogQuery query;
  query.text = "slider crank";
  std::vector<CatalogHit> hits = FindInCatalog(query);
  REQUIRE(hits.size() >= 3);
  hits.resize(3);
  // a hostile field: text that would end the script element and a tab the module splits fields by
  hits[1].search_fields.emplace_back("</script><script>alert(1)</script>\tx", 3);
  CatalogHit missing = hits[0];
  missing.id = "missing-entry";
  missing.path = "/nonexistent/missing-entry.yaml";
  hits.push_back(missing);

  const plot::CatalogOverview page = plot::CatalogOverviewPage(hits);
  for (size_t i = 0; i < 3; ++i) {
    INFO(hits[i].id);
    const size_t card = page.html.find("<section class=\"entry\" id=\"" + hits[i].id + "\">");
    REQUIRE(card != std::string::npos);
    CHECK(page.html.find("<svg", card) < page.html.find("</section>", card));
  }
  REQUIRE(page.problems.size() == 1);
  CHECK_THAT(page.problems[0], Catch::StartsWith("missing-entry: "));
  const size_t missing_card = page.html.find("id=\"missing-entry\"");
  REQUIRE(missing_card != std::string::npos);
  CHECK(page.html.find("No scheme: ", missing_card) < page.html.find("</section>", missing_card));

  const nlohmann::json fields = FieldsOf(page.html);
  REQUIRE(fields.size() == hits.size());
  for (size_t i = 0; i < hits.size(); ++i) {
    REQUIRE(fields[i].size() == hits[i].search_fields.size());
    for (size_t k = 0; k < fields[i].size(); ++k) {
      std::string text = hits[i].search_fields[k].first;
      for (char& c : text) c = c == '\t' ? ' ' : c;
      CHECK(fields[i][k][0].get<std::string>() == text);
      CHECK(fields[i][k][1].get<int>() == hits[i].search_fields[k].second);
    }
  }
  // the JSON above read back whole from the opener to the first "</script>": the field closed nothing
  CHECK(page.html.find("</script><script>alert(1)") == std::string::npos);
}

}  // namespace koppel::catalog_overview_test

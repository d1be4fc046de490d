// The catalog's checks and pages as the API gives them (tools/api/src/catalog_check.cpp).
// References: each report's counts and worst check recomputed here from its own checks; the
// slider-crank's mobility by hand (Grübler: 3 (4 - 1) - 2 * 4 = 1); its features counted again
// from the mechanism the page carries; its card as written (catalog/entries/slider-crank-offset.yaml:
// the Abtrieb s, its sweep 0 .. 360 by 1, the offset e = 0.8).
#include "koppel/api/catalog_check.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace koppel;

TEST_CASE("CheckCatalog: a report's counts and its worst check agree with its checks", "[api][catalog]") {
  const CatalogChecks checked = CheckCatalog({"slider-crank-offset", "mzc-crank-rocker"}, KOPPEL_CATALOG_DIR);
  CHECK(checked.refused.empty());
  REQUIRE(checked.reports.size() == 2);
  CHECK(checked.reports[0].id == "slider-crank-offset");
  for (const CatalogCheckReport& r : checked.reports) {
    INFO(r.id);
    REQUIRE(!r.checks.empty());
    const auto passed = std::count_if(r.checks.begin(), r.checks.end(), [](const CatalogCheck& c) { return c.passed(); });
    CHECK(r.passed_checks == passed);
    CHECK(r.passed == (passed == static_cast<long>(r.checks.size())));
    REQUIRE(r.worst >= 0);
    for (const CatalogCheck& c : r.checks) {
      CHECK(c.ratio <= r.checks[r.worst].ratio);
      CHECK(std::string(ToString(c.status)) == (c.passed() ? "pass" : c.computed() ? "FAIL" : "not computed"));
      if (c.passed()) CHECK(c.ratio <= 1);
    }
    CHECK(r.brief.rfind(r.id, 0) == 0);
  }
}

TEST_CASE("CheckCatalog and ShowCatalogEntry refuse an unknown id with the nearest one", "[api][catalog]") {
  const CatalogChecks checked = CheckCatalog({"slider-crank-offset", "slider-crank-ofset"}, KOPPEL_CATALOG_DIR);
  CHECK(checked.reports.empty());
  CHECK(checked.refused.find("did you mean 'slider-crank-offset'") != std::string::npos);
  const CatalogPage page = ShowCatalogEntry("slider-crank-ofset", KOPPEL_CATALOG_DIR);
  CHECK(page.refused == checked.refused);
  CHECK(page.report.checks.empty());
}

TEST_CASE("ShowCatalogEntry: the slider-crank's page against its card and its mechanism", "[api][catalog]") {
  const CatalogPage page = ShowCatalogEntry("slider-crank-offset", KOPPEL_CATALOG_DIR);
  REQUIRE(page.refused.empty());
  CHECK(page.entry.id == "slider-crank-offset");
  CHECK(page.gruebler_mobility == 1);
  const Mechanism& m = page.mechanism;
  const auto prismatic = std::count_if(m.joints.begin(), m.joints.end(), [](const Joint& j) { return j.type == JointType::kPrismatic; });
  CHECK(page.entry.features.links == static_cast<int>(m.links.size()));
  CHECK(page.entry.features.joints == static_cast<int>(m.joints.size()));
  CHECK(page.entry.features.joints_by_type.at("S") == prismatic);
  CHECK(page.outputs == std::vector<std::string>{"s"});
  REQUIRE(page.output_links.size() == 1);
  CHECK(page.output_links[0].first == "s");
  CHECK(page.input_is_angle);
  CHECK(page.input_name == "phi");
  CHECK(page.from == 0);
  CHECK(page.to == 360);
  CHECK(page.step == 1);
  const auto e = std::find_if(page.parameters.begin(), page.parameters.end(), [](const auto& p) { return p.first == "e"; });
  REQUIRE(e != page.parameters.end());
  CHECK(e->second == 0.8);
  REQUIRE(!page.equations.empty());
  for (const CatalogEquation& q : page.equations) CHECK(q.output_shown == q.output);  // scalar outputs: no component
  CHECK(page.report.passed);
}

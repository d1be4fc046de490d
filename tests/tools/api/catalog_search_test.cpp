// FindInCatalog (tools/api/src/catalog_search.cpp): the hits of a query, checked against the
// mechanisms the hits load (their joints counted independently).
#include "koppel/api/catalog.hpp"
#include "catalog_query.hpp"

#include "koppel/catalog/classes.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace koppel;

TEST_CASE("FindInCatalog: four links with one prismatic joint, counted again from each mechanism", "[api]") {
  CatalogQuery q;
  q.links = "4";
  q.prismatic = "1";
  const std::vector<CatalogHit> hits = FindInCatalog(q, KOPPEL_CATALOG_DIR);
  REQUIRE(!hits.empty());
  bool offset = false;
  for (const CatalogHit& h : hits) {
    offset = offset || h.id == "slider-crank-offset";
    const Model m = h.Load();
    const Mechanism& mech = m.mechanism();
    CHECK(mech.links.size() == 4);
    CHECK(std::count_if(mech.joints.begin(), mech.joints.end(), [](const Joint& j) { return j.type == JointType::kPrismatic; }) == 1);
  }
  CHECK(offset);
  q.links = "four";
  CHECK_THROWS_AS(FindInCatalog(q, KOPPEL_CATALOG_DIR), InputError);
}

TEST_CASE("ToFeatureQuery: the one rule that turns a query's text into the catalog's query", "[api]") {
  // references: the catalog's own class list (CatalogClasses), the five-bar's hand count
  // (3 (5 - 1) - 2 * 5 = 2 with 1 drive), the crank-rocker entry's chain (a four-bar)
  CatalogQuery q;
  q.drives_at_frame = "1";
  q.outputs_at_frame = "0..1";
  q.klass = CatalogClasses().front().name;
  q.like = "crank-rocker";
  const FeatureQuery f = ToFeatureQuery(q);
  REQUIRE(f.drives_at_frame.has_value());
  REQUIRE(f.outputs_at_frame.has_value());
  REQUIRE(f.like.has_value());
  CHECK(f.like->links.size() == 4);
  CHECK(f.klass == q.klass);

  auto field_refused = [](const CatalogQuery& bad) {
    try {
      (void)ToFeatureQuery(bad);
    } catch (const InputError& e) {
      return e.diagnostics().front().path;
    }
    return std::string("admitted");
  };
  CatalogQuery bad_count;
  bad_count.drives_at_frame = "one";
  CHECK(field_refused(bad_count) == "drives_at_frame");
  CatalogQuery bad_class;
  bad_class.klass = "crank-roker";
  CHECK(field_refused(bad_class) == "class");
  CatalogQuery mobility_two;
  mobility_two.like = test::TestDataPath("five-bar.yaml");
  CHECK(field_refused(mobility_two) == "drive");
}

TEST_CASE("FindInCatalog: a hit's features agree with its counts and its mechanism; the vocabulary", "[api]") {
  // references: the mechanism each hit loads (links and joints counted here), the sums of the
  // by-degree and by-type counts, the class list's own entry for slider-crank
  const std::vector<CatalogHit> hits = FindInCatalog(CatalogQuery{}, KOPPEL_CATALOG_DIR);
  REQUIRE(!hits.empty());
  for (const CatalogHit& h : hits) {
    INFO(h.id);
    const Mechanism mech = h.Load().mechanism();
    CHECK(h.features.links == static_cast<int>(mech.links.size()));
    CHECK(h.features.joints == static_cast<int>(mech.joints.size()));
    int by_degree = 0, by_type = 0;
    for (const auto& [degree, n] : h.features.links_by_degree) by_degree += n;
    for (const auto& [type, n] : h.features.joints_by_type) by_type += n;
    CHECK(by_degree == h.features.links);  // every link has a degree
    CHECK(by_type == h.features.joints);
    const auto d = h.features.joints_by_type.find("D");
    CHECK((d == h.features.joints_by_type.end() ? 0 : d->second) == h.revolute);
  }
  const std::vector<CatalogTerm> classes = CatalogClassTerms();
  CHECK(std::any_of(classes.begin(), classes.end(), [](const CatalogTerm& t) { return t.name == "slider-crank" && !t.meaning.empty(); }));
  CHECK(!FigureQuantityTerms().empty());
}

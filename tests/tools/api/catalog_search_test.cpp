// FindInCatalog (tools/api/src/catalog_search.cpp): the hits of a query, checked against the
// mechanisms the hits load (their joints counted independently).
#include "koppel/api/catalog.hpp"

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

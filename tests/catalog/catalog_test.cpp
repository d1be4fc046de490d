// Catalog lookup by access features: every query is answered against the real catalog, and the
// expected ids follow from the seed documents' Zugriffsmerkmale (seeds 000, 001, 003).
#include "koppel/catalog/catalog.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>

namespace koppel {
namespace {

std::vector<std::string> Ids(const Catalog& catalog, const FeatureQuery& q) {
  std::vector<std::string> ids;
  for (const CatalogEntry* e : FindEntries(catalog, q)) ids.push_back(e->file.id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

using Ids_t = std::vector<std::string>;

}  // namespace

TEST_CASE("count ranges parse numbers, closed and open ranges, and reject junk", "[catalog]") {
  CHECK(CountRange::Parse("4")->Contains(4));
  CHECK_FALSE(CountRange::Parse("4")->Contains(5));
  const auto r = CountRange::Parse("4..6");
  REQUIRE(r);
  CHECK(r->Contains(4));
  CHECK(r->Contains(6));
  CHECK_FALSE(r->Contains(7));
  CHECK(CountRange::Parse("..3")->Contains(0));
  CHECK(CountRange::Parse("5..")->Contains(500));
  CHECK_FALSE(CountRange::Parse("six"));
  CHECK_FALSE(CountRange::Parse("6..4"));
  CHECK_FALSE(CountRange::Parse(".."));
  CHECK_FALSE(CountRange::Parse("-1"));
}

TEST_CASE("catalog lookup by each access feature returns exactly the documented entries", "[catalog]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  const auto all = Ids(catalog, {});
  REQUIRE(std::find(all.begin(), all.end(), "proportional-linkage") != all.end());
  REQUIRE(std::find(all.begin(), all.end(), "slider-crank-offset") != all.end());
  REQUIRE(std::find(all.begin(), all.end(), "mzc-crank-rocker") != all.end());

  FeatureQuery q;
  // the example: six links, two ternary, 4 D, 3 S, one drive at the frame -> seed 001
  q.links = CountRange::Parse("6");
  q.ternary = CountRange::Parse("2");
  q.revolute = CountRange::Parse("4");
  q.prismatic = CountRange::Parse("3");
  q.drives_at_frame = CountRange::Parse("1");
  CHECK(Ids(catalog, q) == Ids_t{"proportional-linkage"});

  FeatureQuery prismatic_one;
  prismatic_one.prismatic = CountRange::Parse("1");
  for (const std::string& id : Ids(catalog, prismatic_one)) CHECK(id.find("slider-crank") != std::string::npos);

  FeatureQuery no_prismatic;
  no_prismatic.prismatic = CountRange::Parse("0");
  const auto four_bars = Ids(catalog, no_prismatic);
  CHECK(std::find(four_bars.begin(), four_bars.end(), "mzc-crank-rocker") != four_bars.end());
  CHECK(std::find(four_bars.begin(), four_bars.end(), "slider-crank-offset") == four_bars.end());

  // output link not at the frame: only the coupler-point guidance mechanism of seed 003
  FeatureQuery coupler_output;
  coupler_output.outputs_at_frame = CountRange::Parse("0");
  CHECK(Ids(catalog, coupler_output) == Ids_t{"mzc-crank-rocker"});

  FeatureQuery guidance;
  guidance.kind = "guidance";
  CHECK(Ids(catalog, guidance) == Ids_t{"mzc-crank-rocker"});

  FeatureQuery text;
  text.text = "PROPORTIONAL";
  CHECK(Ids(catalog, text) == Ids_t{"proportional-linkage"});
  text.text = "Versetzung";  // German title
  CHECK(Ids(catalog, text) == Ids_t{"slider-crank-offset"});
}

TEST_CASE("every access feature filters on its own", "[catalog]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  // for each feature: a value only the proportional linkage (seed 001) has, and one it lacks
  struct Case {
    std::optional<CountRange> FeatureQuery::*field;
    const char* only_seed_001;
    const char* not_seed_001;
  };
  const Case cases[] = {{&FeatureQuery::links, "6", "4"},    {&FeatureQuery::binary, "4", "0"}, {&FeatureQuery::ternary, "2", "0"},
                        {&FeatureQuery::joints, "7", "4"},   {&FeatureQuery::revolute, "4", "3"}, {&FeatureQuery::prismatic, "3", "1"}};
  for (const Case& c : cases) {
    FeatureQuery q;
    q.*(c.field) = CountRange::Parse(c.only_seed_001);
    const auto ids = Ids(catalog, q);
    INFO(c.only_seed_001);
    CHECK(std::find(ids.begin(), ids.end(), "proportional-linkage") != ids.end());
    q.*(c.field) = CountRange::Parse(c.not_seed_001);
    const auto other = Ids(catalog, q);
    CHECK(std::find(other.begin(), other.end(), "proportional-linkage") == other.end());
  }
  // drives, outputs, quaternary: every entry has one drive at the frame, none a quaternary link
  FeatureQuery drives;
  drives.drives = CountRange::Parse("1");
  drives.drives_at_frame = CountRange::Parse("1");
  drives.outputs = CountRange::Parse("1");
  CHECK(Ids(catalog, drives).size() == catalog.entries().size());
  FeatureQuery quaternary;
  quaternary.quaternary = CountRange::Parse("1..");
  CHECK(Ids(catalog, quaternary).empty());
  FeatureQuery two_drives;
  two_drives.drives = CountRange::Parse("2");
  CHECK(Ids(catalog, two_drives).empty());
}

TEST_CASE("catalog lookup by ranges", "[catalog]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  FeatureQuery q;
  q.links = CountRange::Parse("5..6");
  CHECK(Ids(catalog, q) == Ids_t{"proportional-linkage"});
  q.links = CountRange::Parse("..4");
  const auto small = Ids(catalog, q);
  CHECK(std::find(small.begin(), small.end(), "proportional-linkage") == small.end());
  CHECK(std::find(small.begin(), small.end(), "mzc-crank-rocker") != small.end());
  q.links = CountRange::Parse("7..");
  CHECK(Ids(catalog, q).empty());
  FeatureQuery joints;
  joints.joints = CountRange::Parse("7..7");
  joints.binary = CountRange::Parse("4");
  CHECK(Ids(catalog, joints) == Ids_t{"proportional-linkage"});
}

TEST_CASE("a catalog directory with a bad entry reports it and does not load", "[catalog]") {
  CHECK_THROWS_AS(Catalog::Load("/nonexistent/koppel/catalog"), InputError);
}

}  // namespace koppel

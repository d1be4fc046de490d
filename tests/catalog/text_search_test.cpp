// The catalog's free-text search (catalog/src/text_search.cpp): folding, the synonym table, the
// rank; and over the real catalog, every word of the catalog's search list, English and German,
// finds the entries it should. The references are the entries' own declared classes and ids, and
// for "inversion" the kinematic chain (SameKinematicChain with the slider-crank).
#include "koppel/catalog/text_search.hpp"

#include "koppel/catalog/catalog.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

namespace koppel::text_search_test {
namespace {

std::set<std::string> Found(const Catalog& catalog, const std::string& text) {
  FeatureQuery q;
  q.text = text;
  std::set<std::string> ids;
  for (const CatalogEntry* e : FindEntries(catalog, q)) ids.insert(e->file.id);
  return ids;
}

std::set<std::string> WithClass(const Catalog& catalog, const std::string& prefix) {
  std::set<std::string> ids;
  for (const CatalogEntry& e : catalog.entries())
    for (const std::string& c : e.classes)
      if (c.rfind(prefix, 0) == 0) ids.insert(e.file.id);
  return ids;
}

bool Holds(const std::set<std::string>& found, const std::set<std::string>& expected) {
  return std::includes(found.begin(), found.end(), expected.begin(), expected.end());
}

}  // namespace

TEST_CASE("FoldForSearch: case, punctuation, umlauts and their ae/oe/ue spelling are one", "[catalog][search]") {
  CHECK(FoldForSearch("Geradführung") == FoldForSearch("Geradfuehrung"));
  CHECK(FoldForSearch("Geradführung") == FoldForSearch("GERADFUHRUNG"));
  CHECK(FoldForSearch("Eilrücklauf") == "eilrucklauf");
  CHECK(FoldForSearch("Stoßmaschine") == "stossmaschine");
  CHECK(FoldForSearch("Übertragungswinkel") == FoldForSearch("uebertragungswinkel"));
  CHECK(FoldForSearch("straight-line, (approximate)") == "straightlineapproximate");
  CHECK(FoldForSearch("Öl") == "ol");
}

TEST_CASE("SearchScore: every word somewhere, synonyms found, heavier fields rank higher", "[catalog][search]") {
  const std::vector<SearchField> entry = {{"toggle-press", 4}, {"dwell", 3}, {"Prägepressen (coining presses)", 1}};
  CHECK(SearchScore(entry, "") == 1);
  CHECK(SearchScore(entry, "Rast") == 3);            // the class dwell, by its German name
  CHECK(SearchScore(entry, "Kniehebel") == 4);       // toggle, in the id
  CHECK(SearchScore(entry, "Kniehebel Rast") == 7);  // both words
  CHECK(SearchScore(entry, "Kniehebel wiper") == 0);
  CHECK(SearchScore(entry, "pragepresse") == 1);
  // a phrase of the table is one term: "quick return" is not "quick" and "return" apart
  const std::vector<SearchField> shaper = {{"Stoßmaschine mit Eilrücklauf", 1}};
  CHECK(SearchScore(shaper, "quick return") == 1);
  CHECK(SearchScore(shaper, "quick") == 0);
  CHECK(SearchScore({{"dead-centre synthesis", 1}}, "Totlage") == 1);
  CHECK(SearchScore({{"Totlagensynthese", 1}}, "dead center") == 1);
  // every group's names find each other
  for (const std::vector<std::string>& group : SearchSynonyms())
    for (const std::string& a : group)
      for (const std::string& b : group) {
        INFO(a << " / " << b);
        CHECK(SearchScore({{a, 1}}, b) == 1);
      }
}

TEST_CASE("catalog search: the words of the catalog's list find their entries in English and German", "[catalog][search]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  struct Word {
    std::vector<std::string> spellings;
    std::set<std::string> expected;
  };
  const std::set<std::string> straight = WithClass(catalog, "straight-line");
  const std::set<std::string> quick = WithClass(catalog, "quick-return");
  const std::set<std::string> dwell = WithClass(catalog, "dwell");
  const std::vector<Word> words = {
      {{"wiper", "Scheibenwischer"}, {"crank-rocker", "windscreen-wiper-parallel"}},
      {{"steering", "Lenkung", "Lenkgetriebe"}, {"double-rocker", "ackermann-steering", "rapson-slide"}},
      {{"hydraulic", "Hydraulik", "hydraulisch"}, {"swinging-block", "hydraulic-boom-cylinder", "backhoe-bucket-linkage"}},
      {{"dead center", "dead centre", "Totlage", "dead-centre"}, {"deadcentre-crank-rocker", "deadcentre-slider-crank"}},
      {{"Rast", "dwell", "Rastgetriebe"}, dwell},
      {{"Kniehebel", "toggle"}, {"toggle-press"}},
      {{"Eilrücklauf", "Eilruecklauf", "eilrucklauf", "quick return", "quick-return"}, quick},
      {{"Geradführung", "Geradfuehrung", "straight line", "Straight-Line"}, straight},
      {{"coupler curve", "Koppelkurve"}, {"stephenson-six-bar", "hoekens-straight-line", "chebyshev-straight-line", "mzc-crank-rocker"}},
      {{"function generator", "Funktionsgetriebe"}, {"proportional-linkage", "function-generator-log"}},
      {{"inversion", "Umkehrung"}, {"swinging-block", "hand-pump", "slotted-link-rotating", "slotted-link-oscillating", "inverted-slider-crank"}},
      {{"Schubkurbel", "slider-crank"}, {"engine-slider-crank", "slider-crank-offset"}},
  };
  CHECK(straight.size() >= 9);
  CHECK(quick.size() >= 4);
  CHECK(dwell.size() >= 3);  // the toggle press and the single- and double-dwell six-bars
  for (const Word& w : words)
    for (const std::string& spelling : w.spellings) {
      INFO(spelling);
      CHECK(Holds(Found(catalog, spelling), w.expected));
    }
  // the inversions the keywords name are the slider-crank's own chain with one of its links as frame
  const CatalogEntry* slider_crank = catalog.Find("engine-slider-crank");
  REQUIRE(slider_crank);
  for (const char* id : {"swinging-block", "hand-pump", "slotted-link-rotating", "slotted-link-oscillating"}) {
    INFO(id);
    bool inversion = false;
    for (size_t frame = 0; frame < slider_crank->file.mechanism.links.size(); ++frame) {
      Mechanism inverted = slider_crank->file.mechanism;
      for (size_t l = 0; l < inverted.links.size(); ++l) inverted.links[l].is_frame = l == frame;
      inversion = inversion || SameKinematicChain(catalog.Find(id)->file.mechanism, inverted);
    }
    CHECK(inversion);
  }
  // ranked: the entry whose id says it comes before those that only mention it
  FeatureQuery q;
  q.text = "crank-rocker";
  const std::vector<const CatalogEntry*> ranked = FindEntries(catalog, q);
  REQUIRE(!ranked.empty());
  CHECK(TextScore(*ranked.front(), q.text) >= TextScore(*ranked.back(), q.text));
  CHECK(ranked.front()->file.id.find("crank-rocker") != std::string::npos);
}

// The mechanisms a textbook's table of useful linkages lists, each found by its English and its
// German name (the reference: the entry the name means, by its id).
TEST_CASE("catalog search: each textbook linkage is found by its English and its German name", "[catalog][search]") {
  const Catalog catalog = Catalog::Load(KOPPEL_CATALOG_DIR);
  const std::vector<std::pair<std::vector<std::string>, std::string>> names = {
      {{"pantograph", "Storchschnabel"}, "pantograph"},
      {{"drag link", "Doppelkurbel", "quick return", "Eilrücklauf"}, "drag-link-quick-return"},
      {{"single dwell", "Rastgetriebe", "dwell", "Rast"}, "single-dwell-six-bar"},
      {{"double dwell", "zwei Rasten", "dwell", "Rast"}, "double-dwell-six-bar"},
      {{"jaw crusher", "Backenbrecher", "Blake"}, "blake-jaw-crusher"},
      {{"toggle clamp", "Kniehebelspanner", "Kniehebel"}, "toggle-clamp"},
      {{"kite", "Drachen", "deltoid"}, "kite-four-bar"},
      {{"Ackermann", "steering", "Lenkung", "Lenktrapez"}, "ackermann-steering"},
      {{"level luffing", "Wippkran", "crane", "Kran"}, "level-luffing-crane"},
      {{"parallel motion", "Parallelbewegung", "Wattsches Parallelogramm", "beam engine", "Balanciermaschine"}, "watt-parallel-motion"},
      {{"scissor lift", "Scherenhubtisch", "lazy tongs"}, "scissor-lift"},
      {{"Walschaerts", "valve gear", "Heusinger", "Steuerung"}, "walschaerts-valve-gear"},
      {{"film advance", "claw", "Greiferwerk", "Filmtransport"}, "film-advance-claw"},
      {{"Klann", "walking", "Schreitwerk"}, "klann-linkage"},
      {{"Chebyshev", "walking", "Tschebyschow", "Schreitwerk"}, "chebyshev-walker"},
      {{"Chebyshev lambda", "Tschebyschow", "straight line", "Geradführung"}, "chebyshev-lambda"},
      {{"pumpjack", "Pferdekopfpumpe", "oil well", "Tiefpumpe"}, "pumpjack"},
      {{"treadle", "Tretkurbel", "Tretantrieb"}, "treadle"},
      {{"radial engine", "Sternmotor"}, "radial-engine"},
      {{"backhoe", "excavator", "Bagger", "hydraulic", "Hydraulik"}, "backhoe-bucket-linkage"},
      {{"function generator", "Funktionsgetriebe"}, "function-generator-log"},
      {{"motion generation", "Führungsgetriebe", "three positions", "Lagensynthese"}, "motion-generation-four-bar"},
      {{"wiper", "Scheibenwischer"}, "windscreen-wiper-parallel"},
      {{"inversion", "Umkehrung", "oscillating cylinder", "Schwingzylinder"}, "inverted-slider-crank"},
      {{"hydraulic cylinder", "Hydraulikzylinder", "boom", "Ausleger"}, "hydraulic-boom-cylinder"},
      {{"Rapson", "steering", "Ruder"}, "rapson-slide"},
      {{"V engine", "V-Motor"}, "v-twin-engine"},
      {{"shaking conveyor", "Schüttelrutsche", "Schwingförderer"}, "shaking-conveyor"},
      {{"press brake", "Abkantpresse"}, "press-brake-toggle"},
      {{"boxer", "Boxermotor"}, "two-cylinder-boxer"},
  };
  CHECK(catalog.entries().size() >= 60);
  for (const auto& [spellings, id] : names) {
    REQUIRE(catalog.Find(id));
    for (const std::string& spelling : spellings) {
      DYNAMIC_SECTION("'" << spelling << "' finds " << id) {
        CHECK(Found(catalog, spelling).count(id) == 1);
      }
    }
  }
}

}  // namespace koppel::text_search_test

// ClassifyModel (tools/api/src/classification.cpp) against the Grashof inequality computed here
// from the catalog entries' own link lengths (the parameters in their files).
#include "koppel/api/classification.hpp"
#include "koppel/api/model.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>

using namespace koppel;
using Catch::Matchers::WithinAbs;

namespace classification_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

constexpr double kLength = 1e-12;  // the lengths are the file's parameters, read back: rounding only

std::map<std::string, double> Lengths(const ModelClassification& c) { return {c.lengths.begin(), c.lengths.end()}; }

std::string Text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("ClassifyModel: the crank-rocker entry, s + l < p + q with the crank shortest, turns fully", "[api]") {
  const Model m = Model::Load(test::CatalogEntryPath("crank-rocker"));
  const ModelClassification c = ClassifyModel(m);
  CHECK(c.mobility == 1);
  REQUIRE(c.assembled);
  CHECK(c.rank_mobility == 1);
  CHECK(c.drive_rotation == "full");
  CHECK(c.grashof == "crank-rocker");
  // the file's a : b : c : d = 1 : 3.5 : 3 : 4: s = a (the crank), l = d
  std::map<std::string, double> l = Lengths(c);
  CHECK_THAT(l["s"], WithinAbs(1.0, kLength));
  CHECK_THAT(l["l"], WithinAbs(4.0, kLength));
  CHECK_THAT(l["p"] + l["q"], WithinAbs(6.5, kLength));
  CHECK(l["s"] + l["l"] < l["p"] + l["q"]);
  CHECK_FALSE(c.rule.empty());
}

TEST_CASE("ClassifyModel: a triple rocker (s + l > p + q) does not turn fully", "[api]") {
  const ModelClassification c = ClassifyModel(Model::Load(test::CatalogEntryPath("triple-rocker")));
  CHECK(c.grashof == "triple-rocker");
  std::map<std::string, double> l = Lengths(c);
  CHECK(l["s"] + l["l"] > l["p"] + l["q"]);
  CHECK(c.drive_rotation == "limited");
}

TEST_CASE("ClassifyModel: a slider-crank driven at its slide is limited though its crank could turn", "[api]") {
  const std::string path = test::CatalogEntryPath("slider-crank-offset");
  const ModelClassification by_crank = ClassifyModel(Model::Load(path));
  CHECK(by_crank.grashof == "crank-slider");
  CHECK(by_crank.drive_rotation == "full");
  // the same chain driven at the slide S (without the catalog's figures, which are the crank's):
  // a P drive never comes round to its pose
  std::string text = Text(path);
  text.erase(text.find("\ncatalog:") + 1);
  const size_t drive = text.find("drive:\n  joint: A0");
  REQUIRE(drive != std::string::npos);
  text.replace(drive, 18, "drive:\n  joint: S ");
  const ModelClassification by_slide = ClassifyModel(Model::Parse(text, "slide-driven"));
  REQUIRE(by_slide.assembled);
  CHECK(by_slide.grashof == "crank-slider");
  CHECK(by_slide.drive_rotation == "limited");
}

TEST_CASE("ClassifyModel: a mechanism that is neither a four-bar nor a slider-crank has no Grashof type", "[api]") {
  const ModelClassification c = ClassifyModel(Model::Load(test::CatalogEntryPath("watt-six-bar")));
  CHECK(c.mobility == 1);
  CHECK(c.grashof.empty());
  CHECK(c.lengths.empty());
  CHECK(c.rule.empty());
}

}  // namespace classification_test

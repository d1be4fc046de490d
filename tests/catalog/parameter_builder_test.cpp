// A mechanism file as a function of some parameters (parameter_builder.hpp), on the catalog's
// slider-crank-offset entry: the reference is ParseMechanismText with the same values written as
// overrides (the reader the builder stands for), and the file's own point formulas (A0 = (0, -e),
// B = (l2, 0) on the coupler, A = (0, -l1) on the crank).
#include "koppel/catalog/parameter_builder.hpp"

#include "input_file.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace koppel::parameter_builder_test {
namespace {

// Every point of every link: exactly equal, as the same text is evaluated with the same numbers.
void CheckSame(const Mechanism& a, const Mechanism& b) {
  REQUIRE(a.links.size() == b.links.size());
  for (size_t l = 0; l < a.links.size(); ++l) {
    CHECK(a.links[l].name == b.links[l].name);
    REQUIRE(a.links[l].points.size() == b.links[l].points.size());
    for (size_t p = 0; p < a.links[l].points.size(); ++p) {
      INFO(a.links[l].name << " " << a.links[l].points[p].name);
      CHECK(a.links[l].points[p].local == b.links[l].points[p].local);
    }
  }
  CHECK(a.joints.size() == b.joints.size());
  CHECK(a.outputs.size() == b.outputs.size());
}

// A point's local coordinates, by link and point name.
Eigen::Vector2d Point(const Mechanism& m, const std::string& link, const std::string& point) {
  for (const Link& l : m.links) {
    if (l.name == link) {
      const int p = l.FindPoint(point);
      REQUIRE(p >= 0);
      return l.points[p].local;
    }
  }
  FAIL("no link " << link);
  return {};
}

const std::string kPath = test::CatalogEntryPath("slider-crank-offset");

}  // namespace

TEST_CASE("MechanismTextWithoutCard drops the catalog card and keeps the mechanism", "[parameter_builder]") {
  const std::string text = test::ReadText(kPath);
  REQUIRE(ParseYamlText(text, kPath)["catalog"]);
  const std::string without = MechanismTextWithoutCard(text, kPath);
  CHECK_FALSE(ParseYamlText(without, kPath)["catalog"]);
  CHECK(ParseYamlText(without, kPath)["links"]);
  CHECK(without.size() < text.size());
  // the reader makes the same mechanism of both, with and without overrides
  CheckSame(ParseMechanismText(without, kPath).mechanism, ParseMechanismText(text, kPath).mechanism);
  CheckSame(ParseMechanismText(without, kPath, {{"e", "-0.3"}}).mechanism, ParseMechanismText(text, kPath, {{"e", "-0.3"}}).mechanism);
}

TEST_CASE("a builder makes the mechanism the reader makes with the values as overrides", "[parameter_builder]") {
  const std::string text = test::ReadText(kPath);
  const MechanismBuilder build = ParameterBuilder(text, kPath, {}, {"l1", "e"});
  // values whose shortest decimal text is the override's text
  const std::vector<std::pair<std::string, std::string>> cases = {{"1", "0.8"}, {"1.2", "-0.5"}, {"0.7", "0"}};
  for (const auto& [l1_text, e_text] : cases) {
    const double l1 = std::stod(l1_text), e = std::stod(e_text);
    INFO("l1 = " << l1_text << ", e = " << e_text);
    const Expected<Mechanism> built = build({l1, e});
    REQUIRE(built);
    CheckSame(*built, ParseMechanismText(text, kPath, {{"l1", l1_text}, {"e", e_text}}).mechanism);
    // the file's formulas: A0 = (0, -e) on the frame, A = (0, -l1) on the crank
    CHECK(Point(*built, "frame", "A0") == Eigen::Vector2d(0, -e));
    CHECK(Point(*built, "crank", "A") == Eigen::Vector2d(0, -l1));
  }
  // the source's overload reads the same text
  const Expected<Mechanism> from_source = ParameterBuilder(MechanismSource::Read(kPath), {}, {"l1", "e"})({1.2, -0.5});
  REQUIRE(from_source);
  CheckSame(*from_source, *build({1.2, -0.5}));
}

TEST_CASE("a value passes the builder exactly (17 significant digits)", "[parameter_builder]") {
  // 0.1 + 0.2 = 0.30000000000000004: a shorter format would round it to 0.3
  const double e = 0.1 + 0.2;
  const Expected<Mechanism> built = ParameterBuilder(test::ReadText(kPath), kPath, {}, {"e"})({e});
  REQUIRE(built);
  CHECK(Point(*built, "frame", "A0").y() == -e);
}

TEST_CASE("the builder's names override the fixed overrides; the other overrides stay", "[parameter_builder]") {
  const std::string text = test::ReadText(kPath);
  const MechanismBuilder build = ParameterBuilder(text, kPath, {{"e", "0.1"}, {"l2", "3"}}, {"e"});
  const Expected<Mechanism> built = build({0.4});
  REQUIRE(built);
  CHECK(Point(*built, "frame", "A0") == Eigen::Vector2d(0, -0.4));  // e from the builder's value
  CHECK(Point(*built, "coupler", "B") == Eigen::Vector2d(3, 0));    // l2 from the fixed override
  // values beyond the names are ignored, names without a value keep the file's value
  const Expected<Mechanism> fewer = ParameterBuilder(text, kPath, {}, {"l1", "e"})({1.5});
  REQUIRE(fewer);
  CHECK(Point(*fewer, "crank", "A") == Eigen::Vector2d(0, -1.5));
  CHECK(Point(*fewer, "frame", "A0") == Eigen::Vector2d(0, -0.8));  // the file's e: 0.8
}

TEST_CASE("a parameter whose formula uses a changed one follows it", "[parameter_builder]") {
  // e = l1/2 by an override: l1 = 1.6 gives e = 0.8 (exact in binary)
  const MechanismBuilder build = ParameterBuilder(test::ReadText(kPath), kPath, {{"e", "l1/2"}}, {"l1"});
  for (double l1 : {1.6, 0.5}) {
    const Expected<Mechanism> built = build({l1});
    REQUIRE(built);
    CHECK(Point(*built, "frame", "A0") == Eigen::Vector2d(0, -l1 / 2));
  }
}

TEST_CASE("a value the reader refuses is the builder's error, and the builder stays usable", "[parameter_builder]") {
  const std::string text = test::ReadText(kPath);
  // an unknown parameter is an InputError of the reader: an error, not an exception
  const Expected<Mechanism> refused = ParameterBuilder(text, kPath, {}, {"nosuch"})({1.0});
  REQUIRE_FALSE(refused);
  CHECK(refused.error().find("nosuch") != std::string::npos);
  const MechanismBuilder build = ParameterBuilder(text, kPath, {{"nosuch", "1"}}, {"e"});
  CHECK_FALSE(build({0.2}));
  CHECK_FALSE(build({0.3}));
  // a good builder after a refused call of another: each call parses its own copy of the tree
  CHECK(ParameterBuilder(text, kPath, {}, {"e"})({0.2}));
}

}  // namespace koppel::parameter_builder_test

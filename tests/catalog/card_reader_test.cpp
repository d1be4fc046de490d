// The card reader: every figure is checked against its quantity's row of the table when the card
// is read, so a misspelled quantity, an argument the quantity does not take, a missing or
// malformed argument, a wrong unit or component are errors with their line, collected with the
// file's other problems (never a figure that silently does not run).
#include "koppel/catalog/figure_quantities.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

namespace koppel::card_reader_test {
namespace {

using test::LineOf;
using test::Replace;

std::string SliderCrank() { return test::ReadText(test::CatalogEntryPath("slider-crank-offset")); }

// Parses `text`, expecting failure; returns every diagnostic.
std::vector<Diagnostic> Bad(const std::string& text) {
  try {
    ParseMechanismText(text, "card.yaml");
  } catch (const InputError& e) {
    return e.diagnostics();
  }
  FAIL("the reader accepted the card");
  return {};
}

// The first diagnostic sits on the line of `needle` and says `phrase`.
void ExpectError(const std::string& text, const std::string& needle, const std::string& phrase) {
  const std::vector<Diagnostic> d = Bad(text);
  REQUIRE_FALSE(d.empty());
  INFO(d[0].ToString());
  CHECK(d[0].line == LineOf(text, needle));
  CHECK(d[0].column > 0);
  CHECK_THAT(d[0].message, Catch::Contains(phrase));
}

// The stroke figure of seed 000's entry, as written in the file.
const char* kStroke = R"Y(    - name: "stroke s_H = 2 l1 (e = 0)"
      quantity: stroke
      output: s
      expected: 2*l1
      tolerance: 1e-8
      variant: e=0)Y";

std::string WithStroke(const std::string& replacement) { return Replace(SliderCrank(), kStroke, replacement); }

}  // namespace

TEST_CASE("a good card is read with typed kind, classes and figure arguments", "[catalog][reader]") {
  const MechanismFile f = ParseMechanismText(SliderCrank(), "card.yaml");
  REQUIRE(f.card);
  CHECK(f.card->kind == CardKind::kTransfer);
  CHECK(f.card->motion == "full rotation -> oscillating translation");
  bool found_value = false;
  for (const FigureCheck& fig : f.card->figures) {
    if (fig.quantity != FigureQuantity::kValue) continue;
    found_value = true;
    CHECK(fig.args.count("at") == 1);
    CHECK(fig.degrees);  // mu is an angle
  }
  CHECK(found_value);
}

TEST_CASE("a misspelled quantity is rejected with its line and a suggestion", "[catalog][reader]") {
  const std::string text = WithStroke(Replace(kStroke, "quantity: stroke", "quantity: strok"));
  ExpectError(text, "quantity: strok\n", "unknown quantity 'strok' (did you mean 'stroke'?)");
  // a name far from any: the list of quantities
  const std::string far = WithStroke(Replace(kStroke, "quantity: stroke", "quantity: elasticity"));
  ExpectError(far, "quantity: elasticity", "expected one of:");
}

TEST_CASE("figure keys are checked against the quantity's arguments", "[catalog][reader]") {
  SECTION("an argument the quantity does not take") {
    ExpectError(WithStroke(std::string(kStroke) + "\n      at: 180"), "      at: 180", "unknown key 'at'");
  }
  SECTION("a misspelled argument, with a suggestion") {
    ExpectError(WithStroke(std::string(kStroke) + "\n      form: 10"), "form: 10", "did you mean 'from'");
  }
  SECTION("a required argument missing") {
    const std::string text = Replace(SliderCrank(), "      at: 0\n", "");
    const std::vector<Diagnostic> d = Bad(text);
    REQUIRE_FALSE(d.empty());
    CHECK_THAT(d[0].message, Catch::Contains("quantity 'value' needs 'at'"));
    CHECK(d[0].line == LineOf(text, "    - name: \"mu_min = mu(0) = mu(180 deg)"));
  }
  SECTION("an order outside 1..8") {
    const std::string derivative = R"(    - name: s'' at 10
      quantity: derivative
      output: s
      at: 10
      order: 9
      expected: 0
      tolerance: 1)";
    ExpectError(WithStroke(std::string(kStroke) + "\n" + derivative), "order: 9", "expected an order 1..8");
  }
  SECTION("an order on a quantity that has none") {
    ExpectError(WithStroke(std::string(kStroke) + "\n      order: 7"), "order: 7", "unknown key 'order'");
  }
  SECTION("a formula argument naming an unknown parameter") {
    ExpectError(WithStroke(std::string(kStroke) + "\n      from: l9"), "from: l9", "unknown name 'l9'");
  }
  SECTION("a joint argument that is not an R joint of the file") {
    const std::string revolves = "    - {name: turns, quantity: revolves, joint: S, expected: 1, tolerance: 0}";
    ExpectError(WithStroke(std::string(kStroke) + "\n" + revolves), "quantity: revolves, joint: S", "is not an R joint");
    const std::string unknown = "    - {name: turns, quantity: revolves, joint: Q7, expected: 1, tolerance: 0}";
    ExpectError(WithStroke(std::string(kStroke) + "\n" + unknown), "joint: Q7", "unknown joint 'Q7'");
  }
  SECTION("an output on a figure of the whole mechanism") {
    const std::string revolves = "    - {name: turns, quantity: revolves, output: s, expected: 1, tolerance: 0}";
    ExpectError(WithStroke(std::string(kStroke) + "\n" + revolves), "quantity: revolves", "takes no output");
  }
  SECTION("an output of the wrong kind") {
    const std::string turns = "    - {name: turns, quantity: turns, output: s, expected: 1, tolerance: 0}";
    ExpectError(WithStroke(std::string(kStroke) + "\n" + turns), "quantity: turns", "needs an angle output");
  }
}

TEST_CASE("units and components are checked", "[catalog][reader]") {
  SECTION("an angle without unit: deg") {
    const std::string text = Replace(SliderCrank(), "      expected: acos(l1/l2)/deg\n      unit: deg\n      tolerance: 1e-9\n      variant: e=0\n    - name: \"mu_min = arccos(l1/l2) (e = 0): at 180",
                                     "      expected: acos(l1/l2)/deg\n      tolerance: 1e-9\n      variant: e=0\n    - name: \"mu_min = arccos(l1/l2) (e = 0): at 180");
    const std::vector<Diagnostic> d = Bad(text);
    REQUIRE_FALSE(d.empty());
    CHECK_THAT(d[0].message, Catch::Contains("this figure is an angle: give 'unit: deg'"));
    CHECK(d[0].line == LineOf(text, "    - name: \"mu_min = mu(0) = mu(180 deg)"));
  }
  SECTION("a length with unit: deg") {
    ExpectError(WithStroke(std::string(kStroke) + "\n      unit: deg"), "      unit: deg\n    - name: \"mu_min = mu(0)", "is not an angle");
  }
  SECTION("a unit other than deg") {
    ExpectError(WithStroke(std::string(kStroke) + "\n      unit: mm"), "unit: mm", "the only unit is deg");
  }
  SECTION("a component of a scalar output") {
    ExpectError(WithStroke(std::string(kStroke) + "\n      component: y"), "component: y", "only a point output has components");
  }
  SECTION("a negative tolerance") {
    ExpectError(WithStroke(Replace(kStroke, "tolerance: 1e-8", "tolerance: -1e-8")), "tolerance: -1e-8", "must not be negative");
  }
  SECTION("an unknown variant") {
    ExpectError(WithStroke(Replace(kStroke, "variant: e=0", "variant: e=1")), "variant: e=1", "unknown variant 'e=1'");
  }
}

TEST_CASE("kind, class and motion words are checked", "[catalog][reader]") {
  ExpectError(Replace(SliderCrank(), "  kind: transfer", "  kind: transmission"), "kind: transmission", "expected transfer");
  ExpectError(Replace(SliderCrank(), "  class: [slider-crank, quick-return]", "  class: [slider-crank, quick-retrun]"), "class:",
              "unknown class 'quick-retrun' (did you mean 'quick-return'?)");
  ExpectError(Replace(SliderCrank(), "motion: full rotation -> oscillating translation", "motion: full rotation to translation"),
              "motion:", "expected '<input motion> -> <output motion>'");
  ExpectError(Replace(SliderCrank(), "motion: full rotation -> oscillating translation", "motion: rotation -> oscillating translation"),
              "motion:", "the input motion 'rotation' is not one of");
  ExpectError(Replace(SliderCrank(), "motion: full rotation -> oscillating translation", "motion: full rotation -> wobbling"),
              "motion:", "does not start with one of");
}

TEST_CASE("all problems of a card are reported at once, each with its line", "[catalog][reader]") {
  std::string text = WithStroke(Replace(kStroke, "quantity: stroke", "quantity: strok"));
  text = Replace(text, "      at: 180\n", "      at: 180\n      qg: 1\n");
  text = Replace(text, "  kind: transfer", "  kind: transfr");
  const std::vector<Diagnostic> d = Bad(text);
  REQUIRE(d.size() >= 3);
  std::vector<int> lines;
  for (const Diagnostic& x : d) lines.push_back(x.line);
  CHECK(std::count(lines.begin(), lines.end(), LineOf(text, "quantity: strok\n")) == 1);
  CHECK(std::count(lines.begin(), lines.end(), LineOf(text, "qg: 1")) == 1);
  CHECK(std::count(lines.begin(), lines.end(), LineOf(text, "kind: transfr")) == 1);
}

}  // namespace koppel::card_reader_test

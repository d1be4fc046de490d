// The length unit a user names for a design made from no file (tools/api/src/design_units.cpp,
// private to the API): no unit for "", the unit's loads for a name, an input error for another
// word, the length figures labelled with it, and the unit carried through the written file into
// a Model. References: the international inch (25.4 mm exactly) and the SI prefixes; the figures'
// units as this test gives them (only "length" is a length); Model::Parse reading back the file
// WriteMechanismYaml wrote with UnitsFor's loads.
#include "design_units.hpp"

#include "koppel/api/model.hpp"
#include "koppel/catalog/mechanism_writer.hpp"
#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace koppel::design_units_test {
namespace {

// relative: a unit's metres against 25.4e-3 or 1e-3 written here: the stored constant's rounding
constexpr double kRounding = 1e-15;

}  // namespace

TEST_CASE("no unit for an empty name; a named unit's loads; the writer's pointer", "[api][design-units]") {
  const std::optional<Loads> none = UnitsOf("");
  CHECK_FALSE(none);
  CHECK(UnitsFor(none) == nullptr);
  const std::optional<Loads> mm = UnitsOf("mm");
  REQUIRE(mm);
  CHECK(mm->metres_per_unit == Approx(1e-3).epsilon(kRounding));
  CHECK(mm->length_unit_given);
  CHECK(mm->LengthUnit() == "mm");
  CHECK(UnitsFor(mm) == &*mm);  // the writer gets this very unit, no copy
  const std::optional<Loads> inch = UnitsOf("in");
  REQUIRE(inch);
  CHECK(inch->metres_per_unit == Approx(25.4e-3).epsilon(kRounding));
}

TEST_CASE("an unknown unit is refused at the field 'units' with the known units listed", "[api][design-units]") {
  try {
    UnitsOf("parsec");
    FAIL("no error");
  } catch (const InputError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK(e.diagnostics()[0].file == "units");
    CHECK_THAT(e.diagnostics()[0].message, Catch::Contains("'parsec'") && Catch::Contains("mm") && Catch::Contains("ft"));
  }
}

TEST_CASE("only the length figures take the unit's name; values stay as they are", "[api][design-units]") {
  const std::vector<DesignFigure> given = {{"l1", 2.5, "length"}, {"mu_min", 40.5, "deg"}, {"ratio", 1.75, "1"}, {"e", -0.3, "length"}};
  std::vector<DesignFigure> figures = given;
  LabelLengths(std::nullopt, figures);  // no unit: nothing changes
  for (size_t i = 0; i < given.size(); ++i) CHECK(figures[i].unit == given[i].unit);
  LabelLengths(UnitsOf("cm"), figures);
  const std::vector<std::string> expected = {"cm", "deg", "1", "cm"};
  for (size_t i = 0; i < given.size(); ++i) {
    INFO(given[i].name);
    CHECK(figures[i].name == given[i].name);
    CHECK(figures[i].value == given[i].value);
    CHECK(figures[i].unit == expected[i]);
  }
}

TEST_CASE("a design written with the unit is a model in that unit", "[api][design-units]") {
  // what the synthesis commands do with --units: the file carries `units: {length: NAME}`
  const std::optional<Loads> units = UnitsOf("in");
  const std::string yaml = WriteMechanismYaml(test::SliderCrank(1, 2.6, 0.8), "a design", SweepDefaults{}, {}, UnitsFor(units));
  const Model model = Model::Parse(yaml, "design.yaml");
  CHECK(model.length_unit() == "in");
  CHECK(model.loads().metres_per_unit == Approx(25.4e-3).epsilon(kRounding));
  // and without a unit the model has none
  const Model plain = Model::Parse(WriteMechanismYaml(test::SliderCrank(1, 2.6, 0.8), "a design", SweepDefaults{}, {},
                                                      UnitsFor(UnitsOf(""))),
                                   "design.yaml");
  CHECK(plain.length_unit() == "length");
  CHECK_FALSE(plain.loads().length_unit_given);
}

}  // namespace koppel::design_units_test

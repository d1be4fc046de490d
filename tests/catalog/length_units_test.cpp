// The named length units (catalog/src/length_units.cpp): each unit's length in metres, the list
// messages print, the unit-only loads a design made from no file is written with, and the unit's
// round trip through the mechanism writer and reader. References: the SI prefixes (d = 1e-1,
// c = 1e-2, m = 1e-3, u = micro = 1e-6, k = 1e3) and the international inch and foot (1959:
// 1 in = 25.4 mm exactly, 1 ft = 12 in); the header's own list "m, dm, cm, mm, um, km, in, ft";
// ReadMechanismFile reading back what WriteMechanismYaml wrote.
#include "koppel/catalog/length_units.hpp"
#include "koppel/catalog/mechanism_file.hpp"
#include "koppel/catalog/mechanism_writer.hpp"

#include "support/mechanisms.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <string>

namespace koppel::length_units_test {
namespace {

// relative: a product of two decimal fractions (12 x 0.0254) against the stored constant: rounding
constexpr double kRounding = 1e-15;

// metres per unit from the definitions, computed here
const std::map<std::string, double> kDefinitions = {{"m", 1.0},          {"dm", 1e-1},         {"cm", 1e-2},
                                                    {"mm", 1e-3},         {"um", 1e-6},         {"km", 1e3},
                                                    {"in", 25.4 * 1e-3}, {"ft", 12 * 25.4 * 1e-3}};

}  // namespace

TEST_CASE("every named unit has its defined length in metres, each name once", "[catalog][length-units]") {
  const auto& units = NamedLengthUnits();
  REQUIRE(units.size() == kDefinitions.size());
  std::map<std::string, int> seen;
  for (const auto& [name, metres] : units) {
    INFO(name);
    REQUIRE(kDefinitions.count(name) == 1);
    CHECK(metres == Approx(kDefinitions.at(name)).epsilon(kRounding));
    ++seen[name];
  }
  for (const auto& [name, count] : seen) CHECK(count == 1);
  // the list the messages print, as length_units.hpp documents it
  CHECK(NamedLengthUnitList() == "m, dm, cm, mm, um, km, in, ft");
}

TEST_CASE("unit-only loads carry the unit and nothing else", "[catalog][length-units]") {
  for (const auto& [name, metres] : kDefinitions) {
    INFO(name);
    const Loads loads = UnitOnlyLoads(name, "--units");
    CHECK(loads.metres_per_unit == Approx(metres).epsilon(kRounding));
    CHECK(loads.length_unit_given);
    CHECK(loads.length_unit_name == name);
    CHECK(loads.LengthUnit() == name);  // what the tables print as the unit
    CHECK_FALSE(loads.HasMass());
    CHECK(loads.gravity.isZero());
    CHECK(loads.masses.empty());
    CHECK(loads.forces.empty());
    CHECK(loads.torques.empty());
    CHECK(loads.springs.empty());
  }
}

TEST_CASE("an unknown unit is an input error naming the flag and listing the known units", "[catalog][length-units]") {
  // a unit of no list, a name in the wrong case, the micro sign for u, a number of metres (a
  // file may give one, a unit name may not)
  for (const std::string name : {"furlong", "MM", "\xC2\xB5m", "0.001", ""}) {
    INFO("'" << name << "'");
    try {
      UnitOnlyLoads(name, "--units");
      FAIL("no error");
    } catch (const InputError& e) {
      REQUIRE(e.diagnostics().size() == 1);
      const Diagnostic& d = e.diagnostics()[0];
      CHECK(d.file == "--units");
      CHECK(d.line == 0);
      CHECK_THAT(d.message, Catch::Contains("unknown length unit '" + name + "'"));
      CHECK_THAT(d.message, Catch::Contains("m, dm, cm, mm, um, km, in, ft"));
    }
  }
}

TEST_CASE("a unit written with the mechanism reads back as the same unit", "[catalog][length-units]") {
  const Mechanism m = test::SliderCrank(1, 2.6, 0.8);
  for (const auto& [name, metres] : kDefinitions) {
    INFO(name);
    const Loads loads = UnitOnlyLoads(name, "--units");
    const std::string text = WriteMechanismYaml(m, "units " + name, SweepDefaults{}, {}, &loads);
    const MechanismFile back = ParseMechanismText(text, "written.yaml");
    CHECK(back.loads.length_unit_given);
    CHECK(back.loads.length_unit_name == name);
    CHECK(back.loads.metres_per_unit == Approx(metres).epsilon(kRounding));
    CHECK_FALSE(back.loads.HasMass());
  }
}

}  // namespace koppel::length_units_test

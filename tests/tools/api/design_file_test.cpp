// ReadDesignFile and CheckLengthUnit (tools/api/src/design_file.cpp), what the synthesis commands
// read through the API: the numbers of tests/data/fit-design.yaml as its text states them (the
// reference), a mistyped key with its file and line, and the length units by name.
#include "koppel/api/design_file.hpp"

#include "koppel/core/angles.hpp"
#include "koppel/core/diagnostic.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

namespace koppel::design_file_test {

TEST_CASE("a design file reads to the space its text states", "[api][design-file]") {
  const DesignSpace space = ReadDesignFile(test::TestDataPath("fit-design.yaml"));
  REQUIRE(space.lengths);
  CHECK(space.lengths->first == 0.5);
  CHECK(space.lengths->second == 5);
  CHECK(space.ratio == 5);
  REQUIRE(space.pivots_x);
  REQUIRE(space.pivots_y);
  CHECK(*space.pivots_x == std::pair(-1.0, 5.0));
  CHECK(*space.pivots_y == std::pair(-1.0, 1.0));
  CHECK(space.input == InputTurn::kCrank);
  REQUIRE(space.mu_min);
  CHECK(*space.mu_min == Approx(DegToRad(40)).epsilon(1e-15));  // degrees in the file, radians inside
  CHECK_FALSE(space.a0);
}

TEST_CASE("a design file's mistake names its file and line", "[api][design-file]") {
  test::TempDir dir;
  const std::string path = dir.Write("d.yaml", "lengths: [0.5, 5]\nratoi: 5\n");
  try {
    ReadDesignFile(path);
    FAIL("a mistyped key was read");
  } catch (const InputError& e) {
    REQUIRE_FALSE(e.diagnostics().empty());
    CHECK(e.diagnostics()[0].file == path);
    CHECK(e.diagnostics()[0].line == 2);
  }
}

TEST_CASE("length units by name", "[api][design-file]") {
  for (const char* unit : {"m", "dm", "cm", "mm", "um", "km", "in", "ft"}) CHECK_NOTHROW(CheckLengthUnit(unit, "units"));
  CHECK_THROWS_WITH(CheckLengthUnit("furlong", "units"), Catch::Contains("units") && Catch::Contains("mm"));
}

}  // namespace koppel::design_file_test

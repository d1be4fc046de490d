// The motor curve file of simulate --motor (catalog/src/motor_curve.cpp): a header, comments and
// formulas as documented, every bad line at its line and column, an empty curve refused with
// the file's name, and a decimal comma caught by the field count.
#include "koppel/catalog/motor_curve.hpp"

#include "koppel/catalog/mechanism_file.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

namespace koppel::motor_curve_test {
namespace {

std::vector<Diagnostic> Problems(const std::string& text) {
  try {
    ParseMotorCurveText(text, "m.csv");
  } catch (const InputError& e) {
    return e.diagnostics();
  }
  return {};
}

}  // namespace

TEST_CASE("a motor curve reads its points, skipping the header and comments", "[motor]") {
  const MotorCurveFile c = ParseMotorCurveText("rpm,Nm\n# measured 2024\n0, 12\n1500,2*4\n\n3000,0\n", "m.csv");
  CHECK(c.speeds == std::vector<double>{0, 1500, 3000});
  CHECK(c.torques == std::vector<double>{12, 8, 0});
}

TEST_CASE("a bad motor line is reported at its line and column", "[motor]") {
  const std::vector<Diagnostic> d = Problems("rpm,Nm\n0,12\n2900,zzz\n1500,2,5\n");
  REQUIRE(d.size() == 2);
  CHECK(d[0].file == "m.csv");
  CHECK(d[0].line == 3);
  CHECK(d[0].column == 6);
  CHECK_THAT(d[0].message, Catch::Contains("torque"));
  CHECK(d[1].line == 4);
  CHECK_THAT(d[1].message, Catch::Contains("decimal comma"));
  const std::vector<Diagnostic> empty = Problems("rpm,Nm\n# nothing measured\n");
  REQUIRE(empty.size() == 1);
  CHECK_THAT(empty[0].ToString(), Catch::StartsWith("m.csv") && Catch::Contains("empty"));
}

TEST_CASE("a motor curve file is read within the input limit", "[motor][limits]") {
  try {
    ReadMotorCurve("/dev/zero");
    FAIL("read /dev/zero");
  } catch (const InputError& e) {
    CHECK_THAT(e.diagnostics().at(0).message, Catch::Contains("kMaxInputBytes"));
  }
  test::TempDir dir;
  const MotorCurveFile c = ReadMotorCurve(dir.Write("m.csv", "0,1\n100,0\n"));
  CHECK(c.speeds.size() == 2);
}

}  // namespace koppel::motor_curve_test

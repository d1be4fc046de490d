// `koppel forces` end to end on the README's slider-crank: the drive torque against seed 000's
// closed form, the virtual-work column beside it, kinetostatics against the reduced inertia
// (torque(speed) - torque(rest) = J_red' speed^2 / 2), singular rows left empty, bad input.
#include "support/closed_forms.hpp"
#include "support/run.hpp"
#include "support/temp_file.hpp"
#include "support/text.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <sstream>
#include <vector>

namespace koppel::forces_command_test {
namespace {

// A CSV table: header and rows of cells (empty cells kept).
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  int Column(const std::string& name) const {
    for (size_t c = 0; c < header.size(); ++c) {
      if (header[c] == name) return static_cast<int>(c);
    }
    FAIL("no column " << name);
    return -1;
  }
  double At(size_t row, const std::string& name) const { return std::stod(rows[row][Column(name)]); }
};

Csv Parse(const std::string& text) {
  Csv csv;
  std::istringstream in(text);
  bool first = true;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    size_t start = 0;
    for (;;) {
      const size_t comma = line.find(',', start);
      cells.push_back(line.substr(start, comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (first) {
      csv.header = cells;
      first = false;
    } else {
      csv.rows.push_back(cells);
    }
  }
  return csv;
}

// Printed with 12 significant digits: a torque of ~15 N m is good to 1e-10 of it.
constexpr double kPrinted = 1e-9;

std::string Example() { return test::TestDataPath("slider-crank-loads.yaml"); }

}  // namespace

TEST_CASE("forces: the README slider-crank, statics without gravity = p s'(phi) (seed 000)", "[cli][forces]") {
  test::TempDir dir;
  std::string text = test::ReadText(Example());
  text = test::Replace(text, "gravity: [0, -9.81]", "gravity: [0, 0]");
  const std::string file = dir.Write("no-gravity.yaml", text);
  const test::RunResult r = test::RunKoppel("forces " + file + " --step 15");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const Csv csv = Parse(r.out);
  CHECK(csv.header == std::vector<std::string>{"phi", "torque", "torque_vw", "J_red", "J_red_d1", "A0_x", "A0_y", "A_x", "A_y",
                                                "B_x", "B_y", "S_x", "S_y", "S_N", "S_M", "singular"});
  REQUIRE(csv.rows.size() == 25);
  for (size_t i = 0; i < csv.rows.size(); ++i) {
    const double phi = csv.At(i, "phi") * M_PI / 180;
    INFO("phi = " << csv.At(i, "phi"));
    // l1 = 50, l2 = 160, e = 10 mm; p = 300 N against the stroke; s' in mm/rad -> m/rad
    const double expected = 300 * test::SliderCrank(50, 160, 10, phi).s1 * 0.001;
    CHECK_THAT(csv.At(i, "torque"), Catch::Matchers::WithinAbs(expected, kPrinted * 15));
    CHECK_THAT(csv.At(i, "torque_vw"), Catch::Matchers::WithinAbs(expected, kPrinted * 15));
    // the slide takes no force along x; the piston force goes through the coupler to the crank
    CHECK(csv.At(i, "S_x") == 0.0);
    CHECK_THAT(csv.At(i, "A0_x"), Catch::Matchers::WithinAbs(300.0, kPrinted * 300));
    CHECK(csv.At(i, "singular") == 0);
  }
}

TEST_CASE("forces --speed: the inertia torque is J_red' speed^2 / 2 at every row", "[cli][forces]") {
  const test::RunResult rest = test::RunKoppel("forces " + Example() + " --step 10");
  const test::RunResult running = test::RunKoppel("forces " + Example() + " --step 10 --speed 1500 --format csv");
  REQUIRE(rest.exit_code == 0);
  REQUIRE(running.exit_code == 0);
  const Csv a = Parse(rest.out), b = Parse(running.out);
  REQUIRE(a.rows.size() == 37);
  REQUIRE(b.rows.size() == 37);
  const double omega = 1500 * 2 * M_PI / 60;
  double largest = 0.0;
  for (size_t i = 0; i < a.rows.size(); ++i) largest = std::max(largest, std::abs(b.At(i, "torque")));
  for (size_t i = 0; i < a.rows.size(); ++i) {
    INFO("phi = " << a.At(i, "phi"));
    // E = J_red omega^2 / 2 at constant omega: the drive adds dE/dt / omega = J_red' omega^2 / 2
    const double inertia = 0.5 * b.At(i, "J_red_d1") * omega * omega;
    CHECK_THAT(b.At(i, "torque") - a.At(i, "torque"), Catch::Matchers::WithinAbs(inertia, kPrinted * largest));
    CHECK_THAT(b.At(i, "torque_vw"), Catch::Matchers::WithinAbs(b.At(i, "torque"), kPrinted * largest));
    CHECK(b.At(i, "J_red") == a.At(i, "J_red"));
  }
  const test::RunResult json = test::RunKoppel("forces " + Example() + " --step 90 --speed 1500 --format json");
  REQUIRE(json.exit_code == 0);
  CHECK_THAT(json.out, Catch::Contains("\"kinetostatic\": true") && Catch::Contains("\"N m\"") && Catch::Contains("\"rpm\""));
}

TEST_CASE("forces: rows at a branch point are left empty and the command exits 1", "[cli][forces]") {
  test::TempDir dir;
  std::string text = test::ReadText(test::TestDataPath("parallelogram.yaml"));
  text = test::Replace(text, "  rocker: {points: {B0: [0, 0], B: [a, 0]}}",
                       "  rocker: {points: {B0: [0, 0], B: [a, 0]}, mass: 2, cg: [0.5, 0], inertia: 0.1}");
  text += "gravity: [0, -9.81]\n";
  const std::string file = dir.Write("parallelogram-loads.yaml", text);
  const test::RunResult r = test::RunKoppel("forces " + file + " --from -20 --to 20 --step 10");
  REQUIRE(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("branch point") && Catch::Contains("have no forces"));
  const Csv csv = Parse(r.out);
  REQUIRE(csv.rows.size() == 5);
  for (size_t i = 0; i < csv.rows.size(); ++i) {
    const bool singular = csv.rows[i][csv.Column("singular")] == "1";
    CHECK(singular == (i == 2));
    CHECK(csv.rows[i][csv.Column("torque")].empty() == singular);
    CHECK(csv.rows[i][csv.Column("A0_x")].empty() == singular);
    if (!singular) {
      // the rocker's weight: V = m g (a/2) sin(phi), so the drive holds m g (a/2) cos(phi)
      const double phi = csv.At(i, "phi") * M_PI / 180;
      CHECK_THAT(csv.At(i, "torque"), Catch::Matchers::WithinAbs(2 * 9.81 * 0.5 * std::cos(phi), kPrinted * 10));
    }
  }
  const test::RunResult json = test::RunKoppel("forces " + file + " --from -20 --to 20 --step 10 --format json");
  CHECK(json.exit_code == 1);
  CHECK_THAT(json.out, Catch::Contains("null"));
}

TEST_CASE("forces: bad input is exit 2 with the file's line", "[cli][forces]") {
  test::TempDir dir;
  const std::string text = test::Replace(test::ReadText(Example()), "magnitude: p", "magnitude: p*q");
  const std::string file = dir.Write("bad.yaml", text);
  const test::RunResult r = test::RunKoppel("forces " + file);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("bad.yaml:" + std::to_string(test::LineOf(text, "magnitude: p*q"))) &&
                        Catch::Contains("unknown name 'q'"));
  CHECK(test::RunKoppel("forces " + Example() + " --speed fast").exit_code == 2);
  CHECK(test::RunKoppel("forces " + Example() + " --step 0").exit_code == 2);
}

}  // namespace koppel::forces_command_test

namespace koppel::forces_command_test {

TEST_CASE("plot --forces draws the drive torque and polar diagrams of joint forces", "[cli][forces]") {
  test::TempDir dir;
  const std::string svg = (dir.path() / "forces.svg").string();
  const test::RunResult r = test::RunKoppel("plot " + test::TestDataPath("slider-crank-loads.yaml") +
                                            " --forces --speed 1500 --joint A0 --joint B --step 5 -o " + svg);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const std::string text = test::ReadText(svg);
  CHECK_THAT(text, Catch::Contains("drive torque [N m]") && Catch::Contains("joint A0: force of frame on crank [N]") &&
                       Catch::Contains("joint B: force of coupler on slider [N]"));
  CHECK(test::RunKoppel("plot " + test::TestDataPath("slider-crank-loads.yaml") + " --forces --joint Z").exit_code == 2);
  CHECK(test::RunKoppel("plot " + test::TestDataPath("slider-crank-loads.yaml") + " --forces --mu").exit_code == 2);
}

}  // namespace koppel::forces_command_test

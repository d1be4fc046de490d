// `koppel simulate` end to end on the README's slider-crank: a free run keeps its energy, a motor
// runs it up to the speed where the motor's torque meets the load, a run that leaves the motor
// curve stops with its rows and exit 1, bad input is exit 2.
#include "support/run.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <vector>

namespace koppel::simulate_command_test {
namespace {

std::vector<std::vector<double>> Rows(const std::string& csv, std::string* header) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(csv);
  std::getline(in, *header);
  for (std::string line; std::getline(in, line);) {
    std::vector<double> row;
    std::istringstream l(line);
    for (std::string cell; std::getline(l, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

std::string Example() { return test::TestDataPath("slider-crank-loads.yaml"); }

}  // namespace

TEST_CASE("simulate: a free run of the slider-crank keeps its energy", "[cli][simulate]") {
  // no piston force: gravity alone, conservative
  const test::RunResult r = test::RunKoppel("simulate " + Example() + " --set p=0 --torque 0 --initial 0,600 --t 0:1 --dt 0.01");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::string header;
  const auto rows = Rows(r.out, &header);
  CHECK(header == "t,phi,speed,s,torque,E_kin,E_pot");
  REQUIRE(rows.size() == 101);
  CHECK(rows[0][2] == 600.0);
  const double e0 = rows[0][5] + rows[0][6];
  double drift = 0.0;
  for (const auto& row : rows) drift = std::max(drift, std::abs(row[5] + row[6] - e0));
  INFO("energy " << e0 << " J, drift " << drift << " J");
  CHECK(drift < 1e-8 * e0);  // the integrator's tolerance (1e-10 per step) over ~9 turns
  CHECK(rows.back()[1] > 9 * 360);
}

TEST_CASE("simulate --motor: the run-up settles where the motor's torque meets the load", "[cli][simulate]") {
  // the piston force and gravity do no work over a turn, so the mean speed settles at the motor's
  // zero-torque speed 2900 rpm (the curve goes on into the generator range to 3100 rpm): after 3 s
  // the run-up (time constant J omega_s / M0 = 0.4 s) has decayed to 2 rpm, and the speed ripples
  // by about +-30 rpm around the mean under the piston's torque
  const test::RunResult r = test::RunKoppel("simulate " + Example() + " --motor 0:40,2900:0,3100:-5 --t 0:4 --dt 0.001");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::string header;
  const auto rows = Rows(r.out, &header);
  REQUIRE(rows.size() == 4001);
  CHECK(rows[0][2] == 0.0);
  CHECK(rows[0][4] == 40.0);  // the motor's starting torque
  double mean = 0.0;
  int count = 0;
  for (const auto& row : rows) {
    if (row[0] >= 3.0) {
      mean += row[2];
      ++count;
    }
  }
  mean /= count;
  INFO("mean speed over the last second: " << mean << " rpm");
  CHECK(std::abs(mean - 2900) < 10);

  const test::RunResult beyond = test::RunKoppel("simulate " + Example() + " --motor 0:40,1000:30 --t 0:2");
  CHECK(beyond.exit_code == 1);
  CHECK_THAT(beyond.err, Catch::Contains("leaves the motor curve"));
  CHECK_THAT(beyond.out, Catch::StartsWith("t,phi,speed,s,torque,E_kin,E_pot\n0,"));
}

TEST_CASE("simulate: bad input is exit 2", "[cli][simulate]") {
  const std::string file = Example();
  CHECK(test::RunKoppel("simulate " + file + " --t 0:1").exit_code == 2);                         // no drive torque
  CHECK(test::RunKoppel("simulate " + file + " --t 0:1 --torque 1 --motor 0:1,10:0").exit_code == 2);  // both
  CHECK(test::RunKoppel("simulate " + file + " --t 1:0 --torque 1").exit_code == 2);
  CHECK(test::RunKoppel("simulate " + file + " --t 0:1 --motor 0-1").exit_code == 2);
  CHECK(test::RunKoppel("simulate " + file + " --t 0:1 --motor 10:1,0:2").exit_code == 2);  // speeds not ascending
  const test::RunResult unknown = test::RunKoppel("simulate " + file + " --t 0:1 --torque 'omega*2'");
  CHECK(unknown.exit_code == 2);
  CHECK_THAT(unknown.err, Catch::Contains("unknown name 'omega'"));
  CHECK(test::RunKoppel("simulate " + file + " --t 0:1 --torque 1 --initial 30").exit_code == 2);
}

}  // namespace koppel::simulate_command_test

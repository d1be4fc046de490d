// SimulateMotion (tools/api/src/simulation.cpp) on the README's slider-crank with loads: a free
// run keeps its energy (a conservative system: the reference is the first row's energy), the
// units of its table (rpm and degrees from the solver's rad/s and radians), a motor curve given as
// points and as a file alike, and the input each refusal is about.
#include "koppel/api/simulation.hpp"
#include "support/temp_file.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace koppel;

namespace simulation_test {  // this file's own names, apart from the other tests' in a unity build
namespace {

Model Example(const ParameterValues& set = {}) { return Model::Load(test::TestDataPath("slider-crank-loads.yaml"), set); }

}  // namespace

TEST_CASE("SimulateMotion: a free run keeps its energy; speed in rpm, the input in degrees", "[api]") {
  const Model m = Example({{"p", "0"}});  // no piston force: gravity alone, conservative
  MotionRequest request;
  request.torque = "0";
  request.initial_input = 0;
  request.initial_speed = 600;
  request.t_end = 1;
  request.dt = 0.01;
  const Motion motion = SimulateMotion(m, request);
  INFO(motion.Brief());
  REQUIRE(motion.complete());
  CHECK(motion.bad_input.empty());
  CHECK(motion.columns == std::vector<std::string>{"t", "phi", "speed", "s", "torque", "E_kin", "E_pot"});
  CHECK(motion.units == std::vector<std::string>{"s", "deg", "rpm", "mm", "N m", "J", "J"});
  REQUIRE(motion.rows.size() == 101);
  CHECK(motion.rows[0][0] == 0);
  CHECK(motion.rows[0][1] == 0);
  CHECK(motion.rows[0][2] == 600.0);  // 600 rpm = 20 pi rad/s, and back
  const double e0 = motion.rows[0][5] + motion.rows[0][6];
  double drift = 0;
  for (const std::vector<double>& row : motion.rows) drift = std::max(drift, std::abs(row[5] + row[6] - e0));
  CHECK(drift < 1e-8 * e0);  // the integrator's tolerance (1e-10 per step) over ~9 turns
  // about 600 rpm for 1 s: some ten turns, in degrees
  CHECK(motion.rows.back()[1] > 9 * 360);
  CHECK(motion.rows.back()[1] < 11 * 360);
  // the default row step: the span / 200
  MotionRequest coarse = request;
  coarse.dt.reset();
  CHECK(SimulateMotion(m, coarse).rows.size() == 201);
}

TEST_CASE("SimulateMotion: a motor curve as points and as a file gives the same run", "[api]") {
  const Model m = Example();
  MotionRequest points;
  points.motor = {{0, 40}, {2900, 0}, {3100, -5}};
  points.t_end = 0.5;
  const test::TempDir dir;
  const std::string file = dir.Write("motor.csv", "rpm,Nm\n0,40\n2900,0\n3100,-5\n");
  MotionRequest from_file = points;
  from_file.motor.clear();
  from_file.motor_file = file;
  const Motion a = SimulateMotion(m, points), b = SimulateMotion(m, from_file);
  REQUIRE(a.complete());
  CHECK(a.rows == b.rows);
}

TEST_CASE("SimulateMotion: refusals name the input they are about", "[api]") {
  const Model m = Example();
  MotionRequest none;
  CHECK_THROWS_AS(SimulateMotion(m, none), InputError);  // no drive law
  MotionRequest two;
  two.torque = "1";
  two.motor = {{0, 1}, {10, 0}};
  CHECK_THROWS_AS(SimulateMotion(m, two), InputError);
  MotionRequest missing;
  missing.motor_file = test::TestDataPath("no-such-motor.csv");
  CHECK_THROWS_AS(SimulateMotion(m, missing), InputError);

  MotionRequest backwards;
  backwards.torque = "1";
  backwards.t_start = 1;
  backwards.t_end = 0;
  CHECK(SimulateMotion(m, backwards).bad_input == "options");
  MotionRequest descending;
  descending.motor = {{10, 1}, {0, 2}};
  CHECK(SimulateMotion(m, descending).bad_input == "drive");
  MotionRequest unknown;
  unknown.torque = "omega*2";
  CHECK(SimulateMotion(m, unknown).bad_input == "drive");
  // a mechanism without masses: its motion is not determined by the loads
  CHECK(SimulateMotion(Model::Load(test::CatalogEntryPath("crank-rocker")), unknown).status == AnalysisStatus::kFailed);
}

}  // namespace simulation_test
